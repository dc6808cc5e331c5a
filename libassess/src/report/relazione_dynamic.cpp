// relazione_dynamic.cpp: the non-linear dynamic analysis (Circ. 2019
// C8.7.1.2.1.9; issue 28, items 1, 2, 5): the candidate that governs the
// dynamic verdict developed in full (its equation of motion with the
// reference, the equivalent body's parameters consistent with each other,
// the restitution coefficients as numbers, the records, their compatibility,
// the histories and the summary with the collapse convention), then every
// other candidate analysed.
#include "report/relazione_context.hpp"

#include "assess/report/relazione.hpp"

#include "report/report_heading.hpp"
#include "report/text_format.hpp"

#include "assess/report/plot.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <map>

namespace assess::relazione {

using detail::code_name;

namespace {

constexpr double g = units::g;

// The assessment whose dynamic analysis governs the dynamic verdict (the
// governing candidate's own, or one of the other candidates').
const FacadeAssessment& governing_dynamics(const FacadeAssessment& a) {
  for (const MethodVerdict& m : a.verdict.methods) {
    if (m.method != "dynamic" || m.code != a.verdict.conclusion_code || m.governing < 0) continue;
    const std::size_t ci = candidate_of(a, a.verdict.rows[std::size_t(m.governing)].candidate);
    for (std::size_t k = 0; k < a.other_dynamics.size(); ++k)
      if (a.other_dynamics_candidate[k] == ci && a.other_dynamics[k].dynamics.applies) return a.other_dynamics[k];
  }
  return a;
}

std::string restitution_text(const Ctx& c, const FacadeAssessment& x, const RestitutionSummary& s) {
  const Restitution& r = x.dynamics.spec->restitutions[s.restitution];
  if (r.kind == Restitution::Kind::value) return "e = " + c.n(s.e, 3);
  return "e = " + c.n(s.e, 3) + " (" + c.t(r.kind == Restitution::Kind::housner ? "dyn.e_housner" : "dyn.e_one_sided") + ")";
}

// The model: equation of motion with its reference, and the body's parameters.
void add_model(Ctx& c, const FacadeAssessment& x) {
  const MechanismDynamics& md = *x.dynamics.mechanism;
  const DynamicSpec& d = *x.dynamics.spec;
  std::string what = c.t(d.smooth ? "dyn.smooth" : "dyn.rigid") + ", ";
  if (x.dynamics.model) what += c.t(x.dynamics.model->sidedness() == Sidedness::one_sided ? "dyn.one_sided" : "dyn.two_sided") + ". ";
  c.d.add_paragraph(what + c.t("dyn.model") + ": " + c.note(md.describe()) + ".");
  c.d.add_paragraph(c.t(md.single_body() ? "dyn.eq_body" : "dyn.eq_chain"), "note");
  if (d.smooth) c.d.add_paragraph(c.t("dyn.eq_winkler"), "note");
  c.d.add_paragraph(c.t("dyn.eq_impact"), "note");
  std::vector<std::vector<Cell>> rows;
  auto row = [&](const std::string& what, double v, int prec, const std::string& unit, const std::string& how) {
    rows.push_back({Cell(what), c.num(v, prec), Cell(unit), Cell(how)});
  };
  if (x.dynamics.model) {
    const RockingBody& b = x.dynamics.model->body();
    row(c.t("dyn.p_W"), b.W / units::kN, 3, "kN/m", c.t("dyn.h_W"));
    row(c.t("dyn.p_b"), b.b, 4, "m", c.t("dyn.h_b"));
    row(c.t("dyn.p_xG"), b.x_G(), 4, "m", c.t("dyn.h_xG"));
    row(c.t("dyn.p_zG"), b.z_G(), 4, "m", c.t("dyn.h_zG"));
    row("R", b.R, 4, "m", "√(x_G² + z_G²) = √(" + c.n(b.x_G(), 4) + "² + " + c.n(b.z_G(), 4) + "²)");
    row("α", b.alpha, 5, "rad", "atan(x_G / z_G) = atan(" + c.n(b.x_G(), 4) + " / " + c.n(b.z_G(), 4) + ")");
    row("I₀", b.I0, 1, "kg m²/m", c.t("dyn.h_I0"));
    row("p", b.p(), 4, "rad/s", "√(W R / I₀)");
    if (b.M_ext != 0.0) row(c.t("dyn.p_Mext"), b.M_ext / units::kN, 3, "kN m/m", c.t("dyn.h_Mext"));
    if (d.smooth) {
      row("k", d.k / units::kN, 0, "kN/m³", c.t("data.case"));
      row("θ_cr", x.dynamics.model->theta_cr(), 6, "rad", "W / (2 b² k)");
    }
    row("θu", x.dynamics.model->theta_u(+1), 5, "rad", c.t(d.smooth ? "dyn.h_thu_smooth" : "dyn.h_thu_rigid"));
  } else {
    row("q_u", md.q_u(), 5, "rad", c.t("dyn.h_qu_chain"));
  }
  row(c.t("dyn.capacity"), md.capacity() / units::kN, 4, "kJ/m", c.t("dyn.h_capacity"));
  for (const RestitutionSummary& s : x.dynamics.summaries) rows.push_back({Cell(c.t("dyn.p_e")), c.num(s.e, 4), Cell("–"), Cell(restitution_text(c, x, s))});
  Cell hv(c.t("kin.value"));
  hv.numeric = true;
  c.d.add_cell_table({Cell(c.t("kin.quantity")), hv, Cell(c.t("kin.unit")), Cell(c.t("kin.how"))}, rows,
                     c.t("dyn.params_cap"));
  // The moment-rotation curve.
  if (!x.curves.mr_theta.empty()) {
    Plot mr = c.plot();
    mr.title = c.t("dyn.mr_title");
    mr.x_label = "θ (rad)";
    mr.y_label = "M (kN m/m)";
    PlotSeries s = plot_series(c.t("dyn.mr_series"), PlotSeries::Style::Line, x.curves.mr_theta);
    for (double v : x.curves.mr_moment) s.y.push_back(v / units::kN);
    s.highlight = true;
    mr.series.push_back(s);
    mr.height = 320;
    c.d.add_svg(render_svg(mr), c.t(md.tied() ? "dyn.mr_fig_tied" : "dyn.mr_fig"), "fig-moment-rotation");
  }
}

// The records (issues 24, 30): what each is (event, date, station, country,
// magnitude, distance and its kind, site class with its basis, usable
// period), why it was chosen (scale, misfit and rank) and its flags; then the
// selection's caveats, the period range and why, the compatibility, and how
// the analyses ended. "—" where the catalogue says nothing.
void add_records(Ctx& c, const FacadeAssessment& x) {
  if (!c.o.shared_records.empty()) {
    // A building's set shared by several mechanisms: described once in its summary (issue 28, item 11).
    std::string names;
    for (const RecordUsed& r : x.dynamics.records) names += (names.empty() ? "" : ", ") + r.name + " (" + c.n(r.scale, 3) + ")";
    c.d.add_paragraph(msgf(c.L, "dyn.shared_set", c.o.shared_records, names));
    if (!x.selection.range_note.empty())
      c.d.add_list({{Span{c.t("dyn.range_why") + ": ", true}, Span{c.note(x.selection.range_note)}}});
    return;
  }
  std::vector<std::vector<Cell>> rows;
  auto or_dash = [](const std::string& t) { return t.empty() ? std::string("—") : t; };
  for (const RecordUsed& r : x.dynamics.records) {
    Cell dist = c.num(r.distance_km, 1);
    if (std::isfinite(r.distance_km)) dist.text += " " + r.distance_kind;
    std::string cls = or_dash(r.site_class);
    if (r.site_class_basis == "Vs30") cls += " (Vs30 " + c.n(r.vs30_m_s, 0) + ")";
    else if (r.site_class_basis == "stated")
      cls += " (" + c.t("dyn.class_stated") + (std::isfinite(r.vs30_m_s) ? "; Vs30 " + c.n(r.vs30_m_s, 0) : "") + ")";
    const std::string what =
        r.in_catalogue ? or_dash(r.event) + ", " + or_dash(r.date) + " / " + or_dash(r.station) + ", " +
                             or_dash(r.component) + " — " + or_dash(r.country)
        : r.event.empty() && r.station.empty() ? std::string("—")
                                               : or_dash(r.event) + " / " + or_dash(r.station) + ", " + or_dash(r.component);
    std::string flags;
    for (const Note& f : r.flags) flags += (flags.empty() ? "" : "; ") + c.note(f);
    Cell name(r.name, flags);
    if (!r.flags.empty()) name.tone = Tone::fail;
    rows.push_back({name, Cell(what), c.num(r.Mw, 2), dist, Cell(cls), c.num(r.usable_period_s, 2), c.num(r.scale, 3),
                    c.num(r.pga / g, 4), c.num(r.deviation, 3), r.rank > 0 ? c.num(r.rank, 0) : c.num(std::nan(""), 0),
                    c.num(r.integrated_s, 1)});
  }
  c.d.add_cell_table({Cell(c.t("dyn.record_code")), Cell(c.t("dyn.event_station")), numeric_cell("Mw"), numeric_cell(c.t("dyn.distance")),
                      Cell(c.t("dyn.site_class")), numeric_cell(c.t("dyn.usable")), numeric_cell(c.t("dyn.scale")), numeric_cell("PGA (g)"),
                      numeric_cell(c.t("dyn.deviation")), numeric_cell(c.t("dyn.rank")), numeric_cell(c.t("dyn.integrated"))},
                     rows, c.t("dyn.records_cap") + " " + c.t("dyn.flags_cap"));
  for (const std::string& w : x.selection.warnings) c.d.add_paragraph(c.t("dyn.selection_warning") + ": " + c.loc(w));
  for (const std::string& f : x.selection.record_failures) c.d.add_paragraph(c.t("dyn.skipped") + ": " + f);
  if (x.selection.result) {
    c.d.add_paragraph(msgf(c.L, "dyn.selection", c.n(x.selection.range.T_min, 2), c.n(x.selection.range.T_max, 2)) +
                      c.loc(x.selection.result->message));
    std::vector<Inline> why;
    if (!x.selection.range_note.empty()) why.push_back({Span{c.t("dyn.range_why") + ": ", true}, Span{c.note(x.selection.range_note)}});
    if (!x.selection.shared_note.empty())
      why.push_back({Span{c.t("dyn.shared_why") + ": ", true}, Span{c.note(x.selection.shared_note)}});
    for (const NoteText& st : x.selection.steps) why.push_back({Span{c.t("dyn.classes_tried") + ": ", true}, Span{c.note(st)}});
    // The limits the set obeys and the rules it was chosen by (what the terminal printed before issue 41).
    const SelectionResult& s = *x.selection.result;
    why.push_back({Span{c.t("dyn.limits") + ": ", true},
                   Span{msgf(c.L, "dyn.limits_text", c.n(x.selection.max_scale, 2), c.n(s.mean_scale, 3),
                             c.n(x.selection.max_mean_scale, 2), c.n(s.max_scaled_pga / g, 3),
                             c.n(x.selection.max_pga_ratio, 2), c.n(x.selection.max_pga_ratio * s.target_pga / g, 3))}});
    why.push_back({Span{c.t("dyn.rules") + ": ", true},
                   Span{msgf(c.L, x.selection.include_near_fault ? "dyn.rules_nf_in" : "dyn.rules_nf_out",
                             x.selection.near_fault_excluded, c.n(x.selection.near_fault_km, 0),
                             c.n(x.selection.max_misfit, 2)) +
                        c.t(x.selection.spectra == "precomputed" ? "dyn.spectra_pre" : "dyn.spectra_int")}});
    if (!why.empty()) c.d.add_list(why);
  }
  if (x.dynamics.compatibility.computed) c.d.add_paragraph(c.t("dyn.compat_msg") + ": " + c.note(x.dynamics.compatibility.message) + ".");
  std::map<std::string, int> ends;
  for (const DynamicRun& r : x.dynamics.runs) ++ends[to_string(r.result.end)];
  std::string list;
  for (const auto& [k, n] : ends) list += (list.empty() ? "" : "; ") + c.t("end." + k) + ": " + std::to_string(n);
  c.d.add_paragraph(c.t("dyn.duration") + " " + c.n(x.dynamics.free_tail_s, 0) + " s. " + c.t("dyn.ends") + " — " + list + ".");
}

void add_floor_spectra(Ctx& c, const FacadeAssessment& x);

void add_compatibility(Ctx& c, const FacadeAssessment& x, const std::string& id = "fig-compatibility") {
  const auto se = x.curves.site_Se.find(LimitState::SLV);
  if (se == x.curves.site_Se.end() || x.curves.record_psa.empty()) return;
  Plot p = c.plot();
  p.title = c.t("dyn.compat_title");
  p.x_label = "T (s)";
  p.y_label = "Se, PSA (g)";
  const PeriodRange& rg = x.dynamics.compatibility.computed ? x.dynamics.compatibility.range : x.selection.range;
  if (rg.T_max > rg.T_min) {
    PlotSeries band = plot_series(c.t("dyn.band"), PlotSeries::Style::Band);
    for (std::size_t i = 0; i < x.curves.periods.size(); ++i) {
      const double T = x.curves.periods[i];
      if (T < rg.T_min || T > rg.T_max) continue;
      band.x.push_back(T);
      band.y.push_back(1.3 * se->second[i] / g);
      band.y_low.push_back(0.9 * se->second[i] / g);
    }
    band.color = "#1f5fbf";
    if (!band.x.empty()) p.series.push_back(band);
  }
  PlotSeries target = plot_series("Se SLV", PlotSeries::Style::Line, x.curves.periods);
  for (double v : se->second) target.y.push_back(v / g);
  target.color = "#1f5fbf";
  target.highlight = true;
  p.series.push_back(target);
  for (std::size_t i = 0; i < x.curves.record_psa.size(); ++i) {
    PlotSeries s = plot_series(i == 0 ? c.t("site.records_scaled") : "", PlotSeries::Style::Line, x.curves.periods);
    for (double v : x.curves.record_psa[i]) s.y.push_back(v / g);
    s.color = "#aaaaaa";
    p.series.push_back(s);
  }
  if (!x.curves.mean_psa.empty()) {
    PlotSeries s = plot_series(c.t("site.records_mean"), PlotSeries::Style::Line, x.curves.periods);
    for (double v : x.curves.mean_psa) s.y.push_back(v / g);
    s.color = "#000000";
    s.highlight = true;
    p.series.push_back(s);
  }
  double top = 0.0;
  for (double v : se->second) top = std::max(top, 1.3 * v / g);
  for (double v : x.curves.mean_psa) top = std::max(top, v / g);
  if (rg.T_max > rg.T_min) {
    PlotSeries l1 = plot_series(c.t("dyn.range"), PlotSeries::Style::Dashed, {rg.T_min, rg.T_min}, {0.0, 1.2 * top});
    PlotSeries l2 = plot_series("", PlotSeries::Style::Dashed, {rg.T_max, rg.T_max}, {0.0, 1.2 * top});
    l1.color = l2.color = "#444444";
    p.series.push_back(l1);
    p.series.push_back(l2);
  }
  p.y_min = 0.0;
  p.y_max = 1.25 * top;
  p.x_min = 0.0;
  p.x_max = x.curves.periods.empty() ? 4.0 : x.curves.periods.back();
  c.d.add_svg(render_svg(p), c.t("dyn.compat_fig"), id);
}

// At height: the mean spectrum of the floor motions against the code's floor spectrum.
void add_floor_spectra(Ctx& c, const FacadeAssessment& x) {
  if (x.curves.code_floor_Se.empty()) return;
  Plot fp = c.plot();
  fp.title = c.t("dyn.floor_title");
  fp.x_label = "T (s)";
  fp.y_label = "Sa (g)";
  PlotSeries fm = plot_series(c.t("dyn.floor_series"), PlotSeries::Style::Line, x.curves.periods);
  for (double v : x.curves.floor_mean_psa) fm.y.push_back(v / g);
  fm.highlight = true;
  PlotSeries cf = plot_series("S_eZ [C7.2.6]", PlotSeries::Style::Dashed, x.curves.periods);
  for (double v : x.curves.code_floor_Se) cf.y.push_back(v / g);
  fp.series.push_back(fm);
  fp.series.push_back(cf);
  c.d.add_svg(render_svg(fp), c.t("dyn.floor_fig"), "fig-floor-spectra");
}

void add_histories(Ctx& c, const FacadeAssessment& x) {
  std::vector<std::pair<std::string, std::string>> panels;
  static const char* colours[] = {"#1f5fbf", "#d9730d", "#2b7a2b", "#8a3ea8"};
  for (std::size_t ir = 0; ir < x.dynamics.records.size(); ++ir) {
    Plot p = c.plot();
    p.x_label = "t (s)";
    p.y_label = "θ/θu";
    p.width = 300;
    p.height = 190;
    p.font_size = 11;  // legible at a third of the page width
    p.key = "off";
    double t_show = 0.0, t_last = 0.0;
    for (const DynamicRun& r : x.dynamics.runs)
      if (r.record == ir) t_show = std::max(t_show, r.result.t_theta_max), t_last = std::max(t_last, r.result.t_end);
    p.x_min = 0.0;
    p.x_max = std::min(t_last, t_show + 10.0);
    if (!(p.x_max > 0.0)) p.x_max = 1.0;
    bool overturned = false;
    for (const DynamicRun& r : x.dynamics.runs) {
      if (r.record != ir || r.result.history.t.empty()) continue;
      PlotSeries s = plot_series("", r.reversed ? PlotSeries::Style::Dashed : PlotSeries::Style::Line);
      const std::vector<double>& t = r.result.history.t;
      const std::size_t n = std::size_t(std::upper_bound(t.begin(), t.end(), p.x_max) - t.begin());
      const std::size_t step = std::max<std::size_t>(1, n / 600);
      for (std::size_t i = 0; i < n; i += step) {
        s.x.push_back(t[i]);
        s.y.push_back(r.result.history.theta[i] / r.result.theta_u);
      }
      if (s.x.empty()) continue;
      s.color = colours[r.restitution % 4];
      p.series.push_back(s);
      if (r.result.overturned && r.result.t_overturn) {
        PlotSeries o = plot_series("", PlotSeries::Style::Points, {*r.result.t_overturn}, {1.0});
        o.point_type = 2;
        o.point_size = 2.0;
        o.color = "#b3001b";
        p.series.push_back(o);
        overturned = true;
      }
    }
    if (p.series.empty()) continue;
    PlotSeries one = plot_series("", PlotSeries::Style::Dashed, {0.0, p.x_max}, {1.0, 1.0});
    one.color = "#b3001b";
    p.series.push_back(one);
    p.y_min = -1.1;
    p.y_max = 1.1;
    panels.push_back({render_svg(p), x.dynamics.records[ir].name + (overturned ? " — " + c.t("dyn.overturning") : "")});
  }
  if (panels.empty()) return;
  c.d.add_heading(c.t("dyn.histories"), 3, false);
  c.d.add_svg_grid(panels, c.t("dyn.histories_fig"), "fig-histories");
}

// The summary per restitution value: the check's D/C with the collapse
// convention (+inf, the figure over the analyses without a collapse apart),
// the energy D/C the same way, and the outcome read from the check.
void add_summary(Ctx& c, const FacadeAssessment& x) {
  const bool brief = c.building && c.tabulati;  // a building's mechanism: the caption in short (issue 36: length)
  if (!brief) c.d.add_heading(c.t("dyn.summary"), 3, false);
  std::vector<std::vector<Cell>> rows;
  for (const RestitutionSummary& s : x.dynamics.summaries) {
    bool uplift = false;
    for (const DynamicRun& r : x.dynamics.runs) uplift = uplift || (r.restitution == s.restitution && r.result.theta_max > 0.0);
    Cell coll(std::to_string(s.collapsed) + " / " + std::to_string(s.analyses));
    coll.numeric = true;
    if (s.failed > 0) coll.note = msgf(c.L, "dc.failed", s.failed, s.analyses);
    Cell energy = c.dc_cell(s.energy_dc, outcome_of(check_satisfied(s.energy_dc, false), false));
    if (!std::isfinite(s.energy_dc) && std::isfinite(s.mean_dc_survivors))
      energy.note = msgf(c.L, "dc.survivors", c.n(s.mean_dc_survivors, 3));
    Cell dc = c.dc_cell(s.dc_slv, s.outcome());
    if (!std::isfinite(s.dc_slv) && std::isfinite(s.dc_survivors))
      dc.note = msgf(c.L, "dc.survivors", c.n(s.dc_survivors, 3));
    if (!uplift) energy.note = dc.note = c.t("dyn.no_uplift");  // a computed zero, said why
    Cell out = c.outcome_cell(s.outcome());
    if (s.collapsed > 0) out.note = msgf(c.L, "dc.collapse", s.collapsed, s.analyses);
    else if (!uplift) out.note = c.t("dyn.no_uplift");
    rows.push_back({Cell(restitution_text(c, x, s)), c.num(s.analyses, 0), coll, energy, c.num(s.mean_d_star, 4),
                    c.num(s.max_d_star, 4), Cell(c.loc(s.rule)), c.num(s.d_demand, 4), dc, out});
  }
  c.d.add_cell_table({Cell(c.t("dyn.restitution")), numeric_cell(c.t("dyn.analyses")), numeric_cell(c.t("dyn.collapses")),
                      numeric_cell(c.t("dyn.energy_dc")), numeric_cell(c.t("dyn.mean_d")), numeric_cell(c.t("dyn.max_d")), Cell(c.t("dyn.rule")),
                      numeric_cell(c.t("dyn.d_demand")), numeric_cell(c.t("dyn.dc_slv")), Cell(c.t("checks.outcome"))},
                     rows, c.t(brief ? "dyn.summary_cap_brief" : "dyn.summary_cap2"));
}

// The other candidates analysed (each as the case restricted to it).
void add_others(Ctx& c, const FacadeAssessment& shown) {
  const FacadeAssessment& a = c.a;
  std::vector<std::pair<const FacadeAssessment*, std::size_t>> list;  // assessment, candidate index
  if (&shown != &a) list.push_back({&a, a.kinematic.governing});
  for (std::size_t k = 0; k < a.other_dynamics.size(); ++k)
    if (&a.other_dynamics[k] != &shown) list.push_back({&a.other_dynamics[k], a.other_dynamics_candidate[k]});
  if (list.empty()) return;
  c.d.add_heading(c.t("dyn.others"), 3, false, true, "dynamic-others");
  c.d.add_paragraph(c.t("dyn.others_text"));
  std::vector<std::vector<Cell>> rows;
  for (const auto& [o, ci] : list) {
    const std::string label = c.loc(c.candidate(ci).label);
    if (!o->dynamics.applies) {
      rows.push_back({Cell(label), Cell("—"), Cell("—"), c.num(std::nan(""), 0), c.num(std::nan(""), 4),
                      c.num(std::nan(""), 4), c.num(std::nan(""), 3), Cell(c.t("dyn.na") + ": " + c.note(o->dynamics.note))});
      continue;
    }
    std::string recs;
    for (const RecordUsed& r : o->dynamics.records) recs += (recs.empty() ? "" : ", ") + r.name + " (" + c.n(r.scale, 2) + ")";
    for (const RestitutionSummary& s : o->dynamics.summaries) {
      Cell coll(std::to_string(s.collapsed) + " / " + std::to_string(s.analyses));
      coll.numeric = true;
      Cell dc = c.dc_cell(s.dc_slv, s.outcome());
      if (!std::isfinite(s.dc_slv) && std::isfinite(s.dc_survivors))
        dc.note = msgf(c.L, "dc.survivors", c.n(s.dc_survivors, 3));
      if (s.dc_slv == 0.0 && s.analyses > 0) dc.note = c.t("dyn.no_uplift");
      Cell out = c.outcome_cell(s.outcome());
      rows.push_back({Cell(label), Cell(recs), Cell(restitution_text(c, *o, s)), coll, c.num(s.d_demand, 4),
                      c.num(o->kinematic.candidates.front().result.d_SLV, 4), dc, out});
    }
  }
  c.d.add_cell_table({Cell(c.t("dyn.candidate")), Cell(c.t("dyn.records_used")), Cell(c.t("dyn.restitution")),
                      numeric_cell(c.t("dyn.collapses")), numeric_cell(c.t("dyn.d_demand")), numeric_cell("d_SLV (m)"), numeric_cell(c.t("dyn.dc_slv")),
                      Cell(c.t("checks.outcome"))},
                     rows, c.t("dyn.others_cap"));
}

}  // namespace

void add_record_set(Ctx& c, const FacadeAssessment& x, const std::string& id) {
  add_records(c, x);
  add_compatibility(c, x, id);
}

void add_dynamic_summary(Ctx& c) {
  const FacadeAssessment& a = c.a;
  if (!a.dynamics.spec) return;
  c.d.add_heading(c.t("dyn.heading"));
  if (!a.dynamics.applies) {
    c.d.add_paragraph(c.t("dyn.na") + ": " + c.note(a.dynamics.note));
    return;
  }
  const FacadeAssessment& x = governing_dynamics(a);
  c.d.add_paragraph(c.t("dyn.model_heading") + ": " + c.note(x.dynamics.note) + ".");
  c.d.add_heading(c.t("dyn.input_heading"), 3, false);
  add_records(c, x);
  if (c.o.shared_records.empty()) add_compatibility(c, x);
  c.d.add_heading(c.t("dyn.results_heading"), 3, false);
  add_summary(c, x);
  add_others(c, x);
}

// The dynamic analysis in the body (issue 36): the candidate analysed, its
// model in one sentence, the records (a building's shared set: by name), the
// summary per restitution value, the other candidates in one sentence; the
// model's parameters, the records' table, the histories and every other
// candidate are in the tabulati.
void add_dynamic(Ctx& c) {
  const FacadeAssessment& a = c.a;
  if (!a.dynamics.spec) return;
  c.d.add_heading(c.t("dyn.heading"), 2, false, true, "dynamic");
  if (!a.dynamics.applies) {
    c.d.add_paragraph(c.t("dyn.na") + ": " + c.note(a.dynamics.note));
    return;
  }
  const FacadeAssessment& x = governing_dynamics(a);
  const std::string label = c.loc(x.kinematic.candidates.front().label);
  c.d.add_paragraph(msgf(c.L, &x == &a ? "dyn.developed_gov" : "dyn.developed_other", label));
  const DynamicSpec& d = *x.dynamics.spec;
  std::string what = c.t(d.smooth ? "dyn.smooth" : "dyn.rigid") + ", ";
  if (x.dynamics.model) what += c.t(x.dynamics.model->sidedness() == Sidedness::one_sided ? "dyn.one_sided" : "dyn.two_sided") + ". ";
  Inline model{Span{what + c.t("dyn.model") + ": " + c.note(x.dynamics.mechanism->describe()) + "."}};
  if (c.tabulati) {
    model.push_back(Span{" "});
    model.push_back(reference(c.t("dyn.params_in_tab"), c.here("dynamic"), tabulati_key));
  }
  c.d.add_paragraph(model);
  // The records: by name and scale (the full table in the tabulati, or the building's set).
  std::string names;
  for (const RecordUsed& r : x.dynamics.records) names += (names.empty() ? "" : ", ") + r.name + " (" + c.n(r.scale, 3) + ")";
  if (!c.o.shared_records.empty()) {
    c.d.add_paragraph(msgf(c.L, "dyn.shared_set", c.o.shared_records, names));
  } else {
    Inline recs{Span{msgf(c.L, "dyn.records_body", x.dynamics.records.size(), names)}};
    if (c.tabulati) {
      recs.push_back(Span{" "});
      recs.push_back(reference(c.t("dyn.records_in_tab"), c.here("records"), tabulati_key));
    }
    c.d.add_paragraph(recs);
    if (x.selection.result)
      c.d.add_paragraph(msgf(c.L, "dyn.selection", c.n(x.selection.range.T_min, 2), c.n(x.selection.range.T_max, 2)) +
                        c.loc(x.selection.result->message));
    if (x.dynamics.compatibility.computed) c.d.add_paragraph(c.t("dyn.compat_msg") + ": " + c.note(x.dynamics.compatibility.message) + ".");
  }
  add_choice_notes(c, {"selection_window"});
  add_summary(c, x);
  // The other candidates analysed: one sentence here, their table in the tabulati.
  std::size_t others = a.other_dynamics.size() + (&x == &a ? 0 : 1);
  if (others > 0) {
    double worst = -1.0;
    for (const CheckRow& r : a.checks)
      if (r.kind == "dynamic") worst = std::max(worst, std::isfinite(r.dc) ? r.dc : 1e300);
    Inline o{Span{msgf(c.L, "dyn.others_body", others, worst >= 1e300 ? "∞" : c.n(worst, 3))}};
    if (c.tabulati) {
      o.push_back(Span{" "});
      o.push_back(reference(c.t("dyn.others_in_tab"), c.here("dynamic-others"), tabulati_key));
    }
    c.d.add_paragraph(o);
  }
}

// The dynamic analysis in the tabulati: the model (equation of motion, every
// parameter, the moment-rotation curve), the records with their metadata and
// flags, the selection, the compatibility, the floor spectra, the histories
// of every analysis, and every other candidate analysed.
void add_tab_dynamic(Ctx& c) {
  const FacadeAssessment& a = c.a;
  if (!a.dynamics.spec || !a.dynamics.applies) return;
  c.d.add_heading(c.t("dyn.heading"), 2, false, true, "dynamic");
  const FacadeAssessment& x = governing_dynamics(a);
  if (c.tabulati)
    c.d.add_paragraph(Inline{reference(c.t("dyn.summary_in_body"), c.here("dynamic"), relazione_key)}, "note");
  c.d.add_heading(c.t("dyn.model_heading"), 3, false);
  add_model(c, x);
  c.d.add_heading(c.t("dyn.input_heading"), 3, false, true, "records");
  add_records(c, x);
  if (c.o.shared_records.empty()) add_compatibility(c, x);
  add_floor_spectra(c, x);
  add_histories(c, x);
  add_others(c, x);
}

}  // namespace assess::relazione
