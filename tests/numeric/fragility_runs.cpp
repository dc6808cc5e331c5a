// Fragility study of a free-standing rigid wall through the campaign runner:
// stripes at the hazard curve's PGA with every record scaled to it, rows that
// equal direct rocking analyses, byte-identical results with 1 or 2 threads,
// split in 2 parts (as MPI ranks) and merged, and interrupted then resumed;
// stripe counts equal to the rows' overturning flags.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/assessment/case_file.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/risk/fragility_job.hpp>
#include <assess/risk/fragility_result.hpp>
#include <assess/risk/fragility_study.hpp>
#include <assess/support/error.hpp>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_files.hpp"

using namespace assess;
using assess::test::rel_tol;

// PGA of a scaled record vs the stripe's Se(0): one multiplication and one
// division apart (-).
constexpr double tol_pga_rel = 1e-13;

namespace {

std::string fresh_dir(const std::string& name) {
  const auto p = std::filesystem::temp_directory_path() / ("assess_fragility_runs_" + name);
  std::filesystem::remove_all(p);
  return p.string();
}

FragilityStudy study() {
  const CaseFile kase = read_case_file(std::string(ASSESS_TEST_DATA_DIR) + "/tests/data/fragility/free_wall.json");
  FragilityOptions o;
  o.return_periods = {101, 475, 2475};
  o.records = 3;
  o.bootstrap = 100;
  return prepare_fragility(kase, o);
}

}  // namespace

TEST_CASE("stripes: records scaled to the PGA of the hazard curve at each return period") {
  const FragilityStudy st = study();
  REQUIRE(st.stripes.size() == 3);
  REQUIRE(st.hazard);
  for (const Stripe& s : st.stripes) {
    CAPTURE(s.TR);
    // Grid return periods: the stripe's PGA is a point of the hazard curve.
    CHECK_CLOSE(s.im, st.hazard->im_at_tr(s.TR), rel_tol(tol_pga_rel));
    CHECK(s.records.size() == 3);
    for (const StripeRecord& r : s.records) CHECK_CLOSE(st.records[r.record].pga() * r.scale, s.im, rel_tol(tol_pga_rel));
  }
  CHECK(st.size() == 3 * 3 * 2);
  CHECK(st.group_size() == 2);
}

TEST_CASE("rows equal direct analyses; identical results with threads, parts and resume") {
  const FragilityStudy st = study();
  const FragilityJob job(st);

  CampaignRunOptions one;
  one.threads = 1;
  const std::string d1 = fresh_dir("t1");
  run_campaign_job(job, d1, one);
  const std::string ref = slurp(d1 + "/results.csv");

  CampaignRunOptions two;
  two.threads = 2;
  const std::string d2 = fresh_dir("t2");
  run_campaign_job(job, d2, two);
  CHECK(slurp(d2 + "/results.csv") == ref);

  // Two parts, as two MPI ranks, merged.
  const std::string dp = fresh_dir("parts");
  for (int part = 0; part < 2; ++part) {
    CampaignRunOptions p;
    p.threads = 1;
    p.part = part;
    p.parts = 2;
    run_campaign_job(job, dp, p);
  }
  merge_campaign_job_parts(job, {campaign_part_path(dp, 0, 2), campaign_part_path(dp, 1, 2)}, dp + "/results.csv");
  CHECK(slurp(dp + "/results.csv") == ref);

  // Interrupted after 7 analyses (limit), then resumed.
  const std::string dr = fresh_dir("resume");
  CampaignRunOptions lim;
  lim.threads = 2;
  lim.limit = 7;
  run_campaign_job(job, dr, lim);
  CampaignRunOptions res;
  res.threads = 2;
  res.resume = true;
  const CampaignRunSummary s = run_campaign_job(job, dr, res);
  CHECK(s.resumed >= 7);
  CHECK(slurp(dr + "/results.csv") == ref);

  // Every row is the rocking analysis of its record, scale and polarity.
  const std::vector<FragilityRow> rows = read_fragility_csv(d1 + "/results.csv");
  REQUIRE(rows.size() == st.size());
  for (const FragilityRow& r : rows) {
    CAPTURE(r.id);
    const auto [si, ri] = st.group(r.id / st.group_size());
    const StripeRecord& sr = st.stripes[si].records[ri];
    RockingOptions ro = st.dynamic.options;
    ro.scale = sr.scale;
    ro.reverse = r.reversed;
    const RockingResult direct = analyse(st.dynamics.rocking.at(r.restitution), st.records[sr.record], ro);
    CHECK(r.ok);
    CHECK(r.stripe == si);
    CHECK(r.reversed == (r.id % 2 == 1));
    CHECK(r.overturned == direct.overturned);
    CHECK_CLOSE(r.theta_max_rad, direct.theta_max, rel_tol(1e-9));  // printed with 10 significant digits
  }

  // Stripe counts of the fit are the rows' overturning flags.
  const FragilityResult fr = fit_fragility(st, rows);
  const FragilityCurve& c = fr.curve(0, FragilityState::overturning);
  for (std::size_t i = 0; i < st.stripes.size(); ++i) {
    int n = 0, k = 0;
    for (const FragilityRow& r : rows)
      if (r.stripe == i) ++n, k += r.overturned ? 1 : 0;
    CHECK(c.stripes[i].n == n);
    CHECK(c.stripes[i].k == k);
  }
  // Missing rows are an error, not a fit.
  std::vector<FragilityRow> short_rows(rows.begin(), rows.end() - 1);
  CHECK_THROWS_AS(fit_fragility(st, short_rows), InputError);
  for (const auto& d : {d1, d2, dp, dr}) std::filesystem::remove_all(d);
}
