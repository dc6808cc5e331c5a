// One verdict everywhere (issue 28): the single rule of a check
// (check_satisfied: a verdict and a finite D/C <= 1), a collapse carried by its
// D/C (+inf), a method's governing check the worst of its rows (a failing row
// is never hidden; a row that cannot be trusted governs), a method with a
// check without a verdict and none failing has no verdict; and the message
// catalogue: every entry exists in Italian and English.
#include <doctest/doctest.h>

#include "assess/assessment/verdict.hpp"
#include "assess/report/facade_report.hpp"
#include "assess/report/messages.hpp"
#include "assess/support/error.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <set>

using namespace assess;

namespace {
constexpr double inf = std::numeric_limits<double>::infinity();

CheckRow row(const std::string& code, const std::string& kind, const std::string& where, double dc,
             bool no_verdict = false) {
  CheckRow r;
  r.code = code;
  r.kind = kind;
  r.limit_state = "SLV";
  r.location = where;
  r.dc = dc;
  r.no_verdict = no_verdict;
  decide(r);
  return r;
}

const VerdictRow& governing(const Verdict& v, const std::string& code, const std::string& method) {
  for (const MethodVerdict& m : v.methods)
    if (m.code == code && m.method == method) {
      REQUIRE(m.governing >= 0);
      return v.rows[std::size_t(m.governing)];
    }
  FAIL("no method " << code << " " << method);
  return v.rows.front();
}
}  // namespace

TEST_CASE("the one rule of a check: satisfied iff a verdict and a finite D/C <= 1") {
  CHECK(check_satisfied(1.0, false));
  CHECK(check_satisfied(0.0, false));
  CHECK_FALSE(check_satisfied(1.0 + 1e-12, false));
  CHECK_FALSE(check_satisfied(inf, false));
  CHECK_FALSE(check_satisfied(std::numeric_limits<double>::quiet_NaN(), false));
  CHECK_FALSE(check_satisfied(0.5, true));
  // Every row decided by it: a collapse is D/C = +inf, never "not satisfied" beside D/C < 1.
  CHECK_FALSE(row("NTC2018", "dynamic", "ground", inf).satisfied);
  CHECK(row("NTC2018", "dynamic", "ground", 0.486).satisfied);
}

TEST_CASE("a method's governing check: the largest D/C, at height as well as at ground level") {
  const Verdict v = build_verdict({row("NTC2008", "strength", "ground", 0.50), row("NTC2008", "displacement", "height", 1.40),
                                   row("NTC2018", "strength", "ground", 0.80), row("NTC2018", "displacement", "ground", 0.95),
                                   row("NTC2018", "displacement", "height", 0.97)});
  CHECK(governing(v, "NTC2008", "nonlinear").dc == 1.40);
  CHECK(governing(v, "NTC2008", "nonlinear").location == "height");
  CHECK(governing(v, "NTC2018", "nonlinear").dc == 0.97);
  CHECK(governing(v, "NTC2018", "linear").dc == 0.80);
}

TEST_CASE("a collapse (D/C = +inf) governs its method and makes it fail; its D/C is +inf, never a number below 1") {
  const Verdict v = build_verdict({row("NTC2018", "strength", "ground", 0.90), row("NTC2018", "dynamic", "ground", inf),
                                   row("NTC2018", "dynamic", "ground", 0.40)},
                                  "dynamic");
  const VerdictRow& g = governing(v, "NTC2018", "dynamic");
  CHECK(std::isinf(g.dc));
  CHECK_FALSE(g.satisfied);
  REQUIRE(v.conclusion() != nullptr);
  CHECK_FALSE(v.conclusion()->satisfied);
  CHECK(std::isinf(v.conclusion()->max_dc));
  CHECK(v.conclusion()->failing == 1);
}

TEST_CASE("a check without a verdict: the method has no verdict when nothing fails, and fails when something does") {
  Verdict v = build_verdict({row("NTC2018", "dynamic", "ground", 0.50, true)}, "dynamic");
  REQUIRE(v.conclusion() != nullptr);
  CHECK(v.conclusion()->undecided());
  CHECK_FALSE(v.conclusion()->satisfied);
  v = build_verdict({row("NTC2018", "dynamic", "ground", 0.50, true), row("NTC2018", "dynamic", "ground", 1.5)}, "dynamic");
  CHECK_FALSE(v.conclusion()->undecided());
  CHECK_FALSE(v.conclusion()->satisfied);
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
    REQUIRE(n <= 7);  // the formatting below passes eight arguments
    CHECK(placeholders(en) == n);
    for (const std::string* s : {&it, &en}) {
      CAPTURE(*s);
      std::string rest = *s;
      for (std::size_t p = rest.find("{}"); p != std::string::npos; p = rest.find("{}")) rest.erase(p, 2);
      // Issue 36: a reference's section number mark (document.hpp section_number_mark), "{{§}}"
      // in a message formatted with arguments ({fmt} prints it "{§}"), "{§}" in one without.
      for (const std::string mark : {n > 0 ? "{{§}}" : "{§}"})
        for (std::size_t p = rest.find(mark); p != std::string::npos; p = rest.find(mark)) rest.erase(p, mark.size());
      CHECK(rest.find('{') == std::string::npos);
      CHECK(rest.find('}') == std::string::npos);
      for (const char* conv : {"%s", "%d", "%llu", "%g", "%f", "%.", "%%", "%-", "%*"}) CHECK(s->find(conv) == std::string::npos);
      if (n == 0) continue;
      const std::string out = fmt::format(fmt::runtime(*s), "<A0>", "<A1>", "<A2>", "<A3>", "<A4>", "<A5>", "<A6>", "<A7>");
      for (int i = 0; i < n; ++i) CHECK(out.find("<A" + std::to_string(i) + ">") != std::string::npos);
      CHECK(out.find("<A" + std::to_string(n) + ">") == std::string::npos);
    }
    with_args += n > 0 ? 1 : 0;
  }
  CHECK(with_args >= 6);  // mech.candidates_cap, kin.adrs_*, dyn.selection, camp.intro
  CHECK(parse_lang("en") == Lang::en);
  CHECK_THROWS_AS(parse_lang("fr"), InputError);
}

// Issue 41, item 6: the message tables are data (libassess/src/report/messages/*.json),
// compiled in. Read here from the source tree, independently of the library's
// reader: every entry of the catalogue and of the tie rods' part is what msg()
// gives, in both languages, every key of msg() comes from one of the two files,
// and the phrase list translates its own phrases.
#include <nlohmann/json.hpp>

#include <fstream>

namespace {
nlohmann::json message_file(const std::string& name) {
  std::ifstream in(std::string(ASSESS_TEST_DATA_DIR) + "/libassess/src/report/messages/" + name + ".json");
  REQUIRE(in.good());
  return nlohmann::json::parse(in);
}
}  // namespace

TEST_CASE("message tables as data: msg() gives the entries of messages/*.json") {
  std::set<std::string> in_files;
  for (const char* name : {"catalogue", "ties"}) {
    const nlohmann::json table = message_file(name);
    for (auto e = table.begin(); e != table.end(); ++e) {
      const std::string key = e.key();
      const nlohmann::json& v = e.value();
      CAPTURE(key);
      CHECK(in_files.insert(key).second);  // a key in one file only
      CHECK(msg(Lang::it, key) == v.at("it").get<std::string>());
      CHECK(msg(Lang::en, key) == v.at("en").get<std::string>());
    }
  }
  const auto keys = message_keys();
  CHECK(std::set<std::string>(keys.begin(), keys.end()) == in_files);
  const nlohmann::json names = message_file("mechanisms");
  for (auto e = names.begin(); e != names.end(); ++e)
    CHECK(mechanism_name(Lang::it, e.key()) == e.value().at("it").get<std::string>());
  // Each phrase alone is translated into its Italian (the longest match first:
  // a phrase that contains a longer one is not alone, none here).
  int checked = 0;
  const nlohmann::json phrases = message_file("phrases_it");
  for (const auto& p : phrases) {
    const std::string en = p.at("en"), it = p.at("it");
    CAPTURE(en);
    CHECK(localise(Lang::it, en) == it);
    CHECK(localise(Lang::en, en) == en);
    ++checked;
  }
  CHECK(checked > 10);
}
