// relazione_code.cpp: the chapter NTC 2018 §10.2 asks of an analysis made
// with a program (issue 36, item 2): the code's identity (name, version,
// source revision), its validation (the project's reference comparisons and
// its tests, read from the verification record compiled in: the same data as
// docs/verification.md, never copied by hand; report/build_info.hpp) and the
// checks of acceptability of the results (alpha0 redone by a closed form,
// the displacement capacity against the wall's thickness, the methods
// compared), computed by the assessment (assessment/acceptability.hpp) and
// printed here with their outcome.
#include "report/relazione_context.hpp"
#include "report/text_format.hpp"

#include "assess/report/build_info.hpp"

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cmath>

namespace assess::relazione {

namespace {

// "unit 25, numeric 35, cli 301 ..." in the report's words.
std::string test_groups(const Ctx& c, const BuildInfo& b) {
  std::string s;
  static const std::vector<std::string> keys = message_keys();
  for (const TestGroup& g : b.tests) {
    // A group the catalogue does not name (a test group added later) is shown by its own name.
    const std::string key = "code.group." + g.group;
    const bool named = std::find(keys.begin(), keys.end(), key) != keys.end();
    s += (s.empty() ? "" : ", ") + msgf(c.L, "code.group", named ? c.t(key) : g.group, g.tests);
  }
  return s;
}

void identity(Ctx& c) {
  const BuildInfo& b = build_info();
  c.d.add_heading(c.t("code.identity"), 3, false);
  std::vector<std::vector<Cell>> rows{
      {Cell(c.t("code.name")), Cell(c.t("code.name_value"))},
      {Cell(c.t("code.version")), Cell(b.version)},
      {Cell(c.t("code.revision")), Cell(b.revision == "unknown" ? c.t("code.revision_unknown") : b.revision)},
      {Cell(c.t("code.licence")), Cell(c.t("code.licence_value"))},
      {Cell(c.t("code.scope")), Cell(c.t("code.scope_value"))},
      {Cell(c.t("code.documentation")), Cell(c.t("code.documentation_value"))}};
  c.d.add_cell_table({Cell(c.t("front.item")), Cell(c.t("front.value"))}, rows, c.t("code.identity_cap"));
}

void validation(Ctx& c) {
  const BuildInfo& b = build_info();
  c.d.add_heading(c.t("code.validation"), 3, false);
  if (b.tests.empty()) c.d.add_paragraph(c.t("code.tests_none"));
  else c.d.add_paragraph(msgf(c.L, "code.tests", b.total_tests(), test_groups(c, b)));
  const nlohmann::json v = nlohmann::json::parse(verification_record(), nullptr, false);
  if (v.is_discarded() || !v.contains("relazione")) {
    c.d.add_paragraph(c.t("code.record_missing"));
    return;
  }
  const std::string lang = c.L == Lang::it ? "it" : "en";
  std::vector<std::vector<Cell>> rows;
  for (const auto& x : v.at("relazione")) {
    const auto& t = x.at(lang);
    rows.push_back({Cell(t.at("area").get<std::string>()), Cell(t.at("compared").get<std::string>()),
                    Cell(t.at("reference").get<std::string>()), Cell(t.at("tolerance").get<std::string>())});
  }
  c.d.add_cell_table({Cell(c.t("code.area")), Cell(c.t("code.compared")), Cell(c.t("code.reference")), Cell(c.t("code.tolerance"))},
                     rows, c.t("code.comparisons_cap"));
}

const AcceptabilityCheck* find(const FacadeAssessment& a, const std::string& key) {
  for (const AcceptabilityCheck& x : a.acceptability)
    if (x.key == key) return &x;
  return nullptr;
}

Cell outcome(const Ctx& c, const AcceptabilityCheck* x) {
  if (!x) return Cell("—");
  if (!x->applicable) return Cell(c.t("code.na." + x->why_not));
  Cell o(c.t(x->passed ? "code.passed" : "code.flagged"));
  o.tone = x->passed ? Tone::ok : Tone::fail;
  return o;
}

void acceptability(Ctx& c, const std::vector<std::pair<std::string, const FacadeAssessment*>>& mechanisms) {
  c.d.add_heading(c.t("code.acceptability"), 3, false, true, "acceptability");
  c.d.add_paragraph(c.t("code.acceptability_intro"));
  std::vector<std::vector<Cell>> rows;
  int checks = 0, passed = 0, flagged = 0;
  std::string flagged_list;
  for (const auto& [label, ap] : mechanisms) {
    const FacadeAssessment& a = *ap;
    const AcceptabilityCheck* al = find(a, "alpha0_closed_form");
    const AcceptabilityCheck* d = find(a, "displacement_vs_thickness");
    const AcceptabilityCheck* m = find(a, "methods_agree");
    for (const AcceptabilityCheck* x : {al, d, m})
      if (x && x->applicable) {
        ++checks;
        if (x->passed) ++passed;
        else {
          ++flagged;
          if (flagged_list.find(label) == std::string::npos) flagged_list += (flagged_list.empty() ? "" : ", ") + label;
        }
      }
    std::string methods;
    if (m)
      for (std::size_t i = 0; i < m->methods.size(); ++i)
        methods += (methods.empty() ? "" : "; ") + c.t("short_method." + m->methods[i].first) + " " + c.n(m->methods[i].second, 3) +
                   " " + verdict_word(c.L, Outcome(m->method_outcomes[i]));
    Cell name(label, al ? c.loc(al->candidate) : "");
    name.user = true;  // a building's wall and mechanism names are the engineer's
    rows.push_back({name, c.num(al ? al->value : std::nan(""), 4),
                    c.num(al && al->applicable ? al->reference : std::nan(""), 4), outcome(c, al),
                    c.num(d && d->applicable ? d->value : std::nan(""), 3), c.num(d && d->applicable ? d->reference : std::nan(""), 3),
                    outcome(c, d), Cell(methods), outcome(c, m)});
  }
  c.d.add_cell_table({Cell(c.t("code.mechanism")), numeric_cell(c.t("code.alpha0")), numeric_cell(c.t("code.alpha0_cf")),
                      Cell(c.t("code.outcome")), numeric_cell("d0* (m)"), numeric_cell(c.t("code.thickness")),
                      Cell(c.t("code.outcome")), Cell(c.t("code.methods")), Cell(c.t("code.outcome"))},
                     rows, c.t("code.acceptability_cap"), "acceptability");
  c.d.add_paragraph(flagged == 0 ? msgf(c.L, "code.all_passed", passed, checks)
                                 : msgf(c.L, "code.some_flagged", passed, checks, flagged_list));
  Inline end{Span{c.t("code.engineer")}};
  if (c.tabulati) {
    end.push_back(Span{" "});
    end.push_back(reference(c.t("code.readings_ref"), "readings", tabulati_key));
  }
  c.d.add_paragraph(end);
}

}  // namespace

void add_code_chapter(Ctx& c, const std::vector<std::pair<std::string, const FacadeAssessment*>>& mechanisms) {
  c.d.add_heading(c.t("code.heading"), 2, !c.building, true, "code");  // a building's: after its conclusions (length)
  c.d.add_paragraph(c.t("code.intro"));
  identity(c);
  validation(c);
  acceptability(c, mechanisms);
}

}  // namespace assess::relazione
