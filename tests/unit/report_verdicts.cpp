// The report's verdict box (governing_verdict_row over the assessment's
// summary rows) and message catalogue: the worst row of each code governs, at
// height as well as at ground level; a failing row is never hidden; a row that
// cannot be trusted (no verdict, D/C not finite) governs; every catalogue
// entry exists in Italian and English.
#include <doctest/doctest.h>

#include "assess/report/facade_report.hpp"
#include "assess/report/messages.hpp"
#include "assess/support/error.hpp"

#include <fmt/format.h>

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
  // Issue 24: messages with arguments are formatted by {fmt} ("{}" placeholders):
  // a "%" is text, never a conversion ("+30 % dello" once printed stray memory).
  // Every entry: the same placeholders in both languages, no braces but "{}",
  // no printf conversion left, and formatting with its arguments puts each in.
  auto placeholders = [](const std::string& s) {
    int n = 0;
    for (std::size_t p = s.find("{}"); p != std::string::npos; p = s.find("{}", p + 2)) ++n;
    return n;
  };
  int with_args = 0;
  for (const std::string& k : keys) {
    CAPTURE(k);
    const std::string& it = msg(Lang::it, k);
    const std::string& en = msg(Lang::en, k);
    const int n = placeholders(it);
    CHECK(placeholders(en) == n);
    for (const std::string* s : {&it, &en}) {
      CAPTURE(*s);
      std::string rest = *s;
      for (std::size_t p = rest.find("{}"); p != std::string::npos; p = rest.find("{}")) rest.erase(p, 2);
      CHECK(rest.find('{') == std::string::npos);
      CHECK(rest.find('}') == std::string::npos);
      for (const char* conv : {"%s", "%d", "%llu", "%g", "%f", "%.", "%%", "%-", "%*"}) CHECK(s->find(conv) == std::string::npos);
      if (n == 0) continue;
      const std::string out = fmt::format(fmt::runtime(*s), "<A0>", "<A1>", "<A2>", "<A3>");
      for (int i = 0; i < n; ++i) CHECK(out.find("<A" + std::to_string(i) + ">") != std::string::npos);
      CHECK(out.find("<A" + std::to_string(n) + ">") == std::string::npos);
    }
    with_args += n > 0 ? 1 : 0;
  }
  CHECK(with_args >= 6);  // mech.candidates_cap, kin.adrs_*, dyn.selection, camp.intro
  CHECK(parse_lang("en") == Lang::en);
  CHECK_THROWS_AS(parse_lang("fr"), InputError);
}
