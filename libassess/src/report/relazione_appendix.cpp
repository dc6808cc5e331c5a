// relazione_appendix.cpp: the appendices (issue 28, items 6 and 7): the
// readings adopted where the code is ambiguous or only recalled, each with its
// basis, so that the signing engineer sees and owns them; every other
// candidate's checks; the warnings; the legend; the case file.
#include "report/relazione_context.hpp"

#include "assess/report/tie_report.hpp"

#include "report/report_heading.hpp"
#include "report/text_format.hpp"

#include <algorithm>

namespace assess::relazione {

namespace {

// The catalogue key of a reading noted by Ctx::clause ("C8A.4.11 [R]" ...).
std::string reading_key(const std::string& r) {
  static const std::vector<std::pair<std::string, std::string>> keys{
      {"C8A.4.11", "reading.c8a411"}, {"C8A.4.12", "reading.c8a412"}, {"C8A.4 SLD", "reading.sld08"},
      {"[4.2.6]", "reading.rod"},     {"eps_u", "reading.eps"},        {"nchor bending", "reading.anchor"},
      {"prassi", "reading.punching"}, {"lanar reduction", "reading.corner"}, {"I_S,SLV", "reading.heritage"},
      {"gamma_M", "reading.masonry_anchor"}, {"mechanisms.md §5", "reading.bound"}};
  for (const auto& [needle, key] : keys)
    if (r.find(needle) != std::string::npos) return key;
  return "";
}

}  // namespace

void add_readings_appendix(Ctx& c) {
  const FacadeAssessment& a = c.a;
  c.d.add_heading(c.t("reading.heading"), 2, false, true, "readings");
  c.d.add_paragraph(c.t("reading.intro"));
  std::vector<std::string> keys;
  auto add = [&](const std::string& k) {
    if (!k.empty() && std::find(keys.begin(), keys.end(), k) == keys.end()) keys.push_back(k);
  };
  // The readings every relazione rests on, then those of the clauses cited.
  if (a.kase.knowledge_level != "given") add("reading.fc");
  add("reading.curve");
  if (a.kinematic.candidates.size() > 1) add("reading.candidates");
  bool height = false;
  for (const CandidateResult& cr : a.kinematic.candidates) height = height || cr.Z > 0.0;
  if (height) add("reading.floor");
  if (a.dynamics.spec && a.dynamics.applies) {
    add("reading.collapse");
    add("reading.count");
    add("reading.energy");
    if (a.dynamics.mechanism && a.dynamics.mechanism->filter) add("reading.floor_filter");
    for (const Restitution& r : a.dynamics.spec->restitutions)
      if (r.kind == Restitution::Kind::one_sided_theory) add("reading.one_sided");
    if (a.dynamics.mechanism && !a.dynamics.mechanism->single_body()) add("reading.chain");
    if (a.selection.result) add("reading.selection");
  }
  if (a.kase.site) add("reading.tr");
  std::vector<std::string> unknown;
  if (c.readings)
    for (const std::string& r : *c.readings) {
      const std::string k = reading_key(r);
      if (k.empty()) unknown.push_back(r);
      add(k);
    }
  std::vector<Inline> items;
  for (const std::string& k : keys) items.push_back({Span{c.t(k + ".what") + ": ", true}, Span{c.t(k + ".text")}});
  for (const std::string& r : unknown) items.push_back({Span{r + ": ", true}, Span{c.t("reading.other")}});
  c.d.add_list(items);
  // The tie rods' formulas and constants with their basis (issue 29): the
  // section itself cites the clause or "ipotesi del progettista" only.
  // The certainty tags of the engine ([R], [I] ...) are not printed (issue 36: no code tokens in the
  // tabulati either): the caption says what the basis column holds.
  if (c.o.ties) {
    std::vector<std::vector<Cell>> rows;
    for (const TieReading& r : tie_readings(*c.o.ties, c.L))
      rows.push_back({Cell(r.quantity), Cell(r.reading), Cell(c.clause(r.basis))});
    c.d.add_cell_table({Cell(msg(c.L, "tie.reading.quantity")), Cell(msg(c.L, "tie.reading.reading")),
                        Cell(msg(c.L, "tie.reading.basis"))},
                       rows, c.t("reading.ties_caption"));
  }
}

void add_warnings(Ctx& c) {
  if (c.a.warnings.empty()) return;
  c.d.add_heading(c.t("warnings.heading"), 2, false, true, "warnings");
  c.d.add_paragraph(c.t("warnings.intro"));
  std::vector<Inline> items;
  for (const std::string& w : c.a.warnings) items.push_back({Span{c.loc(w)}});
  c.d.add_list(items, "warnings");
}

void add_legend(Ctx& c) {
  c.d.add_heading(c.t("legend.heading2"), 2, false, true, "legend");
  std::vector<Inline> items;
  for (const char* k : {"legend.dc2", "legend.inf", "legend.dash", "legend.tables"}) items.push_back({Span{c.t(k)}});
  c.d.add_list(items, "legend");
}

void add_case_file(Ctx& c) {
  c.d.add_heading(c.t("appendix.heading"), 2, false, true, "case-file");
  c.d.add_paragraph(c.t("appendix.note") + " (" + detail::shown_file(c.a.kase.file) + ")");
  c.d.add_pre(c.o.case_text.empty() ? c.t("appendix.missing") : c.o.case_text);
}

}  // namespace assess::relazione
