// Verdicts an engineer can sign (issue 11, docs/theory/facade.md §6-§8):
//  - the summary by approach carries the worst check of every code and
//    approach, over candidates, limit states and locations (the gable);
//  - an overturning dynamic run is never summarised as satisfied, and its
//    energy row says "overturned in k of N";
//  - NTC 2018 §7.3.5: 2 records give no verdict, 5 the most unfavourable
//    result, 7 the mean (recomputed here from the individual analyses);
//  - plain records (one column with dt, two columns with the unit only) give
//    the same analysis as the AT2 file and as `assess rocking`'s model;
//  - alpha0 <= 0 is "statically unstable" with alpha0 and the loads;
//  - plausibility warnings (cm thickness, kg/m^3) and Z > H.
#include <doctest/doctest.h>

#include "check_close.hpp"
#include "find_note.hpp"

#include <assess/assessment/facade_assessment.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/records/record_io.hpp>
#include <assess/support/error.hpp>
#include <assess/support/json_input.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>
#include <string>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;
using nlohmann::json;

namespace {

// The same record and model through two readers: the values are the same
// decimals (AT2 vs one column in g): identical; the two-column file in cm/s^2
// was written with 10 significant digits: 1e-9 relative on the input.
constexpr double tol_same_record = 1e-12;  // relative, theta_max (rad)
// The case builds the body from the chain, assess rocking from (t, h, gamma):
// round-off in W, R, alpha, I0 amplified by the impacts (9e-12 seen in the CLI test).
constexpr double tol_same_model = 1e-9;  // relative, theta_max (rad)
constexpr double tol_cm_record = 1e-6;     // relative, theta_max (rad): 1e-9 input rounding amplified by the event times
// Mean and maximum over the analyses, recomputed from the runs: round-off.
constexpr double tol_d = 1e-12;  // m
// alpha0 of a bare block with a thrust at its top, closed form vs virtual work.
constexpr double tol_alpha = 1e-6;  // (-), the message prints 4 significant digits

const std::string root = ASSESS_TEST_DATA_DIR;

json site() {
  return json{{"hazard",
               {{"SLD", {{"ag_g", 0.08}, {"F0", 2.5}, {"Tc_star", 0.30}}},
                {"SLV", {{"ag_g", 0.25}, {"F0", 2.4}, {"Tc_star", 0.35}}},
                {"SLC", {{"ag_g", 0.32}, {"F0", 2.4}, {"Tc_star", 0.36}}}}},
              {"soil", "A"}};
}

json wall(double h, double t) {
  return json{{"type", "simple_overturning"},
              {"storeys", json::array({{{"height", h}, {"thickness", t}}})},
              {"unit_weight", 18.0},
              {"length", 1.0}};
}

json dynamic_with(json records) {
  return json{{"model", "smooth"}, {"k", 1.0e6}, {"sidedness", "one-sided"}, {"restitution", -0.65},
              {"records", std::move(records)}};
}

json elcentro(double scale) { return json{{"file", root + "/spectra/records/elCentro.AT2"}, {"scale", scale}}; }

FacadeAssessment run(const json& doc) {
  FacadeOptions o;
  o.histories = false;
  return assess_facade(parse_case(doc, root + "/case.json"), o);
}

const VerdictRow* summary_row(const Verdict& v, const std::string& code, const std::string& approach) {
  for (const VerdictRow& r : v.rows)
    if (r.code == code && r.approach == approach) return &r;
  return nullptr;
}

}  // namespace

TEST_CASE("gable: the summary carries every failing check (worst row per code and approach)") {
  const CaseFile c = read_case_file(root + "/mechanisms/gable.json");
  const KinematicCaseResult k = run_kinematic_case(c);
  const Verdict& v = k.verdict;
  // The rows that were hidden before: the at-height strength checks fail.
  const VerdictRow* s08 = summary_row(v, "NTC2008", "strength");
  const VerdictRow* s18 = summary_row(v, "NTC2018", "strength");
  const VerdictRow* d18 = summary_row(v, "NTC2018", "displacement");
  REQUIRE(s08);
  REQUIRE(s18);
  REQUIRE(d18);
  CHECK(s08->location == "height");
  CHECK_FALSE(s08->satisfied);
  CHECK(s08->dc > 2.0);
  CHECK(s18->location == "height");
  CHECK_FALSE(s18->satisfied);
  CHECK_FALSE(d18->satisfied);
  // The property: every check is covered by its (code, approach) row, whose
  // D/C is at least its own, and a failing check makes that row fail and the
  // code's overall verdict "not satisfied".
  for (const CandidateResult& cr : k.candidates)
    for (const CheckRow& r : cr.checks) {
      INFO(r.code << " " << r.limit_state << " " << r.kind << " " << r.location);
      const VerdictRow* s = summary_row(v, r.code, r.kind);
      REQUIRE(s);
      CHECK(s->dc >= r.dc);
      if (!r.satisfied) CHECK_FALSE(s->satisfied);
      for (const CodeVerdict& o : v.overall)
        if (o.code == r.code && !r.satisfied) CHECK_FALSE(o.satisfied);
    }
  REQUIRE(v.overall.size() == 2);
  CHECK_FALSE(v.overall[0].satisfied);
  CHECK_FALSE(v.overall[1].satisfied);
}

TEST_CASE("summary rules on synthetic rows: a failing row outranks a larger satisfied D/C; NaN fails") {
  auto row = [](std::string code, std::string kind, double dc, bool sat) {
    CheckRow r;
    r.code = std::move(code);
    r.kind = std::move(kind);
    r.limit_state = "SLV";
    r.location = "ground";
    r.dc = dc;
    r.satisfied = sat;
    return r;
  };
  const Verdict v = build_verdict({row("NTC2018", "dynamic", 0.9, true), row("NTC2018", "dynamic", 0.5, false),
                                   row("NTC2008", "strength", std::nan(""), false),
                                   row("NTC2008", "strength", 0.7, true)});
  const VerdictRow* d = summary_row(v, "NTC2018", "dynamic");
  REQUIRE(d);
  CHECK(d->dc == 0.5);  // the collapse with the smaller D/C
  CHECK_FALSE(d->satisfied);
  const VerdictRow* s = summary_row(v, "NTC2008", "strength");
  REQUIRE(s);
  CHECK(std::isnan(s->dc));
  CHECK_FALSE(s->satisfied);
  for (const CodeVerdict& o : v.overall) CHECK_FALSE(o.satisfied);
}

TEST_CASE("a dynamic run that overturns under one of two records is never summarised as satisfied") {
  json doc{{"site", site()}, {"mechanism", wall(4.0, 0.3)}};
  doc["dynamic"] = dynamic_with(json::array({elcentro(3.0), elcentro(0.05)}));
  const FacadeAssessment a = run(doc);
  REQUIRE(a.dynamics.applies);
  REQUIRE(a.dynamics.runs.size() == 2);
  CHECK(a.dynamics.runs[0].result.overturned);
  CHECK_FALSE(a.dynamics.runs[1].result.overturned);
  REQUIRE(a.dynamics.summaries.size() == 1);
  const RestitutionSummary& s = a.dynamics.summaries[0];
  CHECK(s.overturned == 1);
  CHECK_FALSE(s.slv_satisfied);
  CHECK_FALSE(s.no_verdict);  // a collapse fails whatever the number of records
  REQUIRE(a.dynamics.energy_rows.size() == 1);
  CHECK_FALSE(a.dynamics.energy_rows[0].satisfied);
  // "overturned in 1 of 2 analyses", as data: the note's id and its two counts.
  const Note* overturned = test::find_note(a.dynamics.energy_rows[0].note, "check.overturned");
  REQUIRE(overturned);
  CHECK(test::note_count(*overturned, 0) == 1);
  CHECK(test::note_count(*overturned, 1) == 2);
  const VerdictRow* dyn = summary_row(a.verdict, "NTC2018", "dynamic");
  const VerdictRow* en = summary_row(a.verdict, "seed", "dynamic energy");
  REQUIRE(dyn);
  REQUIRE(en);
  CHECK_FALSE(dyn->satisfied);
  CHECK_FALSE(en->satisfied);
  const Note* en_overturned = test::find_note(en->note, "check.overturned");
  REQUIRE(en_overturned);
  CHECK(test::note_count(*en_overturned, 0) == 1);
  CHECK(test::note_count(*en_overturned, 1) == 2);
  for (const CodeVerdict& o : a.verdict.overall)
    if (o.code == "NTC2018") CHECK_FALSE(o.satisfied);
}

TEST_CASE("NTC 2018 §7.3.5 record count: 2 records no verdict, 5 the most unfavourable, 7 the mean") {
  const double scales[] = {0.05, 0.08, 0.06, 0.1, 0.07, 0.09, 0.04};
  for (int n : {2, 5, 7}) {
    INFO(n << " records");
    json recs = json::array();
    for (int i = 0; i < n; ++i) recs.push_back(elcentro(scales[i]));
    json doc{{"site", site()}, {"mechanism", wall(4.0, 0.5)}};
    doc["dynamic"] = dynamic_with(recs);
    const FacadeAssessment a = run(doc);
    REQUIRE(a.dynamics.runs.size() == std::size_t(n));
    double mean = 0.0, mx = 0.0;
    bool collapse = false;
    for (const DynamicRun& r : a.dynamics.runs) {
      mean += r.d_star / n;
      mx = std::max(mx, r.d_star);
      collapse = collapse || r.collapse;
    }
    REQUIRE_FALSE(collapse);  // small scales: the rule alone decides
    const RestitutionSummary& s = a.dynamics.summaries.at(0);
    CHECK(s.records == n);
    const double d_SLV = a.kinematic.candidates[a.kinematic.governing].result.d_SLV;
    const CheckRow& row = a.checks.back();
    REQUIRE(row.kind == "dynamic");
    if (n == 2) {
      CHECK(s.rule == "none");
      CHECK(s.no_verdict);
      CHECK_FALSE(s.slv_satisfied);
      CHECK(row.no_verdict);
      CHECK(test::find_note(row.note, "check.rule_few"));  // "no verdict: ... at least 3 records"
      CHECK_FALSE(test::find_note(row.note, "check.rule_few_collapse"));
      const VerdictRow* dyn = summary_row(a.verdict, "NTC2018", "dynamic");
      REQUIRE(dyn);
      CHECK(dyn->no_verdict);
      CHECK_FALSE(dyn->satisfied);
    } else if (n == 5) {
      CHECK(s.rule == "most unfavourable");
      CHECK_CLOSE(s.d_demand, mx, abs_tol(tol_d));
      CHECK(s.slv_satisfied == (mx <= d_SLV));
    } else {
      CHECK(s.rule == "mean");
      CHECK_CLOSE(s.d_demand, mean, abs_tol(tol_d));
      CHECK(s.slv_satisfied == (mean <= d_SLV));
    }
    CHECK_CLOSE(row.demand, s.d_demand, abs_tol(tol_d));
    // Listed records are compared with the SLV spectrum over the default range.
    CHECK(a.dynamics.compatibility.computed);
    // The comparison as data (NTC 2018 §3.2.3.6): its side of the band, the count of records, the two ratios.
    const Note* compat = test::find_note(a.dynamics.compatibility.message, a.dynamics.compatibility.band_satisfied
                                                                              ? "compat.within"
                                                                              : "compat.outside");
    REQUIRE(compat);
    CHECK(test::note_count(*compat, 0) == long(n));
    CHECK(compat->args[3].value == a.dynamics.compatibility.min_ratio);
    CHECK(compat->args[4].value == a.dynamics.compatibility.max_ratio);
    if (!a.dynamics.compatibility.band_satisfied) {
      bool warned = false;
      for (const std::string& w : a.warnings) warned = warned || w.find("/dynamic/records") != std::string::npos;
      CHECK(warned);
    }
  }
}

TEST_CASE("plain records in a case file: the same analysis as the AT2 file and as assess rocking's model") {
  auto theta = [&](const json& rec) {
    json doc{{"site", site()}, {"mechanism", wall(4.0, 0.4)}};
    doc["dynamic"] = dynamic_with(json::array({rec}));
    const FacadeAssessment a = run(doc);
    REQUIRE(a.dynamics.runs.size() == 1);
    return a.dynamics.runs[0].result.theta_max;
  };
  const double at2 = theta(elcentro(1.0));
  const double one = theta(json{{"file", root + "/tests/data/elcentro_plain_1col.txt"}, {"dt", 0.02}, {"unit", "g"}});
  const double two = theta(json{{"file", root + "/tests/data/elcentro_plain_2col_cms2.txt"}, {"unit", "cm/s^2"}});
  CHECK(at2 > 0.0);
  CHECK_CLOSE(one, at2, rel_tol(tol_same_record));
  CHECK_CLOSE(two, at2, rel_tol(tol_cm_record));
  // `assess rocking --model smooth --k 1e6 --thickness 0.4 --height 4
  // --unit-weight 18 --one-sided --restitution -0.65 --record FILE --dt 0.02
  // --unit g` builds this model and reads the file with read_plain_record.
  const RockingModel m(RockingBody::rectangle(0.4, 4.0, 18.0e3), Foundation::winkler(1.0e9), Sidedness::one_sided,
                       Restitution::given(-0.65));
  const Record r = read_plain_record(root + "/tests/data/elcentro_plain_1col.txt", 0.02, AccelerationUnit::g);
  const double direct = analyse(m, r, RockingOptions{}).theta_max;
  CHECK_CLOSE(one, direct, rel_tol(tol_same_model));
}

TEST_CASE("plain record errors name the JSON path") {
  json doc{{"site", site()}, {"mechanism", wall(4.0, 0.4)}};
  doc["dynamic"] = dynamic_with(json::array({{{"file", root + "/tests/data/elcentro_plain_1col.txt"}, {"dt", 0.02}}}));
  CHECK_THROWS_WITH_AS(run(doc), doctest::Contains("/dynamic/records/0: a plain record with \"dt\" needs \"unit\""),
                       InputError);
  doc["dynamic"] = dynamic_with(json::array({{{"file", root + "/tests/data/elcentro_plain_1col.txt"}, {"unit", "g"}}}));
  CHECK_THROWS_WITH_AS(run(doc), doctest::Contains("/dynamic/records/0/file"), InputError);
  doc["dynamic"] = dynamic_with(json::array({{{"file", root + "/tests/data/elcentro_plain_1col.txt"}}}));
  CHECK_THROWS_WITH_AS(run(doc), doctest::Contains("\"dt\": s, \"unit\""), InputError);
}

TEST_CASE("alpha0 <= 0: statically unstable, with alpha0 and the thrust that causes it") {
  // One storey 4 m x 0.5 m, 18 kN/m^3 (W = 36 kN), 80 kN outward thrust at the
  // top: alpha0 = (W t/2 - T h) / (W h/2) = (9 - 320) / 72.
  json m = wall(4.0, 0.5);
  m["storeys"][0]["thrust"] = 80.0;
  const json doc{{"mechanism", m}};
  const CaseFile c = parse_case(doc, "thrust.json");
  const double alpha0 = (36.0 * 0.25 - 80.0 * 4.0) / (36.0 * 2.0);
  CHECK_CLOSE(analyse_kinematic(c.mechanism.candidates[0].chain, c.options).alpha0, alpha0, abs_tol(tol_alpha));
  try {
    run_kinematic_case(c);
    FAIL("no error");
  } catch (const InputError& e) {
    const std::string w = e.what();
    CHECK(w.find("thrust.json: /mechanism: the wall is statically unstable") != std::string::npos);
    CHECK(w.find("alpha0 = -4.319") != std::string::npos);
    CHECK(w.find("\"thrust level 1\" (force, 80 kN") != std::string::npos);
  }
}

TEST_CASE("plausibility warnings: thickness in cm, unit weight in kg/m^3, alpha0 > 1") {
  json m = wall(4.0, 60.0);
  m["unit_weight"] = 1800.0;
  const CaseFile c = parse_case(json{{"mechanism", m}}, "cm.json");
  const KinematicCaseResult k = run_kinematic_case(c);
  auto has = [&](const std::string& s) {
    for (const std::string& w : k.warnings)
      if (w.find(s) != std::string::npos) return true;
    return false;
  };
  CHECK(has("cm.json: /mechanism/storeys/0/thickness = 60 m is outside the plausible range 0.05-3 m"));
  CHECK(has("typed in cm"));
  CHECK(has("/mechanism/unit_weight = 1800 kN/m^3 is outside the plausible range 10-30 kN/m^3"));
  CHECK(has("alpha0 = 15 (-) > 1"));
  // A plausible wall has none.
  CHECK(run_kinematic_case(parse_case(json{{"mechanism", wall(4.0, 0.5)}}, "ok.json")).warnings.empty());
}

TEST_CASE("Z > H: a warning with psi = Z/H > 1, and the at-height demand scales with psi") {
  json doc = read_json_file(root + "/mechanisms/gable.json");
  doc["building"] = {{"height_m", 5.0}, {"storeys", 2}, {"T1_s", 0.2}};
  const KinematicCaseResult above = run_kinematic_case(parse_case(doc, "gable.json"));
  bool warned = false;
  for (const std::string& w : above.warnings)
    warned = warned || (w.find("psi(Z) = Z/H = 1.400 > 1") != std::string::npos &&
                        w.find("/building/height_m") != std::string::npos);
  CHECK(warned);
  doc["building"]["height_m"] = 7.0;  // Z = H: psi = 1, same T1
  const KinematicCaseResult at = run_kinematic_case(parse_case(doc, "gable.json"));
  auto demand = [](const KinematicCaseResult& k) {
    for (const CheckRow& r : k.checks)
      if (r.code == "NTC2008" && r.limit_state == "SLV" && r.kind == "strength" && r.location == "height")
        return r.demand;
    return 0.0;
  };
  CHECK_CLOSE(demand(above) / demand(at), 7.0 / 5.0, rel_tol(1e-12));
}

TEST_CASE("building errors name the file and the JSON path") {
  json doc = read_json_file(root + "/mechanisms/gable.json");
  doc.erase("building");
  CHECK_THROWS_WITH_AS(run_kinematic_case(parse_case(doc, "gable.json")),
                       doctest::Contains("gable.json: /building: missing"), InputError);
  doc["building"] = {{"height_m", 7.0}, {"storeys", 0}};
  CHECK_THROWS_WITH_AS(parse_case(doc, "gable.json"), doctest::Contains("gable.json: /building/storeys"), InputError);
}
