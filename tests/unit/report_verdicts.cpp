// The report's verdict box (governing_verdict_row over the assessment's
// summary rows) and message catalogue: the worst row of each code governs, at
// height as well as at ground level; a failing row is never hidden; a row that
// cannot be trusted (no verdict, D/C not finite) governs; every catalogue
// entry exists in Italian and English.
#include <doctest/doctest.h>

#include "assess/report/facade_report.hpp"
#include "assess/report/messages.hpp"
#include "assess/support/error.hpp"

#include <cmath>
#include <limits>
#include <set>

using namespace assess;

namespace {
VerdictRow row(const std::string& code, const std::string& approach, const std::string& where, double dc,
               bool satisfied, bool no_verdict = false) {
  VerdictRow r;
  r.code = code;
  r.approach = approach;
  r.limit_state = "SLV";
  r.location = where;
  r.dc = dc;
  r.satisfied = satisfied;
  r.no_verdict = no_verdict;
  return r;
}
}  // namespace

TEST_CASE("verdict box: the largest D/C of the code governs, at height as well as at ground level") {
  Verdict v;
  v.rows = {row("NTC2008", "strength", "ground", 0.50, true), row("NTC2008", "displacement", "height", 1.40, false),
            row("NTC2018", "strength", "ground", 0.80, true), row("NTC2018", "displacement", "ground", 0.95, true)};
  CHECK(governing_verdict_row(v, "NTC2008") == 1);
  CHECK(governing_verdict_row(v, "NTC2018") == 3);
  CHECK(governing_verdict_row(v, "NTC2025") == -1);
}

TEST_CASE("verdict box: a failing row with D/C < 1 (d0 exceeded) governs over a larger satisfied D/C") {
  Verdict v;
  v.rows = {row("NTC2018", "strength", "ground", 0.90, true), row("NTC2018", "dynamic", "ground", 0.60, false)};
  CHECK(governing_verdict_row(v, "NTC2018") == 1);
}

TEST_CASE("verdict box: a row without a verdict or with a D/C that is not finite cannot be trusted and governs") {
  Verdict v;
  v.rows = {row("NTC2018", "strength", "ground", 3.0, false),
            row("NTC2018", "displacement", "ground", std::numeric_limits<double>::quiet_NaN(), false)};
  CHECK(governing_verdict_row(v, "NTC2018") == 1);
  v.rows[1] = row("NTC2018", "dynamic", "ground", 0.5, false, true);
  CHECK(governing_verdict_row(v, "NTC2018") == 1);
}

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
