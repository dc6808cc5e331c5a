// relazione_ties.cpp: the section of the relazione on the tie rods (issues
// 23, 29), as blocks of the document model (issue 28: one document for the
// HTML, PDF, Word and text writers): the stato di fatto and the stato di
// progetto, the ties drawn on the mechanism, each level's rod, ends, anchor
// and layout, the formulas with their sources, the checks (capacity design),
// the force each check needs, the two states side by side, the dynamic
// analyses with each tie's outcome, the detailing. Numbers go through the
// context (decimal comma in Italian, never inf or nan); every sentence is in
// the message catalogue (messages/ties.json, keys "tie.*"); the readings the
// section rests on are listed in the appendix (tie_readings), the body
// carries no certainty tag.
#include "assess/report/tie_report.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/report/mechanism_drawing.hpp"
#include "assess/support/units.hpp"
#include "report/relazione_context.hpp"
#include "report/svg_text.hpp"
#include "report/text_format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

namespace assess {

std::string tie_section_title(Lang lang) { return msg(lang, "tie.title"); }

std::vector<TieReading> tie_readings(const TieInterventionResult&, Lang lang) {
  std::vector<TieReading> out;
  for (int i = 1; i <= 18; ++i) {
    const std::string k = "tie.reading." + std::to_string(i);
    out.push_back({msg(lang, k + ".q"), msg(lang, k + ".r"), msg(lang, k + ".b")});
  }
  return out;
}

namespace relazione {
namespace {

constexpr double kN = units::kN;

// The tie messages ("tie." + key) and the context's numbers.
struct TieText {
  const Ctx& c;
  const std::string& t(const std::string& key) const { return msg(c.L, "tie." + key); }
  template <class... A>
  std::string f(const std::string& key, const A&... a) const {
    return msgf(c.L, "tie." + key, a...);
  }
  std::string n(double v, int prec) const { return c.n(v, prec); }
  Cell num(double v, int prec) const { return c.num(v, prec); }
  Cell ok(bool v) const {
    Cell x(t(v ? "ok" : "ko"));
    x.tone = v ? Tone::ok : Tone::fail;
    return x;
  }
  std::string component(const std::string& name) const { return t("component." + name); }
};

std::string rod_text(const TieText& x, const Tie& t) {
  return (t.rod.diameter > 0.0 ? "Ø" + x.n(t.rod.diameter * 1e3, 0) + " mm" : "A = " + x.n(t.rod.area * 1e6, 0) + " mm²") +
         " " + t.rod.grade + " (A = " + x.n(t.rod.area * 1e6, 0) + " mm²)";
}

std::string ends_text(const TieText& x, const Tie& t) {
  return x.t("ends." + std::string(to_string(t.rod.ends))) + " M" + x.n(t.rod.thread_diameter * 1e3, 0) +
         ", A_res = " + x.n(t.rod.thread_area * 1e6, 1) + " mm²";
}

std::string anchor_text(const TieText& x, const Tie& t) {
  return t.anchor.type == AnchorType::Plate
             ? x.t("plate") + " " + x.n(t.anchor.a * 1e3, 0) + " × " + x.n(t.anchor.b * 1e3, 0) + " × " +
                   x.n(t.anchor.t * 1e3, 0) + " mm " + t.anchor.grade
             : x.t("bar") + " " + x.n(t.anchor.a * 1e3, 0) + " mm, Ø" + x.n(t.anchor.b * 1e3, 0) + " mm " + t.anchor.grade;
}

std::string layout_text(const TieText& x, const Tie& t) {
  const TieLayout& L = t.layout;
  std::string s = x.f("layout_n", L.count, x.n(L.wall_length, 2));
  if (L.count > 1) s += ", " + x.f("layout_i", x.n(L.centre_spacing(), 2));
  return s + ", " + x.f("layout_e", x.n(L.edge_distance, 2));
}

// The governing candidate's chain of a state with each level drawn as a tie
// arrow of its design strength, labelled per tie and per level.
std::string drawing(const TieText& x, const CaseFile& kase, const KinematicCaseResult& r,
                    const std::vector<TieLevelResult>& levels) {
  const CandidateResult& cr = r.candidates[r.governing];
  const Chain& chain = kase.mechanism.candidates[r.governing].chain;
  std::vector<Load> loads;
  for (const Load& l : chain.loads())
    if (l.type != LoadType::SelfWeight) loads.push_back(l);
  for (const TieWork& w : cr.result.ties) {
    Load l;
    l.type = LoadType::Tie;
    l.name = w.tie.name;
    l.block = w.tie.block;
    l.point = w.tie.point;
    l.force = w.tie.capacity * w.tie.direction;
    for (const TieLevelResult& v : levels)
      if (v.tie.name == w.tie.name)
        l.label = x.f("drawing_label", x.n(v.resistance.design / kN, 1),
                      x.n(v.resistance.design * v.tie.layout.count / kN, 1));
    loads.push_back(l);
  }
  try {
    const Chain drawn(chain.blocks(), chain.constraints(), loads);
    return mechanism_svg(drawn, cr.result, x.c.L);
  } catch (const std::exception&) {
    return mechanism_svg(chain, cr.result, x.c.L);
  }
}

// One column per level (a wall has one or two): the rows read as a schedule.
void levels_table(const TieText& x, const std::vector<TieLevelResult>& levels) {
  std::vector<Cell> head{Cell(x.t("level"))};
  for (const TieLevelResult& L : levels) {
    Cell name(L.tie.name);
    name.user = true;
    head.push_back(name);
  }
  std::vector<std::vector<Cell>> rows;
  auto row = [&](const std::string& label, auto cell) {
    std::vector<Cell> r{Cell(label)};
    for (const TieLevelResult& L : levels) r.push_back(cell(L));
    rows.push_back(r);
  };
  row(x.t("state"), [&](const TieLevelResult& L) { return Cell(x.t(L.tie.existing ? "existing" : "new")); });
  row(x.t("rod"), [&](const TieLevelResult& L) { return Cell(rod_text(x, L.tie)); });
  row(x.t("ends"), [&](const TieLevelResult& L) { return Cell(ends_text(x, L.tie)); });
  row(x.t("anchor"), [&](const TieLevelResult& L) { return Cell(anchor_text(x, L.tie)); });
  row(x.t("layout"), [&](const TieLevelResult& L) { return Cell(layout_text(x, L.tie)); });
  row(x.t("free_length"), [&](const TieLevelResult& L) { return Cell(x.n(L.tie.free_length, 2)); });
  row(x.t("pretension"), [&](const TieLevelResult& L) { return Cell(x.n(L.tie.pretension / kN, 1)); });
  row(x.t("T_Rd_tie"), [&](const TieLevelResult& L) {
    return Cell(x.n(L.resistance.design / kN, 1) + " (" + x.component(L.resistance.governing) + ")");
  });
  row(x.t("T_Rd_level"), [&](const TieLevelResult& L) {
    return Cell(x.n(L.resistance.design * L.tie.layout.count / kN, 1));
  });
  row(x.t("behaviour"), [&](const TieLevelResult& L) { return Cell(x.t(L.resistance.ductile ? "ductile" : "elastic")); });
  x.c.d.add_cell_table(head, rows, x.t("levels_title"));
}

void formulas(const TieText& x) {
  std::vector<Inline> items;
  for (const char* k : {"f.rod", "f.thread", "f.bearing", "f.punching", "f.sliding", "f.plate", "f.bar", "f.hierarchy",
                        "f.elastic", "f.elongation", "f.temperature", "f.capacity", "f.layout"})
    items.push_back({Span{x.t(k)}});
  x.c.d.add_list(items);
  x.c.d.add_paragraph(x.t("f.note"));
}

// The cells of one check of a tie: check, clause, demand, capacity, unit,
// D/C and outcome (the tie's table and the wall's table, which adds the
// mechanism that governs each row after the clause).
std::vector<Cell> check_row_cells(const TieText& x, const TieCheckRow& r) {
  const double s = r.unit == "mm" ? 1e3 : r.unit == "kN" ? 1.0 / kN : 1.0;
  const bool count = r.unit == "analyses";
  Cell demand = !r.reachable ? Cell(x.t("unreachable")) : count ? x.num(r.demand, 0) : x.num(r.demand * s, 2);
  demand.numeric = true;
  // A D/C read from the check's own verdict (the one rule, issue 28): a break
  // or a force no tie can give is a failure, printed as such.
  Cell dc = r.reachable && !count ? x.num(r.dc, 3) : numeric_cell(r.satisfied ? "0" : "∞");
  dc.tone = r.satisfied ? Tone::ok : Tone::fail;
  dc.strong = true;
  if (count && r.satisfied) dc.note = x.t("no_break");  // a counted zero, said why (issue 36, item 5)
  else if (r.reachable && !count && r.dc == 0.0) dc.note = x.t("no_force");
  return {Cell(x.t("check." + r.check)), Cell(r.clause.empty() ? "" : x.t("clause." + r.check)), demand,
          count ? numeric_cell("0") : x.num(r.capacity * s, 2), Cell(count ? x.t("unit_analyses") : r.unit), dc,
          x.ok(r.satisfied)};
}

void checks_table(const TieText& x, const TieLevelResult& L) {
  std::vector<std::vector<Cell>> rows;
  for (const TieCheckRow& r : L.checks) rows.push_back(check_row_cells(x, r));
  x.c.d.add_cell_table({Cell(x.t("check")), Cell(x.t("clause")), numeric_cell(x.t("demand")), numeric_cell(x.t("capacity")),
                        Cell(x.t("unit")), numeric_cell("D/C"), Cell(x.t("outcome"))},
                       rows, x.t("checks_title") + " — " + L.tie.name);
}

void required_table(const TieText& x, const TieLevelResult& L) {
  std::vector<std::vector<Cell>> rows;
  for (const RequiredTieForce& f : L.required) {
    std::vector<Cell> row{Cell(f.code), Cell(f.limit_state), Cell(x.t("kind." + f.kind)), Cell(x.t("where." + f.location))};
    if (f.reachable) {
      row.push_back(x.num(f.per_tie / kN, 2));
      row.push_back(x.num(f.per_tie * L.tie.layout.count / kN, 2));
      row.push_back(x.num(f.per_metre / kN, 2));
    } else {
      row.push_back(Cell(x.t("unreachable"), x.t("unreachable_why")));
      row.push_back(Cell("—"));
      row.push_back(Cell("—"));
    }
    row.push_back(x.num(f.dc_without, 3));
    rows.push_back(row);
  }
  x.c.d.add_cell_table({Cell(x.t("code")), Cell(x.t("ls")), Cell(x.t("kind")), Cell(x.t("where")),
                        numeric_cell(x.t("per_tie")), numeric_cell(x.t("per_level")), numeric_cell(x.t("per_metre")),
                        numeric_cell(x.t("dc_without"))},
                       rows, x.t("required_title") + " — " + L.tie.name);
}

void level_block(const TieText& x, const TieLevelResult& L, const std::string& state) {
  x.c.d.add_heading(L.tie.name + " (" + state + ")", 4, false);
  const TieResistance& r = L.resistance;
  x.c.d.add_paragraph(r.ductile ? x.f("ductile_text", x.n(r.hierarchy_demand / kN, 1), x.component(r.weakest_brittle),
                                      x.n(r.weakest_brittle_capacity / kN, 1), x.n(r.ultimate_elongation * 1e3, 0))
                      : L.tie.rod.ends == TieEnds::Threaded
                          ? x.f("elastic_text_threaded", x.n(r.thread / kN, 1), x.n(L.demand.elastic_demand() / kN, 2))
                          : x.f("elastic_text", x.component(r.weakest_brittle), x.n(r.weakest_brittle_capacity / kN, 1),
                                x.n(r.hierarchy_demand / kN, 1), x.n(L.demand.elastic_demand() / kN, 2)));
  std::string dem = x.f("demand_static", x.n(L.demand.static_force / kN, 2));
  if (L.demand.curve_force) dem += "; " + x.f("demand_curve", x.n(*L.demand.curve_force / kN, 2));
  if (L.demand.dynamic_force)
    dem += "; " + x.f("demand_dynamic", x.n(*L.demand.dynamic_force / kN, 2), L.demand.dynamic_runs);
  if (L.demand.dynamic_breaks > 0)
    dem += "; " + x.f("demand_broken", L.demand.dynamic_breaks, L.demand.dynamic_runs,
                      x.component(L.demand.dynamic_component));
  x.c.d.add_paragraph(dem + ".");
  checks_table(x, L);
  required_table(x, L);
}

void states_table(const TieText& x, const TieInterventionResult& t, bool explain = true) {
  const KinematicResult& b = t.before.candidates[t.before.governing].result;
  const KinematicResult& a = t.after.candidates[t.after.governing].result;
  auto dk = [&](const KinematicResult& k, double v) { return k.curve_complete() ? x.num(v, 4) : numeric_cell("—"); };
  std::vector<std::vector<Cell>> rows;
  auto row = [&](const std::string& label, Cell u, Cell v) { rows.push_back({Cell(label), u, v}); };
  row("α0", x.num(b.alpha0, 4), x.num(a.alpha0, 4));
  row("a0* (m/s²)", x.num(b.a0_star, 4), x.num(a.a0_star, 4));
  row("d0* (m)", dk(b, b.d0_star), dk(a, a.d0_star));
  // A state without ties has no such displacement.
  row(x.t("d_tie"), t.levels_before.empty() ? numeric_cell("—") : dk(b, b.d_star_tie_limit),
      t.levels.empty() ? numeric_cell("—") : dk(a, a.d_star_tie_limit));
  row(x.t("d_cap"), t.levels_before.empty() ? numeric_cell("—") : dk(b, b.d_star_tie_cap),
      t.levels.empty() ? numeric_cell("—") : dk(a, a.d_star_tie_cap));
  row("d_SLV (m)", dk(b, b.d_SLV), dk(a, a.d_SLV));
  row("d_SLC (m)", dk(b, b.d_SLC), dk(a, a.d_SLC));
  row(x.t("zeta"), x.num(t.zetaE_before, 3), x.num(t.zetaE_after, 3));
  row(x.t("all_checks"), x.ok(t.passes_before), x.ok(t.passes_after));
  const CandidateResult& cb = t.before.candidates[t.before.governing];
  const CandidateResult& ca = t.after.candidates[t.after.governing];
  for (const CheckRow& r : cb.checks) {
    const CheckRow* r2 = nullptr;
    for (const CheckRow& y : ca.checks)
      if (y.code == r.code && y.limit_state == r.limit_state && y.kind == r.kind && y.location == r.location) r2 = &y;
    auto dc = [&](const CheckRow* y) { return y ? x.c.dc_cell(*y) : numeric_cell("—"); };
    row(r.code + " " + r.limit_state + " " + x.t("kind." + r.kind) + " " + x.t("where." + r.location) + " D/C", dc(&r),
        dc(r2));
  }
  x.c.d.add_cell_table({Cell(""), numeric_cell(x.t("before")), numeric_cell(x.t("after"))}, rows, x.t("before_after"));
  if (explain) x.c.d.add_paragraph(x.t("capacity_note"));
}

Cell run_outcome(const TieText& x, const TieDynamicRun& r) {
  if (r.failed) {
    Cell c(x.t("run_failed"));
    c.tone = Tone::fail;
    return c;
  }
  for (const TieLevelRun& l : r.levels)
    if (l.broken) {
      Cell c(x.f("run_broken", l.name, x.component(l.component), x.n(l.t_broken, 2)));
      c.tone = Tone::fail;
      return c;
    }
  if (r.yielded) return Cell(x.f("run_yielded", x.n(r.plastic_elongation * 1e3, 1)));
  return Cell(x.t("run_elastic"));
}

// The runs of the design state, one row each (a building's wall member: in the tabulati).
void dynamic_runs_table(const TieText& x, const TieDynamicResult& d) {
  std::vector<std::vector<Cell>> rows;
  for (const TieDynamicRun& r : d.runs)
    rows.push_back({numeric_cell(std::to_string(r.record + 1)), x.num(r.e, 3), Cell(x.t(r.reversed ? "reversed" : "normal")),
                    x.num(r.theta_max, 5), x.num(r.max_force / kN, 2), run_outcome(x, r)});
  x.c.d.add_cell_table({numeric_cell(x.t("dyn_record")), numeric_cell(x.t("dyn_e")), Cell(x.t("dyn_polarity")),
                        numeric_cell("θ_max (rad)"), numeric_cell(x.t("dyn_fmax")), Cell(x.t("dyn_outcome"))},
                       rows, x.t("dyn_runs_intro"));
}

// `runs_here` false: the table of every run is in the tabulati (a building's
// mechanism whose wall's ties are described once; issue 36: length).
void dynamics(const TieText& x, const TieInterventionResult& t, bool runs_here = true, bool explain = true) {
  const TieDynamicResult& d = t.dynamics;
  x.c.d.add_heading(x.t("dyn_title"), 3, false);
  if (!d.applies) {
    x.c.d.add_paragraph(x.t("dyn_not"));
    return;
  }
  if (explain) x.c.d.add_paragraph(x.t(t.intervention ? "dyn_intro" : "dyn_intro_existing"));
  // One row per restitution and state (the stato di progetto's only with an
  // intervention); d* of a state with a collapse is unbounded: "∞" (issue 28).
  std::vector<std::vector<Cell>> rows;
  auto count = [&](int v) { return numeric_cell(std::to_string(v)); };
  for (const TieDynamicSummary& s : d.summaries)
    for (bool after : {false, true}) {
      if (after && !t.intervention) continue;
      rows.push_back({x.num(s.e, 3), Cell(x.t(after ? "state_after" : "state_before")), count(s.records),
                      count(after ? s.overturned_after : s.overturned_before),
                      x.num(after ? s.d_demand_after : s.d_demand_before, 4),
                      x.num(after ? s.d_SLV_after : s.d_SLV_before, 4), count(after ? s.yielded_after : s.yielded_before),
                      count(after ? s.broken_after : s.broken_before),
                      x.ok(after ? s.satisfied_after : s.satisfied_before)});
    }
  x.c.d.add_cell_table({numeric_cell("e"), Cell(x.t("dyn_state")), numeric_cell("N"), numeric_cell(x.t("dyn_over")),
                        numeric_cell(x.t("dyn_d")), numeric_cell("d_SLV (m)"), numeric_cell(x.t("dyn_yield")),
                        numeric_cell(x.t("dyn_broken")), Cell(x.t("dyn_verdict"))},
                       rows, x.t("dyn_title"));
  if (runs_here) {
    dynamic_runs_table(x, d);
  } else if (!d.runs.empty()) {
    x.c.d.add_paragraph(Inline{reference(x.t("runs_in_tab"), x.c.here("ties"), tabulati_key)}, "note");
  }
}

void detailing(const TieText& x, const std::vector<TieLevelResult>& levels) {
  x.c.d.add_heading(x.t("det_title"), 3, false);
  std::vector<Inline> items;
  for (const TieLevelResult& L : levels) {
    const Tie& tie = L.tie;
    const tie_catalogue::Thread* th = tie_catalogue::find_thread(tie.rod.thread_diameter);
    std::string item = x.f("det_anchor", anchor_text(x, tie), x.t(tie.anchor.type == AnchorType::Plate ? "det_plate" : "det_bar"));
    if (th)
      item += " " + x.f("det_nut", x.n(th->d * 1e3, 0), x.n(th->s * 1e3, 0), x.n(th->m * 1e3, 1),
                        x.n(th->dw * 1e3, 0) + " × " + x.n(th->hw * 1e3, 1));
    item += " " + x.t("det_ends." + std::string(to_string(tie.rod.ends)));
    item += " " + x.f("det_layout", layout_text(x, tie));
    if (tie.pretension > 0.0)
      item += " " + x.f("det_pretension", x.n(tie.pretension / kN, 1),
                        x.n(100.0 * tie.pretension / L.resistance.design, 0));
    else
      item += " " + x.t("det_pretension_none");
    const Span who(tie.name, true, Tone::plain, "", true);
    items.push_back({who, Span{" (" + x.t(tie.existing ? "existing" : "new") + "): " + item}});
  }
  for (const char* k : {"det_far_end", "det_corrosion", "det_execution"}) items.push_back({Span{x.t(k)}});
  x.c.d.add_list(items);
}

// The punched wedge of the tie that governs the punching, drawn in the wall's
// elevation against the crown, the openings and the neighbours' strips (issue
// 37): the wall (grey), the openings (white), the strip the tie owns between
// the dash-dot lines, the whole wedge at the inner face (dashed), its part in
// masonry (shaded), the anchor (dark), the crown (thick line, labelled).
std::string wedge_svg(const TieText& x, const Tie& tie, const TieResistance& r) {
  using detail::coord;
  const AnchorWedge& W = r.wedge;
  const double w = tie.anchor.width(), h = tie.anchor.height(), s = tie.masonry.thickness;
  const double xc = W.x, zc = tie.point.y();
  const TieLayout& L = tie.layout;
  const double m = 0.25 * (w + 2 * s);
  double x0 = xc - w / 2 - s - m, x1 = xc + w / 2 + s + m;
  double z0 = zc - h / 2 - s - m, z1 = zc + h / 2 + s + m;
  if (std::isfinite(L.crown)) z1 = std::min(z1, L.crown + m);
  const double Wd = 520.0, Hd = 340.0, pad = 30.0;
  const double sc = std::min((Wd - 2 * pad) / (x1 - x0), (Hd - 2 * pad) / (z1 - z0));
  const double left = 0.5 * (Wd - (x1 - x0) * sc);  // the view centred
  auto X = [&](double v) { return left + (v - x0) * sc; };
  auto Z = [&](double v) { return Hd - pad - (v - z0) * sc; };
  std::string o = "<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 " + coord(Wd) + " " + coord(Hd) +
                  "\" width=\"" + coord(Wd) + "\" height=\"" + coord(Hd) + "\" font-family=\"DejaVu Sans, sans-serif\">\n";
  auto rect = [&](double a0, double b0, double a1, double b1, const std::string& style) {
    a0 = std::max(a0, x0), a1 = std::min(a1, x1), b0 = std::max(b0, z0), b1 = std::min(b1, z1);
    if (!(a1 > a0) || !(b1 > b0)) return;
    o += "<rect x=\"" + coord(X(a0)) + "\" y=\"" + coord(Z(b1)) + "\" width=\"" + coord((a1 - a0) * sc) + "\" height=\"" +
         coord((b1 - b0) * sc) + "\" " + style + "/>\n";
  };
  const double top = std::isfinite(L.crown) ? L.crown : z1;
  rect(0.0, L.base, L.wall_length, top, "fill=\"#e6e1d8\" stroke=\"none\"");
  for (const WallOpening& op : L.openings) rect(op.x0, op.z0, op.x1, op.z1, "fill=\"#ffffff\" stroke=\"#888\"");
  // The wedge at the inner face: its part in masonry shaded, the whole dashed.
  const double wa = xc - w / 2 - s, wb = xc + w / 2 + s, za = zc - h / 2 - s, zb = zc + h / 2 + s;
  rect(std::max(wa, W.x_lo), std::max(za, L.base), std::min(wb, W.x_hi), std::min(zb, top),
       "fill=\"#c0504d\" fill-opacity=\"0.35\" stroke=\"none\"");
  for (const WallOpening& op : L.openings)
    rect(std::max(op.x0, wa), std::max(op.z0, za), std::min(op.x1, wb), std::min(op.z1, zb), "fill=\"#ffffff\" stroke=\"none\"");
  o += "<rect x=\"" + coord(X(wa)) + "\" y=\"" + coord(Z(zb)) + "\" width=\"" + coord((wb - wa) * sc) + "\" height=\"" +
       coord((zb - za) * sc) + "\" fill=\"none\" stroke=\"#c0504d\" stroke-dasharray=\"6 4\"/>\n";
  rect(xc - w / 2, zc - h / 2, xc + w / 2, zc + h / 2, "fill=\"#333\" stroke=\"none\"");
  for (double xl : {W.x_lo, W.x_hi})
    if (xl > x0 && xl < x1)
      o += "<line x1=\"" + coord(X(xl)) + "\" y1=\"" + coord(pad) + "\" x2=\"" + coord(X(xl)) + "\" y2=\"" +
           coord(Hd - pad) + "\" stroke=\"#555\" stroke-dasharray=\"8 3 2 3\"/>\n";
  if (std::isfinite(L.crown) && L.crown < z1) {
    o += "<line x1=\"" + coord(X(std::max(x0, 0.0))) + "\" y1=\"" + coord(Z(L.crown)) + "\" x2=\"" +
         coord(X(std::min(x1, L.wall_length))) + "\" y2=\"" + coord(Z(L.crown)) +
         "\" stroke=\"#000\" stroke-width=\"2.5\"/>\n";
    o += "<text x=\"" + coord(X(std::max(x0, 0.0)) + 4) + "\" y=\"" + coord(Z(L.crown) - 5) + "\" font-size=\"11\">" +
         detail::svg_escape(x.t("wedge_crown") + " z = " + x.n(L.crown, 2) + " m") + "</text>\n";
    // The distance from the anchor's centre to the crown.
    const double xd = xc + w / 2 + 0.15 * s;
    o += "<line x1=\"" + coord(X(xd)) + "\" y1=\"" + coord(Z(zc)) + "\" x2=\"" + coord(X(xd)) + "\" y2=\"" +
         coord(Z(L.crown)) + "\" stroke=\"#000\" marker-start=\"none\"/>\n";
    o += "<text x=\"" + coord(X(xd) + 4) + "\" y=\"" + coord(0.5 * (Z(zc) + Z(L.crown)) + 4) + "\" font-size=\"11\">" +
         detail::svg_escape(x.n(L.crown - zc, 2) + " m") + "</text>\n";
  }
  o += "<text x=\"" + coord(left) + "\" y=\"" + coord(Hd - 8) + "\" font-size=\"11\">" +
       detail::svg_escape("x = " + x.n(xc, 2) + " m, z = " + x.n(zc, 2) + " m, s = " + x.n(s, 2) + " m") + "</text>\n";
  return o + "</svg>\n";
}

void wedge_figure(const TieText& x, const TieLevelResult& L, const std::string& id) {
  const TieResistance& r = L.resistance;
  x.c.d.add_svg(wedge_svg(x, L.tie, r),
                x.f("wedge_caption", L.tie.name + ", " + std::to_string(r.wedge.tie + 1) + "/" +
                                         std::to_string(L.tie.layout.count),
                    x.n(r.wedge.area, 3), x.n(r.wedge.full_area, 3)),
                id);
}

std::string change_text(const TieText& x, const TieChange& ch) {
  if (!ch.after) return x.t("change.removed");
  const Tie& a = *ch.after;
  if (ch.kind == "anchor") return x.f("change.anchor", anchor_text(x, a));
  return x.f("change.rod", rod_text(x, a) + ", " + ends_text(x, a), anchor_text(x, a));
}

void changes_block(const TieText& x, const TieInterventionResult& t) {
  if (!t.changes.empty()) {
    x.c.d.add_heading(x.t("change_title"), 3, false);
    x.c.d.add_paragraph(x.t("change_intro"));
    std::vector<Inline> items;
    for (const TieChange& ch : t.changes)
      items.push_back({Span(ch.level, true, Tone::plain, "", true), Span{": " + change_text(x, ch)}});
    x.c.d.add_list(items);
  }
  if (!t.designed && !t.failing_existing.empty()) {
    std::string n;
    for (const std::string& f : t.failing_existing) n += (n.empty() ? "" : ", ") + f;
    x.c.d.add_paragraph(Inline{Span{x.f("failing_existing", n), true}});
  }
}

// The ties on the mechanism, in the stato di progetto when there is one.
void tie_drawing(const TieText& x, const TieInterventionResult& t, const std::string& id,
                 const std::string& caption = {}) {
  x.c.d.add_svg(drawing(x, t.intervention ? t.case_after : t.case_before, t.intervention ? t.after : t.before, t.levels),
                caption.empty() ? x.t("drawing") : caption, id);
}

using WallMembers = std::vector<std::pair<std::string, const TieInterventionResult*>>;

// One level's check rows over the mechanisms it restrains, in one state: each
// row the mechanism whose D/C is the largest (a failing row first), with its name.
std::vector<std::pair<TieCheckRow, std::string>> wall_envelope(const WallMembers& members, const std::string& level,
                                                                bool after) {
  std::vector<std::pair<TieCheckRow, std::string>> env;
  for (const auto& [n, r] : members)
    for (const TieLevelResult& l : after ? r->levels : r->levels_before) {
      if (l.tie.name != level || !(l.count > 0.0)) continue;
      for (const TieCheckRow& row : l.checks) {
        auto it = std::find_if(env.begin(), env.end(), [&](const auto& e) { return e.first.check == row.check; });
        const double key = row.unit == "analyses" ? row.demand : row.dc;
        if (it == env.end()) env.push_back({row, n});
        else if (!row.satisfied && it->first.satisfied) *it = {row, n};
        else if (row.satisfied == it->first.satisfied &&
                 key > (it->first.unit == "analyses" ? it->first.demand : it->first.dc))
          *it = {row, n};
      }
    }
  return env;
}

// The levels of the wall in each state (the stato di fatto's, then the stato
// di progetto's with an intervention), each once, in the members' order.
std::vector<std::pair<std::string, bool>> wall_states(const WallMembers& members) {
  std::vector<std::pair<std::string, bool>> out;
  for (bool after : {false, true})
    for (const auto& [n0, r0] : members) {
      if (after && !r0->intervention) continue;
      for (const TieLevelResult& l0 : after ? r0->levels : r0->levels_before) {
        if (!(l0.count > 0.0)) continue;
        const std::pair<std::string, bool> k{l0.tie.name, after};
        if (std::find(out.begin(), out.end(), k) == out.end()) out.push_back(k);
      }
    }
  return out;
}

// Each level's checks in every mechanism it restrains: one table per level and state.
void wall_check_tables(const TieText& x, const WallMembers& members) {
  for (const auto& [level, after] : wall_states(members)) {
    x.c.d.add_heading(level + " (" + x.t(after ? "state_after" : "state_before") + ")", 4, false);
    std::vector<std::vector<Cell>> rows;
    for (const auto& [row, who] : wall_envelope(members, level, after)) {
      std::vector<Cell> cells = check_row_cells(x, row);
      cells.insert(cells.begin() + 2, Cell(who));
      rows.push_back(std::move(cells));
    }
    x.c.d.add_cell_table({Cell(x.t("check")), Cell(x.t("clause")), Cell(x.t("wall_governing")),
                          numeric_cell(x.t("demand")), numeric_cell(x.t("capacity")), Cell(x.t("unit")),
                          numeric_cell("D/C"), Cell(x.t("outcome"))},
                         rows, x.t("checks_title") + " — " + level);
  }
}

// The body's summary of those tables (a building's relazione): per level and
// state the check with the largest D/C (a failing one first: the worst of the
// table it summarises), the number of checks and how many fail.
void wall_check_summary(const TieText& x, const WallMembers& members) {
  std::vector<std::vector<Cell>> rows;
  for (const auto& [level, after] : wall_states(members)) {
    const auto env = wall_envelope(members, level, after);
    if (env.empty()) continue;
    // A failing count of broken analyses or an unreachable force is printed ∞ (check_row_cells).
    auto dc_of = [](const TieCheckRow& r) {
      return !r.satisfied && (r.unit == "analyses" || !r.reachable) ? std::numeric_limits<double>::infinity() : r.dc;
    };
    const std::pair<TieCheckRow, std::string>* worst = &env.front();
    int failing = 0;
    for (const auto& e : env) {
      if (!e.first.satisfied) ++failing;
      const bool worse = (!e.first.satisfied && worst->first.satisfied) ||
                         (e.first.satisfied == worst->first.satisfied && dc_of(e.first) > dc_of(worst->first));
      if (worse) worst = &e;
    }
    std::vector<Cell> cells = check_row_cells(x, worst->first);
    Cell name(level);
    name.user = true;
    Cell count = numeric_cell(std::to_string(failing) + " / " + std::to_string(env.size()));
    if (failing) count.tone = Tone::fail;
    // level, state, governing check and its clause, mechanism, D/C, outcome, failing / checks
    rows.push_back({name, Cell(x.t(after ? "state_after" : "state_before")), cells[0], Cell(worst->second),
                    cells[cells.size() - 2], cells.back(), count});
  }
  x.c.d.add_cell_table({Cell(x.t("level")), Cell(x.t("dyn_state")), Cell(x.t("summary_worst")),
                        Cell(x.t("wall_governing")), numeric_cell("D/C"), Cell(x.t("outcome")),
                        numeric_cell(x.t("summary_failing"))},
                       rows, x.t("summary_cap"));
}

}  // namespace

void add_tie_section(Ctx& c, const TieInterventionResult& t) {
  const TieText x{c};
  const bool wall_member = t.wall_members.size() > 1;
  // A mechanism of a wall whose ties are described once in the wall's section
  // (issue 37): the states and the design's regime are said there.
  if (!wall_member) {
    c.d.add_paragraph(x.t(t.designed ? "intro_design" : t.intervention ? "intro_given" : "intro_existing"));
    if (t.designed && t.found) c.d.add_paragraph(x.t(t.regime == "ductile" ? "regime_ductile" : "regime_elastic"));
  }
  if (t.designed && !t.found) c.d.add_paragraph(Inline{Span{x.t("not_found"), true}});
  // A building's wall member: its drawing in the tabulati (the wall's section
  // draws the ties once; issue 36: length).
  if (!(wall_member && c.building && c.tabulati)) tie_drawing(x, t, "ties-drawing");
  if (wall_member) {
    // Here the mechanism with them, in both states.
    c.d.add_paragraph(x.f("wall_member", [&] {
      std::string m;
      for (const std::string& n : t.wall_members) m += (m.empty() ? "" : ", ") + n;
      return m;
    }()));
    // A building's wall member: how the states and the tied analyses are
    // computed is said once in the wall's section (issue 36: length).
    const bool brief = c.building && c.tabulati;
    c.d.add_heading(x.t("before_after"), 3, false);
    states_table(x, t, !brief);
    dynamics(x, t, !brief, !brief);
    return;
  }
  c.d.add_heading(x.t("levels_title"), 3, false);
  levels_table(x, t.levels);
  changes_block(x, t);
  c.d.add_heading(x.t("wedge_title"), 3, false);
  for (std::size_t i = 0; i < t.levels.size(); ++i) wedge_figure(x, t.levels[i], "ties-wedge-" + std::to_string(i + 1));
  // A building's mechanism (issue 36: length): the formulas, the dynamic check
  // after the intervention and the detailing are in the tabulati (add_tab_ties).
  const bool brief = c.building && c.tabulati;
  if (brief) {
    c.d.add_paragraph(Inline{reference(x.t("in_tab"), c.here("ties"), tabulati_key)}, "note");
  } else {
    c.d.add_heading(x.t("formulas_title"), 3, false);
    formulas(x);
  }
  c.d.add_heading(x.t("checks_title"), 3, false);
  for (const TieLevelResult& L : t.levels_before) level_block(x, L, x.t("state_before"));
  if (t.intervention)
    for (const TieLevelResult& L : t.levels) level_block(x, L, x.t("state_after"));
  c.d.add_heading(x.t("before_after"), 3, false);
  states_table(x, t);
  if (brief) return;
  dynamics(x, t);
  detailing(x, t.levels);
}


// Issue 37: the ties of a wall, once: each level with the mechanisms it
// restrains, its wedge, its checks in every mechanism (the governing one per
// row), the changes to existing ties, the formulas and the detailing.
void add_wall_tie_section(Ctx& c, const std::string& wall,
                          const std::vector<std::pair<std::string, const TieInterventionResult*>>& members,
                          DocumentBuilder* tabulati) {
  if (members.empty()) return;
  const TieText x{c};
  const TieInterventionResult& first = *members.front().second;
  std::string names;
  for (const auto& [n, r] : members) names += (names.empty() ? "" : ", ") + n;
  c.d.add_heading(x.f("wall_title", wall), 2, false);
  c.d.add_paragraph(x.f("wall_intro", names));
  c.d.add_paragraph(x.t(first.designed ? "intro_design" : first.intervention ? "intro_given" : "intro_existing"));
  if (first.designed && first.found) c.d.add_paragraph(x.t(first.regime == "ductile" ? "regime_ductile" : "regime_elastic"));
  if (first.designed && !first.found) c.d.add_paragraph(Inline{Span{x.t("not_found"), true}});
  if (tabulati) {
    // Said here once for every mechanism of the wall (their sections in a building do not repeat it).
    c.d.add_paragraph(x.t("capacity_note"));
    if (first.dynamics.applies) c.d.add_paragraph(x.t(first.intervention ? "dyn_intro_wall" : "dyn_intro_existing_wall"));
  }
  // Every level of the wall once (the stato di progetto's, else the stato di
  // fatto's), with the mechanisms it acts on.
  std::vector<TieLevelResult> levels;
  std::map<std::string, std::string> restrains;
  for (const auto& [n, r] : members)
    for (const TieLevelResult& l : r->intervention ? r->levels : r->levels_before) {
      if (!(l.count > 0.0)) continue;
      std::string& who = restrains[l.tie.name];
      who += (who.empty() ? "" : ", ") + n;
      bool seen = false;
      for (const TieLevelResult& v : levels) seen = seen || v.tie.name == l.tie.name;
      if (!seen) levels.push_back(l);
    }
  c.d.add_heading(x.t("levels_title"), 3, false);
  levels_table(x, levels);
  {
    std::vector<std::vector<Cell>> rows;
    for (const TieLevelResult& l : levels) {
      Cell name(l.tie.name);
      name.user = true;
      rows.push_back({name, Cell(restrains[l.tie.name])});
    }
    c.d.add_cell_table({Cell(x.t("level")), Cell(x.t("wall_restrains"))}, rows, x.t("wall_restrains"));
  }
  // The wall's ties drawn once on its first mechanism (each mechanism's
  // drawing: in the tabulati of a building).
  if (tabulati) tie_drawing(x, first, "ties-drawing", x.f("wall_drawing", members.front().first));
  changes_block(x, first);
  if (!tabulati) {
    c.d.add_heading(x.t("wedge_title"), 3, false);
    for (std::size_t i = 0; i < levels.size(); ++i) wedge_figure(x, levels[i], "wall-wedge-" + std::to_string(i + 1));
    c.d.add_heading(x.t("formulas_title"), 3, false);
    formulas(x);
    c.d.add_heading(x.t("checks_title"), 3, false);
    wall_check_tables(x, members);
    detailing(x, levels);
    return;
  }
  // With the tabulati (a building's relazione, issue 36: length): in the body
  // each level's governing check per state; the full tables, the punched
  // wedges, the formulas and the detailing there, under the same prefix.
  c.d.add_heading(x.t("checks_title"), 3, false);
  wall_check_summary(x, members);
  c.d.add_paragraph(Inline{reference(x.t("wall_in_tab"), c.here("ties"), tabulati_key)}, "note");
  Ctx tc{c.a, c.o, c.L, *tabulati, c.readings, true, true};
  const TieText tx{tc};
  tabulati->add_heading(x.f("wall_title", wall), 2, false, true, "ties");
  tabulati->add_heading(x.t("checks_title"), 3, false);
  wall_check_tables(tx, members);
  tabulati->add_heading(x.t("wedge_title"), 3, false);
  for (std::size_t i = 0; i < levels.size(); ++i) wedge_figure(tx, levels[i], "wall-wedge-" + std::to_string(i + 1));
  tabulati->add_heading(x.t("formulas_title"), 3, false);
  formulas(tx);
  detailing(tx, levels);
}

void add_tab_ties(Ctx& c) {
  if (!c.o.ties) return;
  const TieText x{c};
  // A wall's ties shared by several mechanisms are described once in the
  // wall's section (issue 37); here only this mechanism's tied analyses.
  if (c.o.ties->wall_members.size() > 1) {
    const TieDynamicResult& d = c.o.ties->dynamics;
    c.d.add_heading(x.t("title"), 2, false, true, "ties");
    tie_drawing(x, *c.o.ties, "ties-drawing");
    if (!d.applies || d.runs.empty()) return;
    c.d.add_heading(x.t("dyn_title"), 3, false);
    dynamic_runs_table(x, d);
    return;
  }
  c.d.add_heading(x.t("title"), 2, false, true, "ties");
  c.d.add_heading(x.t("formulas_title"), 3, false);
  formulas(x);
  dynamics(x, *c.o.ties);
  detailing(x, c.o.ties->levels);
}

}  // namespace relazione
}  // namespace assess
