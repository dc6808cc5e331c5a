// A verdict per procedure and the adopted one deciding the conclusion
// (issue 24; assessment/verdict.hpp, docs/theory/facade.md §6): Circ. 2019
// C8.7.1.2 offers the linear, non-linear and dynamic procedures as
// alternatives; NTC 2008 is shown for comparison; SLD checks only on request.
#include <doctest/doctest.h>

#include <assess/assessment/case_file.hpp>
#include <assess/assessment/verdict.hpp>
#include <assess/support/error.hpp>
#include <assess/support/json_input.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

using namespace assess;

namespace {

CheckRow row(const std::string& code, const std::string& kind, const std::string& ls, double dc) {
  CheckRow r;
  r.code = code;
  r.kind = kind;
  r.limit_state = ls;
  r.location = "ground";
  r.dc = dc;
  r.satisfied = dc <= 1.0;
  return r;
}

const std::string kRoot = std::string(ASSESS_TEST_DATA_DIR);

}  // namespace

TEST_CASE("each procedure is the worst of its checks; the adopted one is the conclusion") {
  // The church's pattern: linear fails (3.102), non-linear passes (0.991 the
  // worst of SLV and SLC), dynamic fails (2.047); NTC 2008 fails both.
  const std::vector<CheckRow> rows{row("NTC2008", "strength", "SLV", 3.102), row("NTC2008", "displacement", "SLV", 1.129),
                                   row("NTC2018", "strength", "SLV", 3.102), row("NTC2018", "displacement", "SLV", 0.664),
                                   row("NTC2018", "displacement", "SLC", 0.991), row("NTC2018", "dynamic", "SLV", 2.047),
                                   row("seed", "dynamic energy", "SLV", 1.6)};
  for (const auto& [adopted_, satisfied, dc] :
       {std::tuple<std::string, bool, double>{"linear", false, 3.102}, {"nonlinear", true, 0.991}, {"dynamic", false, 2.047}}) {
    // A copy: doctest's CAPTURE is a lambda, and C++17 lambdas cannot capture structured bindings (clang).
    const std::string adopted = adopted_;
    CAPTURE(adopted);
    const Verdict v = build_verdict(rows, adopted);
    CHECK(v.conclusion_code == "NTC2018");
    REQUIRE(v.conclusion() != nullptr);
    CHECK(v.conclusion()->method == adopted);
    CHECK(v.conclusion()->satisfied == satisfied);
    CHECK(v.conclusion()->max_dc == dc);
  }
  const Verdict v = build_verdict(rows);
  CHECK(v.adopted == "nonlinear");
  REQUIRE(v.methods.size() == 5);  // NTC 2008: linear, non-linear; NTC 2018: all three; never "seed"
  for (const MethodVerdict& m : v.methods) {
    CAPTURE(m.code);
    CAPTURE(m.method);
    CHECK(m.code != "seed");
    REQUIRE(m.governing >= 0);
    CHECK(v.rows[std::size_t(m.governing)].dc == m.max_dc);  // the governing row carries the method's worst D/C
  }
  CHECK(v.methods[3].checks == 2);  // NTC 2018 non-linear: SLV and SLC
  CHECK(v.methods[3].failing == 0);
  // A check without a verdict (e.g. 2 records) keeps its method from "satisfied".
  std::vector<CheckRow> nv = rows;
  nv[5].dc = 0.5, nv[5].satisfied = false, nv[5].no_verdict = true;
  const Verdict w = build_verdict(nv, "dynamic");
  CHECK_FALSE(w.conclusion()->satisfied);
  CHECK(w.conclusion()->no_verdict == 1);
  // Without NTC 2018, the first code concludes.
  const Verdict o = build_verdict({row("NTC2008", "strength", "SLV", 0.5), row("NTC2008", "displacement", "SLV", 1.5)});
  CHECK(o.conclusion_code == "NTC2008");
  CHECK_FALSE(o.conclusion()->satisfied);
}

TEST_CASE("case keys: method, check_SLD") {
  nlohmann::json doc = read_json_file(kRoot + "/mechanisms/church-facade.json");
  doc.erase("dynamic");
  CaseFile c = parse_case(doc, "church.json");
  CHECK(c.method == "nonlinear");
  CHECK_FALSE(c.checks.sld);
  KinematicCaseResult k = run_kinematic_case(c);
  for (const CheckRow& r : k.candidates[k.governing].checks) CHECK(r.limit_state != "SLD");
  CHECK(k.verdict.conclusion()->method == "nonlinear");
  doc["check_SLD"] = true;
  doc["method"] = "linear";
  c = parse_case(doc, "church.json");
  CHECK(c.checks.sld);
  k = run_kinematic_case(c);
  int sld = 0;
  for (const CheckRow& r : k.candidates[k.governing].checks) sld += r.limit_state == "SLD" ? 1 : 0;
  CHECK(sld == 2);  // one per code (strength, ground)
  CHECK(k.verdict.conclusion()->method == "linear");
  CHECK_FALSE(k.verdict.conclusion()->satisfied);
  doc["method"] = "dynamic";  // no dynamic section: the procedure cannot be adopted
  CHECK_THROWS_WITH_AS(parse_case(doc, "church.json"), doctest::Contains("/method"), InputError);
  doc["method"] = "pushover";
  CHECK_THROWS_AS(parse_case(doc, "church.json"), InputError);
}
