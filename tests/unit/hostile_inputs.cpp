// Hostile case files, campaigns and analysis options (issue 10, defects 5, 6,
// 8, 9, 10, 11, 12): each is a named InputError (file, JSON path or field,
// what was expected, unit) or a result reported as a failure. Each test
// failed before its fix: an "internal error" (5), a "completed" analysis
// with theta_max = 1.6e134 rad (6), 0 analyses / a factor of 0 / undefined
// behaviour (8), two writers on one directory (9), 16.8 GB built before
// --limit (10), an unbounded tail or tolerance (11), "period T = inf s" (12).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/assessment/case_file.hpp>
#include <assess/campaign/campaign.hpp>
#include <assess/campaign/campaign_runner.hpp>
#include <assess/campaign/output_lock.hpp>
#include <assess/dynamics/analysis_limits.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/records/record_io.hpp>
#include <assess/support/error.hpp>
#include <assess/support/json_input.hpp>
#include <assess/support/units.hpp>

#include <filesystem>
#include <fstream>
#include <string>

#include <unistd.h>

#include "test_files.hpp"

using namespace assess;
using assess::test::rel_tol;

namespace {

namespace fs = std::filesystem;

const std::string kRoot = std::string(ASSESS_TEST_DATA_DIR);
const std::string kCampaignDir = kRoot + "/tests/data/campaign";
const std::string kStu = kRoot + "/spectra/records/RSN292_ITALY_A-STU270.AT2";

// A minimal valid campaign; `extra` replaces or adds top-level members.
nlohmann::json campaign_json() {
  return nlohmann::json::parse(R"({
    "walls": [{"b": 0.125, "h": 1.5}], "unit_weight_kN_m3": 12.06, "k_kN_m3": 1e6,
    "records": ["../../../spectra/records/RSN292_ITALY_A-STU270.AT2"],
    "scale_factors": [0.5], "models": ["rigid"], "seed": 1})");
}

// The Sturno test block of tests/cli/rocking.cmake: 0.25 m x 3 m, 12.06 kN/m^3.
const RockingBody kBlock = RockingBody::rectangle(0.25, 3.0, 12.06 * units::kN);

}  // namespace

TEST_CASE("defect 5: a JSON number beyond a double names the file and the JSON path") {
  const std::string dir = temp_dir("json");
  const std::string c = write(dir + "/case.json", R"({"mechanism": {"type": "simple_overturning",
      "storeys": [{"height": 1e400, "thickness": 0.5}], "unit_weight": 18, "length": 1}})");
  CHECK_THROWS_WITH_AS(read_case_file(c),
                       doctest::Contains("case.json: /mechanism/storeys/0/height: number out of the range of a double"),
                       InputError);
  CHECK_THROWS_WITH_AS(parse_json_text(R"({"dynamic": {"records": [{"file": "a"}, {"scale": -1e999}]}})", "x.json"),
                       doctest::Contains("x.json: /dynamic/records/1/scale: number out of the range"), InputError);
  // Malformed text keeps "not valid JSON", now with the path.
  CHECK_THROWS_WITH_AS(parse_json_text(R"({"a": [1, 2, }")", "y.json"), doctest::Contains("y.json: /a/2: not valid JSON"),
                       InputError);
  // Campaigns: same message, with the campaign file named.
  const std::string k = write(dir + "/c.json", R"({"walls": [{"b": 0.1, "h": 1}], "scale_factors": [1e999]})");
  CHECK_THROWS_WITH_AS(read_campaign(k), doctest::Contains("c.json': /scale_factors/0: number out of the range"),
                       InputError);
  // An unsigned integer beyond the range of an int.
  const std::string u = write(dir + "/u.json", R"({"schema_version": 18446744073709551615,
      "mechanism": {"type": "simple_overturning", "storeys": [{"height": 3, "thickness": 0.5}], "unit_weight": 18,
      "length": 1}})");
  CHECK_THROWS_WITH_AS(read_case_file(u), doctest::Contains("/schema_version: value 18446744073709551615 out of range"),
                       InputError);
  fs::remove_all(dir);
}

TEST_CASE("defect 6: a Winkler modulus the integration cannot resolve is refused, an absurd result is a failure") {
  const Record rec = read_record(kStu);
  RockingOptions o;
  o.scale = 0.2;
  // k = 1e20 kN/m^3 ran 70 s and reported "completed" with theta_max = 1.6e134 rad.
  const RockingModel huge(kBlock, Foundation::winkler(1e20 * units::kN), Sidedness::two_sided, Restitution::housner());
  CHECK_THROWS_WITH_AS(analyse(huge, rec, o), doctest::Contains("exceeds 1e+09 kN/m^3"), InputError);
  // Within the physical bound, but theta_cr = 2.9e-6 rad < 10 abs_tol = 1e-5 rad.
  const RockingModel stiff(kBlock, Foundation::winkler(1e8 * units::kN), Sidedness::two_sided, Restitution::housner());
  RockingOptions loose = o;
  loose.abs_tol = 1e-6;
  CHECK_THROWS_WITH_AS(analyse(stiff, rec, loose), doctest::Contains("too stiff for the integration"), InputError);
  // At the bound k = 1e9 kN/m^3 (theta_cr = 2.9e-7 rad = 289 abs_tol) the peak is within 1e-3 of a run with
  // tolerances 1e5 times tighter (measured 2.4e-4).
  constexpr double kThetaMaxRelTol = 1e-3;  // - (theta_max at the bound vs the tight run)
  const RockingModel bound(kBlock, Foundation::winkler(1e9 * units::kN), Sidedness::two_sided, Restitution::housner());
  const RockingResult r = analyse(bound, rec, o);
  RockingOptions tight = o;
  tight.abs_tol = 1e-14;
  tight.rel_tol = 1e-10;
  const RockingResult t = analyse(bound, rec, tight);
  CHECK(succeeded(r));
  CHECK_CLOSE(r.theta_max, t.theta_max, rel_tol(kThetaMaxRelTol));
  // An absurd result is flagged, whatever produced it.
  RockingResult absurd = r;
  absurd.theta_max = 1.6e134;
  flag_untrustworthy(bound, o, absurd);
  CHECK(absurd.termination == RockingTermination::integrator_error);
  CHECK(absurd.message.find("loss of accuracy") != std::string::npos);
  CHECK_FALSE(succeeded(absurd));
  RockingResult inf = r;
  inf.dc = std::numeric_limits<double>::infinity();
  flag_untrustworthy(bound, o, inf);
  CHECK(inf.termination == RockingTermination::integrator_error);
  RockingResult fine = r;
  flag_untrustworthy(bound, o, fine);
  CHECK(fine.termination == RockingTermination::completed);
}

TEST_CASE("defect 8: campaign scale-factor ranges and integrator limits") {
  auto parse = [](const nlohmann::json& j) { return parse_campaign(j, kCampaignDir); };
  nlohmann::json j = campaign_json();
  // A range of 1e300 factors gave 0 analyses (a long overflow): refused.
  j["scale_factors"] = {{"from", 1e-300}, {"to", 1.0}, {"step", 1e-300}};
  CHECK_THROWS_WITH_AS(parse(j), doctest::Contains("/scale_factors: too many scale factors"), InputError);
  // A small factor was rounded to exactly 0: kept to 12 significant digits.
  j["scale_factors"] = {{"from", 1e-13}, {"to", 3e-13}, {"step", 1e-13}};
  const CampaignSpec s = parse(j);
  REQUIRE(s.scale_factors.size() == 3);
  CHECK_CLOSE(s.scale_factors[0], 1e-13, rel_tol(1e-12));
  CHECK_CLOSE(s.scale_factors[2], 3e-13, rel_tol(1e-12));
  j["scale_factors"] = {{"from", 0.2}, {"to", 2.0}, {"step", 0.2}};
  CHECK(parse(j).scale_factors.size() == 10);
  j["scale_factors"] = {0.5, 1e3};
  CHECK_THROWS_WITH_AS(parse(j), doctest::Contains("/scale_factors/1: a scale factor must lie in (0, 100]"), InputError);
  j = campaign_json();
  // max_steps: 1e300 was a static_cast<long> of an out-of-range double (UB).
  j["integrator"] = {{"max_steps", 1e300}};
  CHECK_THROWS_WITH_AS(parse(j), doctest::Contains("/integrator/max_steps: expected an integer number of steps in [1, 1e+09]"),
                       InputError);
  j["integrator"] = {{"max_steps", 1000.5}};
  CHECK_THROWS_AS(parse(j), InputError);
  j["integrator"] = {{"max_steps", 1000}};
  CHECK(parse(j).rocking.max_steps == 1000);
}

TEST_CASE("defect 9: one writer per campaign output directory") {
  const std::string dir = temp_dir("lock");
  const Campaign c(parse_campaign(campaign_json(), kCampaignDir));
  CampaignRunOptions o;
  o.threads = 1;
  {
    const CampaignOutputLock held(dir);  // another process, as far as flock(2) is concerned
    CHECK_THROWS_WITH_AS(run_campaign(c, dir, o), doctest::Contains("is in use by another assess campaign"), InputError);
    o.resume = true;
    CHECK_THROWS_WITH_AS(run_campaign(c, dir, o), doctest::Contains("is in use"), InputError);
    CHECK_FALSE(fs::exists(dir + "/results.csv"));  // nothing written by the refused runs
  }
  // Released (also by kill -9: the kernel drops flock locks with the process): the run proceeds.
  o.resume = false;
  CHECK(run_campaign(c, dir, o).run == c.size());
  {
    // The ranks of one MPI job share the directory, one rank per part.
    const CampaignOutputLock r0(dir, 0, 2), r1(dir, 1, 2);
    CHECK_THROWS_WITH_AS(CampaignOutputLock(dir, 1, 2), doctest::Contains("is in use"), InputError);
    CHECK_THROWS_WITH_AS(CampaignOutputLock{dir}, doctest::Contains("is in use"), InputError);
  }
  const CampaignOutputLock single(dir);
  CHECK_THROWS_WITH_AS(CampaignOutputLock(dir, 0, 2), doctest::Contains("is in use"), InputError);
  fs::remove_all(dir);
}

TEST_CASE("defect 10: tasks are built lazily, so --limit bounds memory and time") {
  const std::string dir = temp_dir("lazy");
  nlohmann::json j = campaign_json();
  j["realisations"] = 100000000;  // 2e8 analyses: the task list alone was 16.8 GB
  j["models"] = {"rigid", "smooth"};
  const Campaign c(parse_campaign(j, kCampaignDir));
  CHECK(c.size() == 200000000ULL);
  CampaignRunOptions o;
  o.threads = 2;
  o.limit = 8;
  const CampaignRunSummary s = run_campaign(c, dir, o);
  CHECK(s.total == 8);
  CHECK(s.run == 8);
  CHECK(read_campaign_csv(dir + "/results.csv").size() == 8);
  // Resume with a larger limit continues after id 7, in a later group of a 2-part split too.
  o.limit = 12;
  o.resume = true;
  const CampaignRunSummary r = run_campaign(c, dir, o);
  CHECK(r.resumed == 8);
  CHECK(r.run == 4);
  const auto rows = read_campaign_csv(dir + "/results.csv");
  REQUIRE(rows.size() == 12);
  for (std::size_t i = 0; i < rows.size(); ++i) CHECK(rows[i].id == i);
  fs::remove_all(dir);
}

TEST_CASE("defect 11: one set of bounds on tail, tolerances, scale and steps") {
  RockingOptions o;
  CHECK_NOTHROW(o.validate());
  o.tail_s = 1e9;  // ran unbounded from the CLI (the case file capped 600 s)
  CHECK_THROWS_WITH_AS(o.validate(), doctest::Contains("tail duration (s) must lie in [0, 600]"), InputError);
  o = RockingOptions{};
  o.rel_tol = 10;  // accepted by the CLI (the case file capped 0.01)
  CHECK_THROWS_WITH_AS(o.validate(), doctest::Contains("relative tolerance (-) must lie in [1e-14, 0.01]"), InputError);
  o = RockingOptions{};
  o.abs_tol = 1.0;
  CHECK_THROWS_AS(o.validate(), InputError);
  o = RockingOptions{};
  o.scale = 1e300;
  CHECK_THROWS_WITH_AS(o.validate(), doctest::Contains("scale factor must lie in (0, 100]"), InputError);
  o = RockingOptions{};
  o.max_steps = 2'000'000'000L;
  CHECK_THROWS_AS(o.validate(), InputError);
  // The same bounds reach campaigns (with the JSON path).
  nlohmann::json j = campaign_json();
  j["integrator"] = {{"tail_s", 1e9}};
  CHECK_THROWS_WITH_AS(parse_campaign(j, kCampaignDir), doctest::Contains("/integrator: tail duration (s) must lie in [0, 600]"),
                       InputError);
  j["integrator"] = {{"rel_tol", 10}};
  CHECK_THROWS_WITH_AS(parse_campaign(j, kCampaignDir), doctest::Contains("relative tolerance"), InputError);
  j = campaign_json();
  j["k_kN_m3"] = 1e20;
  j["models"] = {"smooth"};
  CHECK_THROWS_WITH_AS(parse_campaign(j, kCampaignDir), doctest::Contains("/k_kN_m3: a Winkler modulus must be <= 1e+09 kN/m^3"),
                       InputError);
  j = campaign_json();
  j["unit_weight_kN_m3"] = 1e300;
  CHECK_THROWS_WITH_AS(parse_campaign(j, kCampaignDir), doctest::Contains("/unit_weight_kN_m3: a unit weight must be <= 10000 kN/m^3"),
                       InputError);
}

TEST_CASE("defect 12: a unit weight of 1e300 kN/m^3 is an input error, not \"period T = inf s\"") {
  const std::string dir = temp_dir("uw");
  const std::string c = write(dir + "/uw.json", R"({"mechanism": {"type": "simple_overturning",
      "storeys": [{"height": 6, "thickness": 0.5}], "unit_weight": 1e300, "length": 1}})");
  CHECK_THROWS_WITH_AS(read_case_file(c), doctest::Contains("uw.json: /mechanism/unit_weight: value 1e+300 out of range"),
                       InputError);
  const std::string b = write(dir + "/b.json", R"({"mechanism": {"type": "blocks",
      "blocks": [{"polygon": [[0,0],[0.5,0],[0.5,3],[0,3]], "unit_weight": 1e300, "length": 1}],
      "constraints": [{"type": "ground_hinge", "block": 0, "point": [0.5, 0]}]}})");
  CHECK_THROWS_WITH_AS(read_case_file(b), doctest::Contains("/mechanism/blocks/0/unit_weight: value 1e+300 out of range"),
                       InputError);
  fs::remove_all(dir);
}
