// Campaign runner: identical results on 1 and 2 threads and across parts
// (MPI ranks), resume after an interruption equals an uninterrupted run,
// failing analyses become rows with their reason, and the CSV round-trips.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include "assess/campaign/campaign.hpp"
#include "assess/campaign/campaign_report.hpp"
#include "assess/campaign/campaign_runner.hpp"
#include "assess/support/error.hpp"

#include <unistd.h>

#include <atomic>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_files.hpp"

namespace fs = std::filesystem;

namespace {

const std::string kTiny = std::string(ASSESS_TEST_DATA_DIR) + "/tests/data/campaign/tiny.json";
const std::string kBad = std::string(ASSESS_TEST_DATA_DIR) + "/tests/data/campaign/bad_record.json";

// A fresh temporary directory per test, removed at the end.
struct TempDir {
  std::string path;
  explicit TempDir(const std::string& name)
      : path((fs::temp_directory_path() / ("assess_campaign_" + name + "_" + std::to_string(::getpid()))).string()) {
    fs::remove_all(path);
  }
  ~TempDir() { fs::remove_all(path); }
};

std::string run(const assess::Campaign& c, const std::string& dir, unsigned threads, std::uint64_t limit = 0,
                bool resume = false) {
  assess::CampaignRunOptions o;
  o.threads = threads;
  o.limit = limit;
  o.resume = resume;
  assess::run_campaign(c, dir, o);
  return slurp(dir + "/results.csv");
}

}  // namespace

TEST_CASE("campaign: the same seed gives identical CSVs on 1 and 2 threads") {
  const assess::Campaign c(assess::read_campaign(kTiny));
  TempDir a("t1"), b("t2");
  const std::string one = run(c, a.path, 1), two = run(c, b.path, 2);
  CHECK(one == two);
  const auto rows = assess::read_campaign_csv(a.path + "/results.csv");
  REQUIRE(rows.size() == c.size());
  for (std::size_t i = 0; i < rows.size(); ++i) CHECK(rows[i].id == i);
}

TEST_CASE("campaign: parts (MPI ranks) merged equal the single-process file") {
  const assess::Campaign c(assess::read_campaign(kTiny));
  TempDir a("single"), b("parts");
  const std::string single = run(c, a.path, 2);
  for (int part = 0; part < 3; ++part) {
    assess::CampaignRunOptions o;
    o.threads = 1;
    o.part = part;
    o.parts = 3;
    assess::run_campaign(c, b.path, o);
  }
  assess::merge_campaign_parts({assess::campaign_part_path(b.path, 0, 3), assess::campaign_part_path(b.path, 1, 3),
                                assess::campaign_part_path(b.path, 2, 3)},
                               b.path + "/results.csv");
  CHECK(slurp(b.path + "/results.csv") == single);
}

TEST_CASE("campaign: a run stopped halfway and resumed equals an uninterrupted one") {
  const assess::Campaign c(assess::read_campaign(kTiny));
  TempDir a("full"), b("resumed");
  const std::string full = run(c, a.path, 2);
  run(c, b.path, 2, 21);  // stopped after 21 of 48 analyses (mid-group)
  // An interruption while writing: the last row is cut in the middle.
  const std::string partial = slurp(b.path + "/results.csv");
  std::ofstream(b.path + "/results.csv", std::ios::binary | std::ios::trunc) << partial.substr(0, partial.size() - 25);
  CHECK(run(c, b.path, 2, 0, true) == full);
  // Resuming a complete file runs nothing and changes nothing, also with a smaller limit.
  CHECK(run(c, b.path, 1, 0, true) == full);
  CHECK(run(c, b.path, 1, 5, true) == full);
}

TEST_CASE("campaign: a cancelled run keeps every finished row and resumes to the full result") {
  const assess::Campaign c(assess::read_campaign(kTiny));
  TempDir a("full_c"), b("cancelled");
  const std::string full = run(c, a.path, 2);
  std::atomic<bool> cancel{false};
  assess::CampaignRunOptions o;
  o.threads = 2;
  o.cancel = &cancel;
  o.progress = [&cancel](std::uint64_t done, std::uint64_t) { cancel = cancel || done >= 10; };
  const assess::CampaignRunSummary s = assess::run_campaign(c, b.path, o);
  CHECK(s.interrupted);
  CHECK(s.run >= 10);
  CHECK(s.run < c.size());
  const auto rows = assess::read_campaign_csv(b.path + "/results.csv");
  CHECK(rows.size() == s.run);
  CHECK(full.compare(0, slurp(b.path + "/results.csv").size(), slurp(b.path + "/results.csv")) == 0);
  CHECK(run(c, b.path, 2, 0, true) == full);
}

TEST_CASE("campaign: resume refuses a changed campaign; a fresh run refuses to overwrite") {
  assess::CampaignSpec spec = assess::read_campaign(kTiny);
  TempDir a("changed");
  run(assess::Campaign(spec), a.path, 1, 10);
  CHECK_THROWS_WITH_AS(run(assess::Campaign(spec), a.path, 1), doctest::Contains("--resume"), assess::InputError);
  spec.seed += 1;
  CHECK_THROWS_WITH_AS(run(assess::Campaign(spec), a.path, 1, 0, true), doctest::Contains("different campaign"),
                       assess::InputError);
}

TEST_CASE("campaign: an unreadable record fails its analyses with the reason; the campaign goes on") {
  const assess::Campaign c(assess::read_campaign(kBad));
  TempDir a("bad");
  run(c, a.path, 2);
  const auto rows = assess::read_campaign_csv(a.path + "/results.csv");
  REQUIRE(rows.size() == 4);
  for (int i = 0; i < 2; ++i) {
    CHECK_FALSE(rows[i].ok);
    CHECK(rows[i].reason.find("truncated.AT2") != std::string::npos);
    CHECK_FALSE(rows[i].has_dynamics);
  }
  for (int i = 2; i < 4; ++i) {
    CHECK(rows[i].ok);
    CHECK(rows[i].has_dynamics);
  }
  const auto summary = assess::summarise_campaign(rows);
  CHECK(summary["failed"] == 2);
  CHECK_THROWS_AS(c.applied_record(0, 0, 1.0), assess::InputError);
  CHECK_THROWS_AS(c.evaluate(0, 3), assess::InputError);  // groups of 1 analysis (1 restitution x 1 model)
}

TEST_CASE("campaign: an analysis stopped by the step limit is a failed row with its reason") {
  assess::CampaignSpec spec = assess::read_campaign(kTiny);
  spec.rocking.max_steps = 50;  // far fewer than the record's samples
  const assess::Campaign c(spec);
  TempDir a("steplimit");
  assess::CampaignRunOptions o;
  o.threads = 2;
  o.limit = 4;
  const assess::CampaignRunSummary s = assess::run_campaign(c, a.path, o);
  CHECK(s.failed == 4);
  for (const auto& r : assess::read_campaign_csv(a.path + "/results.csv")) {
    CHECK_FALSE(r.ok);
    CHECK(r.termination == "step_limit");
    CHECK(r.reason.find("step limit") != std::string::npos);
    CHECK(r.has_code);  // the code ratios do not depend on the integration
  }
}

TEST_CASE("campaign CSV: a row round-trips, including quoted text") {
  assess::AnalysisRow r;
  r.id = 12;
  r.wall = "wall, \"north\"";
  r.b_m = 0.125;
  r.h_m = 1.5;
  r.unit_weight_kN_m3 = 12.06;
  r.record = "Sturno WE";
  r.scale = 0.6;
  r.realisation = 3;
  r.restitution = "housner";
  r.model = "rigid";
  r.ok = false;
  r.reason = "step limit, after 5e7 steps";
  const assess::AnalysisRow s = assess::parse_campaign_csv_row(assess::campaign_csv_row(r));
  CHECK(s.id == 12);
  CHECK(s.wall == r.wall);
  CHECK(s.scale == 0.6);
  CHECK_FALSE(s.k_kN_m3.has_value());
  CHECK_FALSE(s.ok);
  CHECK(s.reason == r.reason);
  CHECK(assess::campaign_csv_row(s) == assess::campaign_csv_row(r));
}
