// relazione_checks.cpp: the checks (issue 28, items 1-3): one table of every
// check of the candidates developed in the body and every dynamic check, each
// row with its inputs, its D/C and its verdict read from the check itself;
// the safety indices zetaE = PGA_C/PGA_D and TR_C/TR_D per method and edition.
#include "report/relazione_context.hpp"

#include "report/report_heading.hpp"
#include "report/text_format.hpp"

#include "assess/assessment/building_assessment.hpp"

#include <algorithm>
#include <cmath>

namespace assess::relazione {

using detail::code_name;

namespace {

std::string check_name(const Ctx& c, const CheckRow& r) {
  return c.t("checks.verifica") + " " + r.limit_state + ", " + c.t("kind." + r.kind) + ", " + c.t("where." + r.location);
}

// The second line of a check: its demand formula, clause, every input and,
// at height, which part of the floor spectrum gives the demand.
std::string check_note(const Ctx& c, const CheckRow& r) {
  std::string s = c.loc(r.formula) + "; " + c.clause(r.clause);
  std::string inputs;
  for (const auto& [name, v] : r.inputs) inputs += (inputs.empty() ? "" : ", ") + c.input_name(name) + " = " + c.g(v, 4);
  if (!inputs.empty()) s += "; " + inputs;
  if (!r.floor_branch.empty()) s += "; " + c.t("branch." + r.floor_branch);
  return s;
}

}  // namespace

std::vector<std::vector<Cell>> check_rows(const Ctx& c, const std::vector<CheckRow>& rows, bool with_candidate) {
  std::vector<std::vector<Cell>> out;
  for (const CheckRow& r : rows) {
    std::vector<Cell> row{Cell(code_name(r.code)), Cell(check_name(c, r), check_note(c, r))};
    if (with_candidate) row.push_back(Cell(c.loc(r.candidate)));
    row.push_back(c.num(r.demand, 4));
    row.push_back(c.num(r.capacity, 4));
    row.push_back(Cell(c.unit(r.unit)));
    Cell dc = c.dc_cell(r);
    if (r.kind == "dynamic" && r.analyses > 0 && r.dc == 0.0) dc.note = c.t("dyn.no_uplift");  // a computed zero, said why
    row.push_back(dc);
    // The check's own safety index (issue 41), coloured by the check's verdict.
    Cell zeta = c.num(r.index.defined ? r.index.zeta : std::nan(""), 3);
    if (r.index.defined) zeta.tone = verdict_tone(r.outcome());
    row.push_back(zeta);
    row.push_back(c.verdict_cell(r));
    out.push_back(row);
  }
  return out;
}

std::vector<Cell> check_head(const Ctx& c, bool with_candidate) {
  std::vector<Cell> head{Cell(c.t("checks.code")), Cell(c.t("checks.check"))};
  if (with_candidate) head.push_back(Cell(c.t("mech.candidate")));
  for (Cell x : {numeric_cell(c.t("checks.demand")), numeric_cell(c.t("checks.capacity")), Cell(c.t("kin.unit")), numeric_cell("D/C"), numeric_cell(c.t("checks.ag")),
                 Cell(c.t("checks.outcome"))})
    head.push_back(x);
  return head;
}

void add_checks(Ctx& c) {
  const FacadeAssessment& a = c.a;
  if (a.checks.empty() && a.kinematic.candidates.front().checks.empty()) return;
  c.d.add_heading(c.t("checks.heading"), 2, true, true, "checks");
  const std::size_t ci = body_candidate(a);
  // Every check of the candidate the body develops (NTC 2018 first: the
  // conclusion's code), then every dynamic check; the other candidates'
  // checks are in the tabulati, so that the verdict box's counts are the rows
  // of the two (issue 36).
  const bool brief = c.building && c.tabulati;  // a building's mechanism: one note (issue 36: length)
  // A building's mechanism: the checks of the conclusion's code (the other
  // edition's are in the tabulati, under the candidate; issue 36: length).
  const MethodVerdict* concl = a.verdict.conclusion();
  std::vector<CheckRow> rows;
  for (const char* code : {"NTC2018", "NTC2008"})
    for (const CheckRow& r : c.candidate(ci).checks)
      if (r.code == code && (!brief || !concl || r.code == concl->code)) rows.push_back(r);
  for (const CheckRow& r : a.checks)
    if (r.kind == "dynamic") rows.push_back(r);
  const bool others = a.kinematic.candidates.size() > 1;
  const bool several_dynamic = !a.other_dynamics.empty();
  if (brief)
    c.d.add_paragraph(Inline{reference(c.t("checks.brief_note"), c.here("candidates"), tabulati_key)}, "note");
  else if (others && c.tabulati)
    c.d.add_paragraph(Inline{Span{c.t("checks.body_note_tab") + " "},
                             reference(c.t("checks.see_tab"), c.here("candidates"), tabulati_key)});
  else
    c.d.add_paragraph(c.t(others ? "checks.body_note_summary" : "checks.body_note_all"));
  c.d.add_cell_table(check_head(c, several_dynamic), check_rows(c, rows, several_dynamic), brief ? std::string() : c.t("checks.table_cap"), "checks");
  add_choice_notes(c, {"height_demand", "xi_SLV_pct", "xi_SLC_pct"});
}

// A building's mechanism (issue 36: length): one line per approach of the
// conclusion's code, each quotient written out so that it can be redone;
// the dynamic analysis has no index (said in the introduction).
void brief_safety_indices(Ctx& c, const MethodVerdict& concl) {
  std::vector<Inline> items;
  for (const SafetyIndex& s : c.a.indices) {
    if (s.code != concl.code || s.approach == "dynamic") continue;
    const std::string method = c.t("method." + method_of_kind(s.approach));
    if (!s.defined) {
      items.push_back({Span{method + ": " + c.note(s.note)}});
      continue;
    }
    const CheckIndex& v = s.index;
    const bool above = v.extrapolated && v.TR_capacity > tr_max_years;
    const std::string yrs = " " + c.t("site.years");
    const std::string trc = !v.extrapolated ? "= " + c.n(v.TR_capacity, 0) + yrs
                                            : (above ? "> 2475" : "< 30") + yrs + " (" + c.t("zeta.extrapolated_short") + ")";
    const std::string ratio = !v.extrapolated ? "= " + c.n(v.TR_ratio, 2)
                                              : (above ? "> " : "< ") + c.n((above ? tr_max_years : tr_min_years) / v.TR_demand, 2);
    Span zeta("ζE = " + c.n(v.zeta, 3), true, verdict_tone(s.outcome()));
    std::string tail = "; TR_C " + trc + ", TR_D = " + c.n(v.TR_demand, 0) + yrs + ", TR_C/TR_D " + ratio;
    if (v.bound != 0) tail += " (" + c.t(v.bound > 0 ? "zeta.bound_above" : "zeta.bound_below") + ")";
    if (v.shape_held) tail += " (" + c.t("zeta.shape_held") + ")";
    if (v.non_monotonic) tail += " (" + msgf(c.L, "zeta.non_monotonic", c.n(v.other_crossing_TR, 0)) + ")";
    items.push_back({Span{method + " (" + s.limit_state + ", " + c.t("where." + s.location) + "): PGA_C/PGA_D = " +
                          c.n(v.ag_capacity_g, 4) + "/" + c.n(v.ag_demand_g, 4) + " g, "},
                     zeta, Span{tail + "."}});
  }
  if (!items.empty()) c.d.add_list(items);
}

// Safety indices (issue 28, item 3; docs/theory/building.md §4): per method
// and edition the PGA the mechanism withstands, the site's, zetaE and the
// return periods; an extrapolated return period is shown as a bound.
void add_safety_indices(Ctx& c) {
  const std::vector<SafetyIndex>& idx = c.a.indices;  // computed once by the assessment (issue 41)
  if (idx.empty()) return;
  c.d.add_heading(c.t("zeta.heading"));
  // A building's mechanism: the code of the conclusion alone (the other
  // edition's indices are in the building's summary; issue 36: length), its
  // definition in one sentence.
  const MethodVerdict* concl = c.a.verdict.conclusion();
  const bool brief = c.building && c.tabulati && concl;
  c.d.add_paragraph(c.t(brief ? "zeta.intro_brief" : "zeta.intro"));
  if (brief) {
    brief_safety_indices(c, *concl);
    return;
  }
  std::vector<std::vector<Cell>> rows;
  bool any_extrapolated = false;
  for (const SafetyIndex& s : idx) {
    if (brief && s.code != concl->code) continue;
    // A building's mechanism: the dynamic analysis has no index, said in the
    // introduction rather than by a row of dashes.
    if (brief && !s.defined && s.approach == "dynamic") continue;
    const std::string method = c.t("method." + method_of_kind(s.approach));
    if (!s.defined) {
      Cell why(s.approach == "dynamic" ? c.t("zeta.no_dynamic") : c.note(s.note));
      rows.push_back({Cell(code_name(s.code)), Cell(method), Cell("—"), c.num(std::nan(""), 3), c.num(std::nan(""), 3),
                      c.num(std::nan(""), 3), c.num(std::nan(""), 0), c.num(std::nan(""), 0), c.num(std::nan(""), 2), why});
      continue;
    }
    const std::string where = s.limit_state + ", " + c.t("where." + s.location) +
                              (s.candidate.empty() ? "" : "; " + c.loc(s.candidate));
    Cell zeta = c.num(s.index.zeta, 3);
    zeta.tone = verdict_tone(s.outcome());  // by the verdict of its approach (issue 41)
    Cell trc = c.num(s.index.TR_capacity, 0), ratio = c.num(s.index.TR_ratio, 2);
    std::vector<std::string> notes;
    if (s.index.extrapolated) {
      any_extrapolated = true;
      const bool above = s.index.TR_capacity > tr_max_years;
      trc.text = above ? "> 2475" : "< 30";
      ratio.text = (above ? "> " : "< ") + c.n((above ? tr_max_years : tr_min_years) / s.index.TR_demand, 2);
      notes.push_back(c.t(above ? "zeta.tr_above_short" : "zeta.tr_below_short"));
    }
    if (s.index.bound != 0) notes.push_back(c.t(s.index.bound > 0 ? "zeta.bound_above" : "zeta.bound_below"));
    if (s.index.shape_held) notes.push_back(c.t("zeta.shape_held"));
    if (s.index.non_monotonic) notes.push_back(msgf(c.L, "zeta.non_monotonic", c.n(s.index.other_crossing_TR, 0)));
    std::string note;
    for (const std::string& n : notes) note += (note.empty() ? "" : "; ") + n;
    rows.push_back({Cell(code_name(s.code)), Cell(method), Cell(where), c.num(s.index.ag_capacity_g, 4), c.num(s.index.ag_demand_g, 4),
                    zeta, trc, c.num(s.index.TR_demand, 0), ratio, Cell(note)});
  }
  c.d.add_cell_table({Cell(c.t("checks.code")), Cell(c.t("cmp.method")), Cell(c.t("zeta.check")), numeric_cell("PGA_C (g)"),
                      numeric_cell("PGA_D (g)"), numeric_cell("ζE"), numeric_cell("TR_C (" + c.t("site.years") + ")"), numeric_cell("TR_D (" + c.t("site.years") + ")"),
                      numeric_cell("TR_C/TR_D"), Cell(c.t("zeta.notes"))},
                     rows, c.t("zeta.cap"));
  if (any_extrapolated) c.d.add_paragraph(c.t("zeta.extrapolated"), "note");
  if (c.a.kase.report.heritage) {
    c.d.add_paragraph(c.t("zeta.heritage"));
    if (c.readings) c.readings->insert("D.P.C.M. 9/2/2011 I_S,SLV f_a,SLV [R]");
  }
}

}  // namespace assess::relazione
