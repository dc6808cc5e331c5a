// The report's verdict box (code_verdicts) and message catalogue: the worst
// check of each code governs, at height as well as at ground level; a failing
// check is never hidden; a D/C that cannot be trusted (not finite) counts as
// failing and governs; every catalogue entry exists in Italian and English.
#include <doctest/doctest.h>

#include "assess/report/facade_report.hpp"
#include "assess/report/messages.hpp"
#include "assess/support/error.hpp"

#include <cmath>
#include <limits>
#include <set>

using namespace assess;

namespace {
CheckRow row(const std::string& code, const std::string& ls, const std::string& kind, const std::string& where,
             double dc, bool satisfied) {
  CheckRow r;
  r.code = code;
  r.limit_state = ls;
  r.kind = kind;
  r.location = where;
  r.dc = dc;
  r.satisfied = satisfied;
  return r;
}
}  // namespace

TEST_CASE("verdict per code: the largest D/C over ground and height governs") {
  FacadeAssessment a;
  a.checks = {row("NTC2008", "SLV", "strength", "ground", 0.50, true),
              row("NTC2008", "SLV", "strength", "height", 1.40, false),
              row("NTC2018", "SLV", "strength", "ground", 0.80, true),
              row("NTC2018", "SLC", "displacement", "ground", 0.95, true)};
  const auto v = code_verdicts(a);
  REQUIRE(v.size() == 2);
  CHECK(v[0].code == "NTC2008");
  CHECK_FALSE(v[0].satisfied);
  CHECK(v[0].governing == 1);  // the failing check at height
  CHECK(v[0].dc == 1.40);      // copied from the row, not computed
  CHECK(v[0].checks == 2);
  CHECK(v[0].failing == 1);
  CHECK(v[1].code == "NTC2018");
  CHECK(v[1].satisfied);
  CHECK(v[1].governing == 3);
  CHECK(v[1].failing == 0);
}

TEST_CASE("a failing check with D/C < 1 (d0 exceeded in a dynamic run) still fails the code and governs") {
  FacadeAssessment a;
  a.checks = {row("NTC2018", "SLV", "strength", "ground", 0.90, true),
              row("NTC2018", "SLV", "dynamic", "ground", 0.60, false)};
  const auto v = code_verdicts(a);
  REQUIRE(v.size() == 1);
  CHECK_FALSE(v[0].satisfied);
  CHECK(v[0].governing == 1);
}

TEST_CASE("a D/C that is not finite cannot be trusted: the code fails and that check governs") {
  FacadeAssessment a;
  a.checks = {row("NTC2018", "SLV", "strength", "ground", 3.0, false),
              row("NTC2018", "SLC", "displacement", "ground", std::numeric_limits<double>::quiet_NaN(), true)};
  const auto v = code_verdicts(a);
  REQUIRE(v.size() == 1);
  CHECK_FALSE(v[0].satisfied);
  CHECK(v[0].governing == 1);
  CHECK(v[0].failing == 2);
}

TEST_CASE("no checks (no site): no verdict") { CHECK(code_verdicts(FacadeAssessment{}).empty()); }

TEST_CASE("message catalogue: every key in both languages, Italian code terms") {
  const auto keys = message_keys();
  CHECK(keys.size() > 100);
  for (const std::string& k : keys) {
    CAPTURE(k);
    CHECK_FALSE(msg(Lang::it, k).empty());
    CHECK_FALSE(msg(Lang::en, k).empty());
  }
  CHECK(msg(Lang::it, "verdict.ok") == "VERIFICATO");
  CHECK(msg(Lang::it, "verdict.fail") == "NON VERIFICATO");
  CHECK(msg(Lang::it, "checks.verifica") == "verifica allo");
  CHECK(msg(Lang::it, "kin.alpha0") == "moltiplicatore di attivazione α0");
  CHECK(mechanism_name(Lang::it, "simple_overturning") == "ribaltamento semplice");
  CHECK(mechanism_name(Lang::it, "vertical_flexure") == "flessione verticale");
  CHECK(mechanism_name(Lang::en, "gable_overturning") == "gable overturning");
  CHECK_THROWS_AS(msg(Lang::it, "no.such.key"), std::logic_error);
  CHECK(parse_lang("en") == Lang::en);
  CHECK_THROWS_AS(parse_lang("fr"), InputError);
}
