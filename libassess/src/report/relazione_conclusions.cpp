// relazione_conclusions.cpp: the comparison of the methods, the interventions,
// the probabilistic result, the evaluation of the results and the conclusions
// (issue 28, item 4): every sentence of judgement is computed from the
// verdict, the sensitivity study and the dynamic analyses, none is boilerplate.
#include "report/relazione_context.hpp"

#include "report/report_heading.hpp"
#include "report/text_format.hpp"

#include "assess/assessment/building_assessment.hpp"
#include "assess/report/plot.hpp"
#include "assess/report/tie_report.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>

namespace assess::relazione {

using detail::code_name;

namespace {

// One colour per code edition in every figure (issue 28, item 9).
const char* edition_colour(const std::string& code) {
  if (code == "NTC2008") return "#d9730d";
  if (code == "NTC2018") return "#1f5fbf";
  return "#2b7a2b";  // the seed's energy measure
}

std::string method_phrase(const Ctx& c, const MethodVerdict& m) {
  const std::string word = m.undecided() ? c.t("verdict.no_verdict_short") : c.t(m.satisfied ? "ok" : "fail");
  return c.t("method." + m.method) + ": " + word + " (D/C = " + c.n(m.max_dc, 3) + ")";
}

// The dynamic rows' collapses, in words: "collasso in 4 su 7 analisi (e = −0,48)".
std::string collapses_text(const Ctx& c) {
  std::string out;
  for (const CheckRow& r : c.a.checks) {
    if (r.kind != "dynamic" || r.collapsed == 0) continue;
    out += (out.empty() ? "" : "; ") + msgf(c.L, "dc.collapse", r.collapsed, r.analyses) + " (" + c.clause(r.clause) + ")";
  }
  return out;
}

}  // namespace

namespace {

// The comparison by approach: the bars (figure `id`, "" none) and every row's table (`rows_table`).
// A dynamic D/C of zero is computed (the wall never lifted): its cell says so (issue 36, item 5).
Cell zero_said(const Ctx& c, Cell dc, const VerdictRow& r) {
  if (r.dc == 0.0 && r.approach.rfind("dynamic", 0) == 0) dc.note = c.t("dyn.no_uplift");
  return dc;
}

void comparison(Ctx& c, bool figure, bool rows_table) {
  const Verdict& v = c.a.verdict;
  Plot p = c.plot();
  p.title = c.t("cmp.title");
  p.y_label = "D/C (–)";
  p.bar_width = 0.8;
  p.rotate_x_tic_labels = true;
  p.height = 480;
  p.width = 720;
  p.key = "outside right top";
  auto short_name = [&](const VerdictRow& r) {
    std::string n = c.t("short." + std::string(r.approach == "dynamic energy" ? "energy" : r.approach)) + " " +
                    r.limit_state;
    if (r.location == "height") n += " " + c.t("short.height");
    if (r.approach == "dynamic" || r.approach == "dynamic energy") {
      const std::size_t e = r.clause.find("e = ");
      if (e != std::string::npos) n += " e=" + c.loc(r.clause.substr(e + 4, r.clause.find(',', e) - e - 4));
    }
    return n;
  };
  std::vector<std::string> groups;
  for (const VerdictRow& r : v.rows)
    if (std::find(groups.begin(), groups.end(), r.code) == groups.end()) groups.push_back(r.code);
  double x = 0.0, dc_max = 1.0;
  for (const VerdictRow& r : v.rows)
    if (std::isfinite(r.dc)) dc_max = std::max(dc_max, r.dc);
  const double top = 1.25 * dc_max;
  std::vector<std::vector<Cell>> rows;
  for (const std::string& grp : groups) {
    PlotSeries bars;
    bars.name = grp == "seed" ? c.t("cmp.group_seed") : code_name(grp);
    bars.style = PlotSeries::Style::Bars;
    bars.color = edition_colour(grp);
    for (const VerdictRow& r : v.rows) {
      if (r.code != grp) continue;
      bars.x.push_back(x);
      bars.y.push_back(std::isfinite(r.dc) ? r.dc : top);  // a collapse: the bar reaches the top (∞ in the table)
      p.x_tic_labels.push_back({x, short_name(r) + (std::isfinite(r.dc) ? "" : " (∞)")});
      std::string note = c.loc(r.candidate.empty() ? "" : r.candidate + "; ") + c.clause(r.clause);
      if (!r.note.empty()) note += "; " + c.note(r.note);
      Cell outcome = c.outcome_cell(r.outcome());
      if (r.code == "seed") outcome.text = r.satisfied ? "≤ 1" : std::isfinite(r.dc) ? "> 1" : c.t("dc.collapse_word");
      rows.push_back({Cell(grp == "seed" ? c.t("cmp.group_seed") : code_name(r.code)),
                      Cell(c.t("kind." + r.approach) + " " + r.limit_state +
                               (r.location == "height" ? " (" + c.t("where.height") + ")" : ""),
                           note),
                      zero_said(c, c.dc_cell(r.dc, r.outcome()), r), outcome});
      x += 1.0;
    }
    p.series.push_back(bars);
    x += 0.6;
  }
  PlotSeries one;
  one.name = c.t("cmp.line");
  one.style = PlotSeries::Style::Dashed;
  one.x = {-0.6, x - 0.4};
  one.y = {1.0, 1.0};
  one.color = "#b3001b";
  one.highlight = true;
  p.series.push_back(one);
  p.x_min = -0.6;
  p.x_max = x - 0.4;
  p.y_min = 0.0;
  p.y_max = top;
  if (figure) c.d.add_svg(render_svg(p), c.t("cmp.fig"), "fig-dc");
  Cell hdc("D/C");
  hdc.numeric = true;
  if (rows_table)
    c.d.add_cell_table({Cell(c.t("checks.code")), Cell(c.t("cmp.approach")), hdc, Cell(c.t("checks.outcome"))}, rows,
                       c.t("cmp.table_cap"));
  // The methods' table repeats the verdict box: written where there is no box beside it (issue 36: length).
  if (!figure || c.tabulati) return;
  std::vector<std::vector<Cell>> orows;
  for (const MethodVerdict& m : v.methods) {
    Cell outcome(verdict_title(c.L, m.outcome()));
    outcome.tone = verdict_tone(m.outcome());
    Cell counts(std::to_string(m.failing) + " / " + std::to_string(m.checks));
    counts.numeric = true;
    orows.push_back({Cell(code_name(m.code) + (m.code == v.conclusion_code ? "" : " (" + c.t("verdict.comparison") + ")")),
                     Cell(c.t("method." + m.method) + (m.method == v.adopted ? " (" + c.t("verdict.adopted") + ")" : "")),
                     outcome, counts, c.num(m.no_verdict, 0), c.dc_cell(m.max_dc, m.outcome())});
  }
  c.d.add_cell_table({Cell(c.t("checks.code")), Cell(c.t("cmp.method")), Cell(c.t("cmp.overall")), numeric_cell(c.t("cmp.failing")),
                      numeric_cell(c.t("verdict.no_verdict")), numeric_cell(c.t("cmp.max_dc"))},
                     orows, c.t("cmp.methods_cap"));
}

}  // namespace

void add_comparison(Ctx& c) {
  if (c.a.verdict.rows.empty()) return;
  c.d.add_heading(c.t("cmp.heading"), 2, true, true, "comparison");
  if (c.tabulati)
    c.d.add_paragraph(Inline{reference(c.t("cmp.rows_in_tab"), c.here("comparison"), tabulati_key)}, "note");
  comparison(c, true, !c.tabulati);
}

void add_tab_comparison(Ctx& c) {
  if (c.a.verdict.rows.empty()) return;
  c.d.add_heading(c.t("cmp.heading_tab"), 3, false, true, "comparison");
  comparison(c, false, true);
}

// Interventions (issue 28, item 4; relazione.md §2.11): the ties' section
// when the case gives or designs ties; otherwise, when the adopted method
// fails, what the mechanism needs and how the ties can be designed.
void add_interventions(Ctx& c) {
  const MethodVerdict* m = c.a.verdict.conclusion();
  const bool fails = m && !m->satisfied;
  if (!c.o.ties && !fails) return;
  c.d.add_heading(c.t("int.heading"));
  if (c.o.ties) {
    add_tie_section(c, *c.o.ties);
    return;
  }
  c.d.add_paragraph(msgf(c.L, "int.needed", c.t("method." + m->method), c.n(m->max_dc, 3)));
}

// The probabilistic result (issue 16): a neutral box, labelled as not a code check.
void add_probabilistic(Ctx& c) {
  if (!c.o.fragility) return;
  const ProbabilisticResult& r = *c.o.fragility;
  c.d.add_heading(c.t("prob.heading"), 2, false);
  Box b{"probabilistic", Tone::plain, {}, {}};
  b.content.push_back(Paragraph{{Span{c.t("prob.not_a_check"), true}, Span{" " + c.t("prob.explain")}}, "", ""});
  const std::string method = r.method == "ida" ? c.t("prob.method.ida") : c.t("prob.method.stripes");
  b.content.push_back(Paragraph{{Span{c.t("prob.method") + ": " + method + "; " + std::to_string(r.analyses) + " " +
                                      c.t("prob.analyses") + ", " + std::to_string(r.failed) + " " + c.t("prob.failed") +
                                      ". " + c.t("prob.model") + ": " + c.loc(r.model) + ". " + c.t("prob.restitution") +
                                      ": " + c.loc(r.restitution) + "."}},
                                "meta", ""});
  std::vector<std::vector<Cell>> rows;
  auto row = [&](const std::string& k, const std::string& v) {
    Cell x(v);
    x.numeric = true;
    rows.push_back({Cell(k), x});
  };
  const std::string years = " " + c.t("prob.years");
  if (r.has_risk) {
    row(c.t("prob.median"), c.n(r.median_pga / units::g, 3) + " g");
    row(c.t("prob.beta"), c.n(r.beta, 3));
    row(c.t("prob.lambda"), c.e(r.lambda, 3) + c.t("prob.per_year"));
    row(c.t("prob.return_period"), c.n(r.return_period, 0) + years);
    row(c.t("prob.p_vn") + " (VN = " + c.n(r.VN, 0) + years + ")", c.n(100.0 * r.p_vn, 1) + " %");
  } else {
    row(c.t("prob.no_risk"), c.loc(r.note));
  }
  row(c.t("prob.tr_slv"), c.n(r.TR_SLV, 0) + years);
  if (r.has_risk && std::isfinite(r.p_at_SLV))
    row(c.t("prob.p_at_slv") + " (" + c.n(r.pga_SLV / units::g, 3) + " g)", c.n(100.0 * r.p_at_SLV, 1) + " %");
  DocumentBuilder inner("", to_string(c.L));
  Cell hv(c.t("prob.value"));
  hv.numeric = true;
  inner.add_cell_table({Cell(c.t("prob.quantity")), hv}, rows, "");
  inner.add_paragraph(c.t("prob.cap") + " " + c.t("prob.source") + ": " + detail::shown_file(r.source), "meta");
  for (DocBlock& x : inner.take_blocks()) b.content.push_back(std::move(x));
  c.d.add_box(std::move(b));
}

// Valutazione dei risultati (issues 28, 36): the adopted check's margin, the
// methods that disagree and by how much, the dynamic collapses, the
// alternatives of the modelling choices that change the verdict, the checks
// of acceptability that fail; then the judgement, decided by the assessment
// (assessment/judgement.hpp) and read here.
void add_evaluation(Ctx& c) {
  const Verdict& v = c.a.verdict;
  const MethodVerdict* m = v.conclusion();
  if (!m) return;
  c.d.add_heading(c.t("eval.heading"), 2, true, true, "evaluation");
  // Margin.
  const double dc = m->max_dc;
  std::string margin;
  if (m->undecided()) margin = c.t("eval.undecided");
  else if (!std::isfinite(dc)) margin = msgf(c.L, "eval.margin_inf", c.t("method." + m->method));
  else if (dc <= 1.0) margin = msgf(c.L, "eval.margin_ok", c.t("method." + m->method), c.n(dc, 3), c.n(100.0 * (1.0 - dc), 1));
  else margin = msgf(c.L, "eval.margin_fail", c.t("method." + m->method), c.n(dc, 3), c.n(100.0 * (dc - 1.0), 1));
  c.d.add_paragraph(margin);
  // The other methods of the same edition.
  std::vector<std::string> disagree, agree;
  for (const MethodVerdict& o : v.methods) {
    if (o.code != m->code || o.method == m->method) continue;
    (o.outcome() == m->outcome() ? agree : disagree).push_back(method_phrase(c, o));
  }
  auto join = [](const std::vector<std::string>& xs) {
    std::string s;
    for (const std::string& x : xs) s += (s.empty() ? "" : "; ") + x;
    return s;
  };
  if (!disagree.empty()) c.d.add_paragraph(msgf(c.L, "eval.disagree", join(disagree)));
  if (!agree.empty()) c.d.add_paragraph(msgf(c.L, "eval.agree", join(agree)));
  const std::string coll = collapses_text(c);
  if (!coll.empty()) c.d.add_paragraph(msgf(c.L, "eval.collapses", coll));
  if (!c.a.judgement) return;
  const Judgement& j = *c.a.judgement;
  // The modelling choices whose computed alternative changes the adopted verdict.
  std::vector<std::string> flips;
  for (std::size_t i : j.flips) flips.push_back(choice_flip_text(c, c.a.choices[i]));
  Inline choices{Span{flips.empty() ? c.t("eval.choices_none") : msgf(c.L, "eval.choices_flip", join(flips))}};
  if (c.tabulati && !c.a.choices.empty()) {
    choices.push_back(Span{" "});
    choices.push_back(c.building ? reference(c.t("choice.see_tab"), c.here("choices"), tabulati_key)
                                 : reference(c.t("choice.see_body"), c.here("choices")));
  }
  if (!c.a.choices.empty()) c.d.add_paragraph(choices);
  for (const std::string& k : j.implausible) {
    for (const AcceptabilityCheck& x : c.a.acceptability)
      if (x.key == k)
        c.d.add_paragraph(Inline{Span{msgf(c.L, "eval.implausible_" + k, c.n(x.value, 3), c.n(x.reference, 3)), false,
                                      Tone::fail}});
  }
  c.d.add_paragraph(Inline{Span{c.t("eval.judgement") + ": ", true}, Span{judgement_text(c, j)}});
}

void add_conclusions(Ctx& c, bool signature) {
  const Verdict& v = c.a.verdict;
  c.d.add_heading(c.t("doc.conclusioni"), 2, false);
  if (const MethodVerdict* m = v.conclusion()) {
    std::vector<Inline> items;
    for (const MethodVerdict& o : v.methods) {
      if (o.code != m->code) continue;
      items.push_back({Span{c.t("method." + o.method) + (o.method == v.adopted ? " (" + c.t("verdict.adopted") + ")" : "") + ": "},
                       c.outcome_span(o.outcome()), Span{", D/C = " + c.n(o.max_dc, 3)}});
    }
    c.d.add_paragraph(msgf(c.L, "concl.state", code_name(m->code)));
    c.d.add_list(items);
    std::string zeta;
    for (const SafetyIndex& s : c.a.indices)
      if (s.code == m->code && method_of_kind(s.approach) == m->method && s.defined)
        zeta = msgf(c.L, "concl.zeta", c.n(s.index.zeta, 3));
    // The judgement beside the verdict (issue 36, item 4): a verdict it calls
    // not robust is concluded with that qualification, never plainly.
    Inline line{Span{msgf(c.L, "concl.adopted", c.t("method." + m->method), code_name(m->code))}, c.outcome_span(m->outcome()),
                Span{", D/C = " + c.n(m->max_dc, 3) + zeta}};
    if (c.a.judgement) {
      const std::string q = judgement_qualifier(c, *c.a.judgement);
      if (!q.empty())
        line.push_back(Span{" — " + msgf(c.L, m->outcome() == Outcome::satisfied ? "concl.not_robust_ok" : "concl.not_robust_fail", q),
                            true});
      else if (c.a.judgement->robust)
        line.push_back(Span{" — " + c.t(m->outcome() == Outcome::satisfied ? "concl.robust_ok" : "concl.robust_fail")});
    }
    line.push_back(Span{". " + c.t("concl.see_eval")});
    c.d.add_paragraph(line);
  } else {
    c.d.add_paragraph(c.t("verdict.no_method_checks") + ".");
  }
  if (signature) add_signature(c);
}

void add_signature(Ctx& c) {
  const ReportInfo& r = c.a.kase.report;
  c.d.add_signature({c.t("doc.place_date") + ": " + (r.place.empty() ? "______________________" : r.place + ", ______________"),
                     c.t("doc.engineer") + ": " + (r.engineer.empty() ? "______________________" : r.engineer) +
                         (r.registration.empty() ? "" : " (" + r.registration + ")")});
}

}  // namespace assess::relazione
