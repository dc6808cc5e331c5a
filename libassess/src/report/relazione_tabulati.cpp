// relazione_tabulati.cpp: the tabulati di calcolo (issue 36, item 1): what a
// reviewer consults rather than reads, each table referred to from the body
// and referring back to it: every candidate of the mechanism with its virtual
// work, its kinematic quantities, its capacity curve by points and its checks
// (the candidates that govern a method with their drawing and ADRS plot too).
// The dynamic analysis, the comparison by approach, the modelling choices,
// the readings and the case file are added by their own sections.
#include "report/relazione_context.hpp"
#include "report/text_format.hpp"

#include "report/report_heading.hpp"

#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>

namespace assess::relazione {

using detail::code_name;

void add_tab_intro(Ctx& c) {
  c.d.add_heading(c.t("tab.intro_heading"), 2, false, true, "tabulati-intro");
  c.d.add_paragraph(Inline{Span{c.t("tab.intro") + " "}, reference(c.t("tab.intro_ref"), "premessa", relazione_key)});
  c.d.add_paragraph(c.t("tab.numbers"));
}

void add_tab_candidates(Ctx& c) {
  const FacadeAssessment& a = c.a;
  const std::size_t body = body_candidate(a);
  const std::size_t n = a.kinematic.candidates.size();
  const std::vector<std::size_t> dev = developed_candidates(a);
  c.d.add_heading(c.t("tab.candidates"), 2, false, true, "candidates");
  c.d.add_paragraph(Inline{Span{msgf(c.L, n > 1 ? "tab.candidates_intro" : "tab.candidates_intro1", n) + " "},
                           reference(c.t("tab.see_body_mechanism"), c.here("mechanism"), relazione_key)});
  // Every candidate's kinematic quantities in one table (formulas: the relazione's).
  std::vector<std::vector<Cell>> rows;
  for (std::size_t i = 0; i < n; ++i) {
    const KinematicResult& k = a.kinematic.candidates[i].result;
    const bool curve = k.curve_complete();
    auto dk = [&](double v, int p) { return curve ? c.num(v, p) : c.num(std::nan(""), p); };
    Cell label(c.loc(a.kinematic.candidates[i].label));
    label.link = c.here("cand-" + std::to_string(i));
    std::vector<Cell> row{label, c.num(k.alpha0, 4), c.num(k.M_star / units::tonne, 3), c.num(k.e_star, 4),
                          c.num(k.a0_star, 4), dk(k.d0_star, 4), dk(k.du_star, 4), dk(k.Ts, 3), dk(k.d_SLV, 4),
                          dk(k.T_SLV, 3), dk(k.d_SLC, 4), dk(k.T_SLC, 3)};
    for (Cell& x : row) x.highlight = i == body;
    rows.push_back(row);
  }
  c.d.add_cell_table({Cell(c.t("mech.candidate")), numeric_cell("α0 (–)"), numeric_cell("M* (t)"), numeric_cell("e* (–)"),
                      numeric_cell("a0* (m/s²)"), numeric_cell("d0* (m)"), numeric_cell("du* (m)"), numeric_cell("Ts (s)"),
                      numeric_cell("d_SLV (m)"), numeric_cell("T_SLV (s)"), numeric_cell("d_SLC (m)"), numeric_cell("T_SLC (s)")},
                     rows, c.t("tab.candidates_cap"));
  for (std::size_t i = 0; i < n; ++i) {
    const CandidateResult& cr = a.kinematic.candidates[i];
    const std::string suffix = std::to_string(i);
    c.d.add_heading(c.loc(cr.label) + " (α0 = " + c.n(cr.result.alpha0, 4) + ", a0* = " + c.n(cr.result.a0_star, 3) + " m/s²)",
                    3, false, true, "cand-" + suffix);
    if (i == body) {
      // Developed in the body: its capacity curve by points here.
      c.d.add_paragraph(Inline{reference(c.t(c.building ? "tab.in_body_brief" : "tab.in_body"), c.here("mechanism"), relazione_key)},
                        "note");
      // A building's body leaves its virtual work and ADRS plot here (relazione_mechanism.cpp).
      if (c.building) add_virtual_work(c, i);
      add_curve_table(c, i);
      if (c.building && cr.result.curve_complete()) add_adrs(c, i, "fig-adrs-" + suffix);
      // A building's body gives the checks of the conclusion's code: the other edition's here.
      const MethodVerdict* concl = a.verdict.conclusion();
      if (c.building && concl) {
        std::vector<CheckRow> other;
        for (const CheckRow& r : cr.checks)
          if (r.code != concl->code) other.push_back(r);
        if (!other.empty())
          c.d.add_cell_table(check_head(c, false), check_rows(c, other, false), c.t("tab.checks_other_code_cap"), "checks");
      }
      continue;
    }
    const bool governs = std::find(dev.begin(), dev.end(), i) != dev.end();
    if (governs) add_candidate_data(c, i, "fig-mechanism-" + suffix, 4);
    add_virtual_work(c, i);
    if (governs) add_quantities(c, i);
    add_curve_table(c, i);
    if (governs && cr.result.curve_complete()) add_adrs(c, i, "fig-adrs-" + suffix);
    if (!cr.checks.empty()) c.d.add_cell_table(check_head(c, false), check_rows(c, cr.checks, false), c.t("tab.checks_cap"), "checks");
  }
}

}  // namespace assess::relazione
