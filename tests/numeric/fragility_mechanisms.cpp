// Fragility studies of mechanisms beyond the single ground-level block
// (issue 16, item "chains and mechanisms at height"): the study takes the
// dynamic model of `assess run` (assessment/mechanism_dynamics).
//  - a 2-block chain (vertical flexure, mechanisms/vertical_flexure_dynamic.json,
//    at height Z = 3 m: floor motions): every row equals analyse_chain on a
//    ChainDynamics built here from the candidate's chain under the floor
//    motion built here, its d* the chain's control-point displacement;
//  - a body at height (two-storey façade about the first floor, Z = 4 m,
//    mechanisms/upper_storey_dynamic.json): every row equals the rocking
//    analysis of the floor motion a_Z = ug'' + gamma psi ur'' built here with
//    gamma psi = 3N/(2N+1) Z/H [C7.2.10] from the case's building;
//  - both byte-identical with 1 and 2 threads.
// Few stripes and records: a few seconds.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/assessment/case_file.hpp>
#include <assess/dynamics/chain_analysis.hpp>
#include <assess/dynamics/chain_dynamics.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/dynamics/rocking_from_chain.hpp>
#include <assess/dynamics/rocking_model.hpp>
#include <assess/records/floor_motion.hpp>
#include <assess/risk/fragility_job.hpp>
#include <assess/risk/fragility_study.hpp>
#include <assess/support/error.hpp>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>

#include "test_files.hpp"

using namespace assess;
using assess::test::rel_tol;

// results.csv prints 10 significant digits: a row and a direct analysis of
// the same model and motion agree to that (rad, m, -).
constexpr double tol_printed_rel = 1e-9;
// Absolute floor for quantities that are zero when the mechanism does not
// move (rad, m).
constexpr double tol_zero_abs = 1e-12;
// gamma psi of the first mode: a product of two ratios (-).
constexpr double tol_gamma_psi_rel = 1e-14;

namespace {

std::string fresh_dir(const std::string& name) {
  const auto p = std::filesystem::temp_directory_path() / ("assess_fragility_mechanisms_" + name);
  std::filesystem::remove_all(p);
  return p.string();
}

CaseFile case_of(const std::string& rel) { return read_case_file(std::string(ASSESS_TEST_DATA_DIR) + "/" + rel); }

FragilityStudy small_study(const CaseFile& kase) {
  FragilityOptions o;
  o.return_periods = {475, 2475};
  o.records = 2;
  o.bootstrap = 0;
  return prepare_fragility(kase, o);
}

// Runs the job with 1 and 2 threads; checks identical bytes; returns the rows.
std::vector<FragilityRow> run_twice(const FragilityStudy& st, const std::string& name) {
  const FragilityJob job(st);
  CampaignRunOptions one;
  one.threads = 1;
  const std::string d1 = fresh_dir(name + "_t1");
  run_campaign_job(job, d1, one);
  CampaignRunOptions two;
  two.threads = 2;
  const std::string d2 = fresh_dir(name + "_t2");
  run_campaign_job(job, d2, two);
  const std::string ref = slurp(d1 + "/results.csv");
  CHECK(!ref.empty());
  CHECK(slurp(d2 + "/results.csv") == ref);
  std::vector<FragilityRow> rows = read_fragility_csv(d1 + "/results.csv");
  std::filesystem::remove_all(d1);
  std::filesystem::remove_all(d2);
  return rows;
}

// The first-mode filter of the case's building at the governing candidate's
// height Z, built here: gamma psi = 3N/(2N+1) Z/H [C7.2.10].
FloorFilter first_mode_filter(const CaseFile& kase, const FragilityStudy& st) {
  const KinematicCaseResult kin = run_kinematic_case(kase);
  const double Z = kin.candidates[kin.governing].Z;
  const double N = kase.building->storeys, H = kase.building->H;
  FloorFilter f;
  f.T1 = kase.building->T1;
  f.xi = kase.building->damping_pct / 100.0;
  f.gamma_psi = 3.0 * N / (2.0 * N + 1.0) * std::min(Z, H) / H;
  REQUIRE(st.dynamics.filter);
  CHECK_CLOSE(st.dynamics.filter->gamma_psi, f.gamma_psi, rel_tol(tol_gamma_psi_rel));
  CHECK_CLOSE(st.dynamics.filter->T1, f.T1, rel_tol(0.0));
  CHECK_CLOSE(st.dynamics.filter->xi, f.xi, rel_tol(0.0));
  return f;
}

void check_close_or_zero(double got, double want) {
  if (std::fabs(want) < tol_zero_abs)
    CHECK(std::fabs(got) < tol_zero_abs);
  else
    CHECK_CLOSE(got, want, rel_tol(tol_printed_rel));
}

}  // namespace

TEST_CASE("fragility of a 2-block chain: rows are the chain model's analyses") {
  const CaseFile kase = case_of("mechanisms/vertical_flexure_dynamic.json");
  const FragilityStudy st = small_study(kase);
  REQUIRE(!st.dynamics.single_body());
  REQUIRE(st.dynamics.chain);
  CHECK(st.dynamics.chain->chain().blocks().size() == 2);
  REQUIRE(kase.building);
  CHECK(st.dynamics.Z == doctest::Approx(3.0));  // at height: floor motions
  const FloorFilter f = first_mode_filter(kase, st);
  CHECK(st.restitutions() == 2);
  CHECK(st.polarities.size() == 2);
  REQUIRE(st.stripes.size() == 2);

  // The chain model built here, independently of the study.
  const KinematicCaseResult kin = run_kinematic_case(kase);
  const Chain& chain = kase.mechanism.candidates[kin.governing].chain;
  const ChainDynamics model(chain, Foundation::rigid());
  const KinematicResult& k = kin.candidates[kin.governing].result;
  const double e_values[] = {-0.5, 0.0};  // the case's restitution list

  const std::vector<FragilityRow> rows = run_twice(st, "chain");
  REQUIRE(rows.size() == st.size());
  int moved = 0;
  for (const FragilityRow& r : rows) {
    CAPTURE(r.id);
    REQUIRE(r.ok);
    const auto [si, ri] = st.group(r.id / st.group_size());
    const StripeRecord& sr = st.stripes[si].records[ri];
    RockingOptions ro = st.dynamic.options;
    ro.scale = sr.scale;
    ro.reverse = r.reversed;
    const RockingResult direct =
        analyse_chain(model, floor_motion(st.records[sr.record], f), ro, e_values[r.restitution]);
    moved += direct.theta_max > 0.0 ? 1 : 0;
    CHECK(r.overturned == direct.overturned);
    check_close_or_zero(r.theta_max_rad, direct.theta_max);
    CHECK_CLOSE(r.theta_u_rad, model.q_u(), rel_tol(tol_printed_rel));
    const double d_control =
        std::fabs(model.horizontal_displacement(k.control_block, k.control_point, direct.theta_max_side * direct.theta_max));
    check_close_or_zero(r.d_star_m, d_control * k.d_star_per_dk);
    check_close_or_zero(r.dc_energy, direct.dc);
  }
  CHECK(moved > 0);  // the comparison is not one of zeros
}

TEST_CASE("fragility of a body at height: rows are rocking analyses of the first-mode floor motion") {
  const CaseFile kase = case_of("mechanisms/upper_storey_dynamic.json");
  const FragilityStudy st = small_study(kase);
  REQUIRE(st.dynamics.single_body());
  REQUIRE(kase.building);
  CHECK(st.dynamics.Z == doctest::Approx(4.0));
  const FloorFilter f = first_mode_filter(kase, st);
  CHECK(st.floor_inputs.size() == st.records.size());

  // The rocking models built here from the candidate's chain.
  const KinematicCaseResult kin = run_kinematic_case(kase);
  const ChainRockingBody body = rocking_body_from_chain(kase.mechanism.candidates[kin.governing].chain);
  const Foundation found = Foundation::winkler(st.dynamic.k);

  const std::vector<FragilityRow> rows = run_twice(st, "height");
  REQUIRE(rows.size() == st.size());
  int moved = 0;
  for (const FragilityRow& r : rows) {
    CAPTURE(r.id);
    REQUIRE(r.ok);
    const auto [si, ri] = st.group(r.id / st.group_size());
    const StripeRecord& sr = st.stripes[si].records[ri];
    // The stripe's IM is the ground record's PGA (hazard curve), not the floor's.
    CHECK_CLOSE(st.records[sr.record].pga() * sr.scale, st.stripes[si].im, rel_tol(1e-13));
    const Record floor = floor_motion(st.records[sr.record], f);
    const RockingModel m(body.body, found, st.dynamic.sidedness, st.dynamic.restitutions[r.restitution]);
    RockingOptions ro = st.dynamic.options;
    ro.scale = sr.scale;
    ro.reverse = r.reversed;
    const RockingResult direct = analyse(m, floor, ro);
    CHECK(r.overturned == direct.overturned);
    check_close_or_zero(r.theta_max_rad, direct.theta_max);
    moved += direct.theta_max > 0.0 ? 1 : 0;
  }
  CHECK(moved > 0);  // the comparison is not one of zeros
}

TEST_CASE("fragility refuses floor motions given by the user and mechanisms the dynamics cannot represent") {
  CaseFile kase = case_of("mechanisms/upper_storey_dynamic.json");
  // Listed floor motions (an IDA would scale them): no hazard curve of theirs.
  kase.dynamic["input"] = "floor";
  kase.dynamic.erase("select");
  kase.dynamic["records"] = {{{"file", "spectra/records/elCentro.AT2"}, {"scale", 1.0}}};
  FragilityOptions ida;
  ida.method = FragilityMethod::ida;
  ida.ida_levels = {1.0, 2.0};
  try {
    prepare_fragility(kase, ida);
    FAIL("floor input accepted");
  } catch (const InputError& e) {
    CAPTURE(e.what());
    CHECK(std::string(e.what()).find("/dynamic/input: \"floor\"") != std::string::npos);
  }
  FragilityOptions o;
  o.return_periods = {475};
  o.records = 2;
  CaseFile no_building = case_of("mechanisms/upper_storey_dynamic.json");
  no_building.building.reset();
  try {
    prepare_fragility(no_building, o);
    FAIL("mechanism at height without a building accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("/building: missing") != std::string::npos);
  }
}
