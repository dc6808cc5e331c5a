// relazione_mechanism.cpp: the formulas, written once with their clauses, and
// the mechanism developed in the body (issue 28, items 2 and 5): each candidate
// that governs a method of the verdict, with its bodies, drawing, virtual-work
// table, kinematic quantities (each with the numbers it is computed from),
// capacity curve and ADRS plot; then the table of every candidate examined.
#include "report/relazione_context.hpp"

#include "assess/report/relazione.hpp"

#include "report/report_heading.hpp"
#include "report/text_format.hpp"

#include "assess/kinematic/code_rules.hpp"
#include "assess/report/mechanism_drawing.hpp"
#include "assess/report/plot.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <numeric>

namespace assess::relazione {

using detail::code_name;

namespace {

constexpr double pi = units::pi;
constexpr double g = units::g;

bool any_at_height(const FacadeAssessment& a) {
  for (const CandidateResult& cr : a.kinematic.candidates)
    if (cr.Z > 0.0) return true;
  return false;
}

// The chain's rigid bodies: blocks joined by two hinges at distinct points
// move as one (the gable's integration slices, the corner's pillar and arms).
std::vector<std::vector<int>> rigid_bodies(const Chain& chain) {
  const std::size_t n = chain.blocks().size();
  std::vector<std::size_t> parent(n);
  std::iota(parent.begin(), parent.end(), std::size_t(0));
  const auto root = [&](std::size_t i) {
    while (parent[i] != i) i = parent[i] = parent[parent[i]];
    return i;
  };
  const auto& cons = chain.constraints();
  for (std::size_t i = 0; i < cons.size(); ++i) {
    if (cons[i].type != ConstraintType::Hinge) continue;
    for (std::size_t j = i + 1; j < cons.size(); ++j) {
      if (cons[j].type != ConstraintType::Hinge) continue;
      const bool same_pair = (cons[i].block == cons[j].block && cons[i].other == cons[j].other) ||
                             (cons[i].block == cons[j].other && cons[i].other == cons[j].block);
      if (same_pair && (cons[i].point - cons[j].point).norm() > 1e-9)
        parent[root(std::size_t(cons[i].block))] = root(std::size_t(cons[i].other));
    }
  }
  std::vector<std::vector<int>> bodies;
  std::vector<int> index(n, -1);
  for (std::size_t b = 0; b < n; ++b) {
    const std::size_t r = root(b);
    if (index[r] < 0) {
      index[r] = int(bodies.size());
      bodies.emplace_back();
    }
    bodies[std::size_t(index[r])].push_back(int(b));
  }
  return bodies;
}

// Geometry of the bodies: one row per body (a body of several blocks is one
// body: its integration slices are internal), with its extent, section area,
// out-of-plane length, volume, weight and centroid.
void add_bodies(Ctx& c, const Chain& chain) {
  std::vector<std::vector<Cell>> rows;
  const auto bodies = rigid_bodies(chain);
  for (std::size_t k = 0; k < bodies.size(); ++k) {
    double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300, A = 0.0, V = 0.0, W = 0.0, xg = 0.0, zg = 0.0;
    double L0 = -1.0;
    bool same_L = true;
    for (int b : bodies[k]) {
      const Block& bl = chain.blocks()[std::size_t(b)];
      for (const Eigen::Vector2d& v : bl.polygon) {
        x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
        z0 = std::min(z0, v.y()), z1 = std::max(z1, v.y());
      }
      const double a = chain.area(b), vol = a * bl.length, w = bl.unit_weight * vol;
      A += a;
      V += vol;
      W += w;
      xg += w * chain.centroid(b).x();
      zg += w * chain.centroid(b).y();
      if (L0 < 0.0) L0 = bl.length;
      same_L = same_L && std::abs(bl.length - L0) < 1e-9;
    }
    if (W > 0.0) xg /= W, zg /= W;
    std::string name = c.t("data.body") + " " + std::to_string(k + 1);
    if (bodies[k].size() > 1) name += " (" + msgf(c.L, "data.slices", bodies[k].size()) + ")";
    else if (!chain.blocks()[std::size_t(bodies[k].front())].name.empty())
      name += " (" + c.loc("P " + chain.blocks()[std::size_t(bodies[k].front())].name).substr(2) + ")";
    rows.push_back({Cell(name), c.num(z0, 3), c.num(z1, 3), c.num(x1 - x0, 3), c.num(A, 4),
                    same_L ? c.num(L0, 3) : Cell(c.t("data.variable_length")), c.num(V, 4),
                    c.num(W / units::kN, 2), c.num(xg, 3), c.num(zg, 3)});
  }
  c.d.add_cell_table({Cell(c.t("data.body_col")), numeric_cell("z₀ (m)"), numeric_cell("z₁ (m)"), numeric_cell(c.t("data.thickness_col")),
                      numeric_cell(c.t("data.area_col")), numeric_cell("L (m)"), numeric_cell(c.t("data.volume_col")), numeric_cell("W (kN)"), numeric_cell("x_G (m)"),
                      numeric_cell("z_G (m)")},
                     rows, c.t("data.bodies_cap"));
}

// The virtual-work table (C8A.4.1 / C8.7.1.1): every load with its virtual
// displacements; the sums of the columns add up: the seismic weights' sum is
// given apart from the loads without seismic mass.
// A load's or block's name in the report's language: the catalogue's names
// through the phrase table, a bare "tie" or "thrust" by its kind.
std::string load_name(const Ctx& c, const Load& l) {
  if (l.name == "tie") return c.t("load.tie");
  if (l.name == "thrust") return c.t("load.force");
  return c.loc(l.name);
}

void virtual_work_table(Ctx& c, const Chain& chain, const KinematicResult& k) {
  std::vector<std::vector<Cell>> rows;
  double W_other = 0.0;
  // The self weights of a body made of several blocks (the gable's
  // integration slices) in one row: the sums of its blocks, at its centroid
  // (a rigid body's virtual displacement is linear in the position).
  const auto bodies = rigid_bodies(chain);
  std::vector<int> body_of(chain.blocks().size(), -1);
  for (std::size_t b = 0; b < bodies.size(); ++b)
    if (bodies[b].size() > 1)
      for (int i : bodies[b]) body_of[std::size_t(i)] = int(b);
  std::vector<LoadWork> merged(bodies.size());
  std::vector<bool> has(bodies.size(), false);
  auto row_of = [&](const LoadWork& w, const std::string& name) {
    const bool weight = w.load.type == LoadType::Weight || w.load.type == LoadType::SelfWeight;
    const double W = (weight ? w.load.weight : w.load.force.norm()) / units::kN;
    const bool seismic = weight && w.load.seismic;
    if (weight && !seismic) W_other += W;
    // A block's weight distributed over its area (issue 36): W·δx² is W δx_G² plus
    // the term of its rotation, printed beside it so that the row can be redone.
    Cell wdx2 = c.num(w.W_dx2 / units::kN, 3);
    const double lumped = weight && seismic ? W * w.dx * w.dx : 0.0;
    if (w.load.type == LoadType::SelfWeight && seismic && std::abs(w.W_dx2 / units::kN - lumped) > 5e-4)
      wdx2.note = msgf(c.L, "vw.distributed", c.n(lumped, 3), c.n(w.W_dx2 / units::kN - lumped, 3));
    rows.push_back({Cell(name), Cell(c.t("load." + to_string(w.load.type))), Cell(c.t(seismic ? "vw.yes" : "vw.no")),
                    c.num(w.load.point.x(), 3), c.num(w.load.point.y(), 3), c.num(W, 2), c.num(w.dx, 4),
                    c.num(w.dz, 4), c.num(w.W_dx / units::kN, 3), wdx2, c.num(w.work / units::kN, 3)});
  };
  for (const LoadWork& w : k.loads) {
    const int b = w.load.type == LoadType::SelfWeight && w.load.block >= 0 ? body_of[std::size_t(w.load.block)] : -1;
    if (b < 0) {
      row_of(w, load_name(c, w.load));
      continue;
    }
    LoadWork& m = merged[std::size_t(b)];
    if (!has[std::size_t(b)]) {
      m = w;
      m.load.weight = 0.0;
      m.load.point.setZero();
      m.dx = m.dz = m.W_dx = m.W_dx2 = m.work = 0.0;
      has[std::size_t(b)] = true;
    }
    m.load.weight += w.load.weight;
    m.load.point += w.load.weight * w.load.point;
    m.dx += w.load.weight * w.dx;
    m.dz += w.load.weight * w.dz;
    m.W_dx += w.W_dx;
    m.W_dx2 += w.W_dx2;
    m.work += w.work;
  }
  for (std::size_t b = 0; b < bodies.size(); ++b) {
    if (!has[b]) continue;
    LoadWork& m = merged[b];
    if (m.load.weight > 0.0) {
      m.load.point /= m.load.weight;
      m.dx /= m.load.weight;
      m.dz /= m.load.weight;
    }
    row_of(m, "P " + c.t("data.body") + " " + std::to_string(b + 1) + " (" + msgf(c.L, "data.slices", bodies[b].size()) + ")");
  }
  auto sum = [&](double v, int prec) {
    Cell x = c.num(v, prec);
    x.highlight = true;
    return x;
  };
  Cell blank;
  blank.highlight = true;
  Cell label(c.t("vw.sum_seismic"));
  label.highlight = true;
  rows.push_back({label, blank, blank, blank, blank, sum(k.sum_W / units::kN, 2), blank, blank,
                  sum(k.sum_W_dx / units::kN, 3), sum(k.sum_W_dx2 / units::kN, 3), sum(k.work_other / units::kN, 3)});
  std::string cap = c.t(chain.plan() ? "mech.vw_cap_plan" : "mech.vw_cap");
  if (W_other > 0.0) cap += " " + msgf(c.L, "vw.non_seismic", c.n(W_other, 2));
  c.d.add_cell_table({Cell(c.t("mech.load")), Cell(c.t("mech.kind")), Cell(c.t("vw.seismic")), numeric_cell("x (m)"), numeric_cell("z (m)"),
                      numeric_cell("W, F (kN)"), numeric_cell("δx (m)"), numeric_cell("δz (m)"), numeric_cell("W·δx (kN m)"), numeric_cell("W·δx² (kN m²)"),
                      numeric_cell(c.t("mech.work") + " (kN m)")},
                     rows, cap);
}

// The kinematic quantities, each with the numbers it is computed from (the
// formulas of §Formule) so that it can be redone by hand.
void quantities_table(Ctx& c, const KinematicResult& k) {
  const double SW = k.sum_W / units::kN, SWdx = k.sum_W_dx / units::kN, SWdx2 = k.sum_W_dx2 / units::kN;
  const double Lo = k.work_other / units::kN, M = k.M_star / units::tonne;
  std::vector<std::vector<Cell>> rows;
  auto row = [&](const std::string& key, double v, int prec, const std::string& unit, const std::string& how,
                 const std::string& clause) {
    rows.push_back({Cell(c.t(key)), c.num(v, prec), Cell(unit), Cell(how), Cell(clause)});
  };
  row("kin.alpha0", k.alpha0, 4, "–", "−(" + c.n(Lo, 3) + ") / " + c.n(SWdx, 3), "C8.7.1.1; C8A.4.1");
  row("kin.M", M, 3, "t", c.n(SWdx, 3) + "² / (" + c.n(g, 5) + " · " + c.n(SWdx2, 3) + ")", "C8.7.1.2; C8A.4.2");
  row("kin.e", k.e_star, 4, "–", c.n(g, 5) + " · " + c.n(M, 3) + " / " + c.n(SW, 3), "C8.7.1.5; C8A.4.3");
  row("kin.FC", k.FC, 2, "–", c.a.kase.knowledge_level == "given" ? c.t("data.case") : c.a.kase.knowledge_level,
      "C8.5.4, Tab. C8.5.IV");
  row("kin.a0", k.a0_star, 4, "m/s²",
      c.n(k.alpha0, 4) + " · " + c.n(g, 5) + " / (" + c.n(k.e_star, 4) + " · " + c.n(k.FC, 2) + ")",
      "C8.7.1.3; C8A.4.4");
  if (k.curve_complete()) {
    row("kin.dstar_dk", k.d_star_per_dk, 4, "–",
        c.n(SWdx2, 3) + " / (" + c.n(k.dx_k, 4) + " · " + c.n(SWdx, 3) + ")", "C8.7.1.4; C8A.4.5");
    row("kin.dk0", k.dk0, 4, "m", c.t("kin.dk0_how"), "C8.7.1.4; C8A.4.5");
    row("kin.d0", k.d0_star, 4, "m", c.n(k.dk0, 4) + " · " + c.n(k.d_star_per_dk, 4), "C8.7.1.4; C8A.4.5");
    const bool capped_u = k.du_star < code_rules::du_over_d0_2008 * k.d0_star * (1 - 1e-12);
    row("kin.du", k.du_star, 4, "m",
        capped_u ? c.t("kin.capped") : c.n(code_rules::du_over_d0_2008, 2) + " · " + c.n(k.d0_star, 4), "C8A.4.6");
    row("kin.ds", k.ds_star, 4, "m", c.n(code_rules::ds_over_du_2008, 2) + " · " + c.n(k.du_star, 4), "C8A.4.7");
    row("kin.as", k.as_star, 4, "m/s²", c.t("kin.on_curve"), "C8A.4.7");
    row("kin.Ts", k.Ts, 3, "s", "2π √(" + c.n(k.ds_star, 4) + " / " + c.n(k.as_star, 4) + ")", "C8A.4.7");
    const double f = c.a.kase.options.dSLV_over_d0;
    const bool capped_v = k.d_SLV < f * k.d0_star * (1 - 1e-12);
    row("kin.dSLV", k.d_SLV, 4, "m", capped_v ? c.t("kin.capped") : c.n(f, 2) + " · " + c.n(k.d0_star, 4),
        "C8.7.1.2.1.6");
    row("kin.aSLV", k.a_SLV, 4, "m/s²", c.t("kin.on_curve"), "C8.7.1.4");
    row("kin.TSLV", k.T_SLV, 3, "s", c.n(code_rules::T_SLV_factor_of_pi, 2) + " π √(" + c.n(k.d_SLV, 4) + " / " + c.n(k.a_SLV, 4) + ")", "C8.7.1.10");
    const bool capped_c = k.d_SLC < code_rules::dSLC_over_d0_2018 * k.d0_star * (1 - 1e-12);
    row("kin.dSLC", k.d_SLC, 4, "m",
        capped_c ? c.t("kin.capped") : c.n(code_rules::dSLC_over_d0_2018, 2) + " · " + c.n(k.d0_star, 4),
        "C8.7.1.2.1.6");
    row("kin.aSLC", k.a_SLC, 4, "m/s²", c.t("kin.on_curve"), "C8.7.1.4");
    row("kin.TSLC", k.T_SLC, 3, "s", c.n(code_rules::T_SLC_factor_of_pi, 2) + " π √(" + c.n(k.d_SLC, 4) + " / " + c.n(k.a_SLC, 4) + ")", "C8.7.1.11");
  }
  Cell hv(c.t("kin.value"));
  hv.numeric = true;
  c.d.add_cell_table({Cell(c.t("kin.quantity")), hv, Cell(c.t("kin.unit")), Cell(c.t("kin.how")), Cell(c.t("kin.clause"))},
                     rows, c.t("kin.table_cap"));
  if (!k.curve_complete()) c.d.add_paragraph(c.t("kin.incomplete") + ": " + c.loc(k.message));
}

// The capacity curve at a few points (d*, a*), to read a*(d) by hand.
void curve_table(Ctx& c, const KinematicResult& k) {
  if (k.curve.size() < 3) return;
  std::vector<std::vector<Cell>> rows;
  const std::size_t n = k.curve.size(), step = std::max<std::size_t>(1, (n - 1) / 10);
  for (std::size_t i = 0; i < n; i += step) {
    const CapacityPoint& p = k.curve[i];
    rows.push_back({c.num(p.dk, 4), c.num(p.alpha, 5), c.num(p.d_star, 4), c.num(p.a_star, 4)});
    if (i + step >= n && i != n - 1) {
      const CapacityPoint& q = k.curve.back();
      rows.push_back({c.num(q.dk, 4), c.num(q.alpha, 5), c.num(q.d_star, 4), c.num(q.a_star, 4)});
    }
  }
  c.d.add_cell_table({numeric_cell("d_k (m)"), numeric_cell("α (–)"), numeric_cell("d* (m)"), numeric_cell("a* (m/s²)")}, rows, c.t("kin.curve_cap"));
}

double a_on_curve(const KinematicResult& k, double d) {
  for (std::size_t i = 1; i < k.curve.size(); ++i)
    if (d <= k.curve[i].d_star) {
      const CapacityPoint &p0 = k.curve[i - 1], &p1 = k.curve[i];
      const double t = (p1.d_star > p0.d_star) ? (d - p0.d_star) / (p1.d_star - p0.d_star) : 0.0;
      return p0.a_star + t * (p1.a_star - p0.a_star);
    }
  return k.curve.back().a_star;
}

// ADRS: the capacity curve and, for each displacement check of the candidate,
// its demand curve (its damping, floor spectrum at height), the line of the
// period at which the demand is read, the demand and the capacity points.
void adrs_figure(Ctx& c, std::size_t ci, const std::string& id) {
  const CandidateResult& cr = c.candidate(ci);
  const KinematicResult& k = cr.result;
  if (!k.curve_complete() || k.curve.empty()) return;
  Plot p = c.plot();
  p.title = c.t("kin.adrs_title");
  p.x_label = c.t("kin.adrs_x");
  p.y_label = c.t("kin.adrs_y");
  PlotSeries cap = plot_series(c.t("kin.adrs_curve"), PlotSeries::Style::Line);
  for (const CapacityPoint& q : k.curve) cap.x.push_back(q.d_star), cap.y.push_back(q.a_star);
  cap.highlight = true;
  cap.color = "#000000";
  p.series.push_back(cap);
  double d_show = k.d0_star;
  std::vector<const CheckRow*> disp;
  for (const CheckRow& r : cr.checks)
    if (r.kind == "displacement") disp.push_back(&r);
  const std::vector<AdrsDemand>* curves = ci < c.a.curves.candidate_adrs.size() ? &c.a.curves.candidate_adrs[ci] : nullptr;
  // One colour per code edition and limit state across every report (issue 28, item 9).
  auto colour = [](const CheckRow& r) {
    if (r.code == "NTC2008") return "#d9730d";
    return r.limit_state == "SLC" ? "#8a3ea8" : "#1f5fbf";
  };
  for (std::size_t i = 0; curves && i < disp.size() && i < curves->size(); ++i) {
    const CheckRow& row = *disp[i];
    const AdrsDemand& dem = (*curves)[i];
    const std::string who = code_name(row.code) + " " + row.limit_state +
                            (row.location == "height" ? " (" + c.t("where.height") + ")" : "");
    PlotSeries s = plot_series(msgf(c.L, "kin.adrs_spectrum", code_name(row.code),
                               row.limit_state + (row.location == "height" ? " (" + c.t("where.height") + ")" : std::string()),
                               c.n(dem.xi_pct, 0)),
                          row.code == "NTC2008" ? PlotSeries::Style::Dashed : PlotSeries::Style::Line, dem.Sd, dem.Sa);
    s.color = colour(row);
    p.series.push_back(s);
    const double T = row.secant_T;
    if (T > 0.0 && row.secant_d > 0.0 && std::isfinite(row.demand)) {
      const double slope = std::pow(2.0 * pi / T, 2);
      const double x_end = 1.1 * std::max({row.demand, row.capacity, row.secant_d});
      PlotSeries line = plot_series(i == 0 ? msgf(c.L, "kin.adrs_secant", "") : "", PlotSeries::Style::Dashed, {0.0, x_end},
                               {0.0, slope * x_end});
      line.color = "#888888";
      p.series.push_back(line);
      PlotSeries d = plot_series(msgf(c.L, "kin.adrs_demand", who), PlotSeries::Style::Points, {row.demand},
                            {row.demand * slope});
      d.color = colour(row);
      d.point_size = 1.3;
      d.point_type = 7;
      p.series.push_back(d);
      if (row.code == "NTC2008") {
        PlotSeries q = plot_series("", PlotSeries::Style::Points, {row.secant_d}, {row.secant_a});
        q.color = colour(row);
        q.point_type = 9;
        q.point_size = 1.1;
        p.series.push_back(q);
      }
      d_show = std::max(d_show, x_end);
    }
    PlotSeries q = plot_series(msgf(c.L, "kin.adrs_capacity", who), PlotSeries::Style::Points, {row.capacity},
                          {a_on_curve(k, row.capacity)});
    q.color = colour(row);
    q.point_type = 5;
    q.point_size = 1.1;
    p.series.push_back(q);
  }
  p.x_min = 0.0;
  p.x_max = 1.05 * d_show;
  p.y_min = 0.0;
  double a_top = 3.0 * k.a0_star;
  for (const PlotSeries& s : p.series)
    if (s.style == PlotSeries::Style::Points) a_top = std::max(a_top, 1.3 * s.y[0]);
  p.y_max = a_top;
  p.key = "below";
  p.height = 460 + 16 * int((p.series.size() + 1) / 2);
  c.d.add_svg(render_svg(p), c.t("kin.adrs_fig"), id);
}

// A table of the mechanism's own quantities (issue 33: a chain reduced to a
// plan or a projection shows the wall's data, not its blocks' extents; the
// derivation of a candidate: arch thrust, roof thrust, side walls' friction,
// alpha0 with and without a term, a corner's axis).
void add_quantity_table(Ctx& c, const std::vector<MechanismQuantity>& qs, const std::string& caption) {
  std::vector<std::vector<Cell>> rows;
  for (const MechanismQuantity& q : qs) {
    Cell v(q.unit.empty() ? "" : c.g(q.value, 4));
    v.numeric = true;
    rows.push_back({Cell(c.loc(q.label)), v, Cell(q.unit == "-" ? "–" : c.unit(q.unit)),
                    Cell(q.source == "input" ? c.t("data.case") : c.clause(q.source))});
  }
  Cell hv(c.t("kin.value"));
  hv.numeric = true;
  c.d.add_cell_table({Cell(c.t("kin.quantity")), hv, Cell(c.t("kin.unit")), Cell(c.t("data.source"))}, rows, caption);
}

// The methods a candidate governs, in words ("lineare, non lineare (NTC 2018)").
std::string governs_text(const Ctx& c, std::size_t ci) {
  std::string out;
  const Verdict& v = c.a.verdict;
  for (const MethodVerdict& m : v.methods) {
    if (m.governing < 0 || candidate_of(c.a, v.rows[std::size_t(m.governing)].candidate) != ci) continue;
    out += (out.empty() ? "" : "; ") + c.t("method." + m.method) + " (" + code_name(m.code) + ")";
  }
  return out;
}

}  // namespace

std::size_t body_candidate(const FacadeAssessment& a) {
  if (const MethodVerdict* m = a.verdict.conclusion())
    if (m->governing >= 0) return candidate_of(a, a.verdict.rows[std::size_t(m->governing)].candidate);
  return a.kinematic.governing;
}

void add_candidate_data(Ctx& c, std::size_t ci, const std::string& fig, int level) {
  const CandidateResult& cr = c.candidate(ci);
  const MechanismCandidate& mc = c.a.kase.mechanism.candidates.at(ci);
  const Chain& chain = mc.chain;
  if (!c.a.kase.mechanism.data.empty()) add_quantity_table(c, c.a.kase.mechanism.data, c.t("data.caption_mechanism"));
  else add_bodies(c, chain);
  if (!fig.empty()) {
    bool welded = false;  // issue 33: the corner's pieces, projected on the plane normal to the axis
    for (const Constraint& x : chain.constraints()) welded = welded || x.type == ConstraintType::Weld;
    c.d.add_svg(mechanism_svg(chain, cr.result, c.L),
                c.t(chain.plan() ? "mech.fig_plan" : welded ? "mech.fig_projection" : "mech.fig"), fig);
  }
  if (!mc.quantities.empty()) {
    c.d.add_heading(c.t("mech.derivation"), level, false);
    add_quantity_table(c, mc.quantities, c.t("mech.derivation_cap"));
  }
  const KinematicResult& kr = cr.result;
  if (std::isfinite(kr.d0_star_bound) && kr.d0_star_bound < kr.d0_star)
    c.d.add_paragraph(msgf(c.L, "mech.bound", c.n(kr.d0_star, 3), c.n(kr.d0_star_bound, 3), c.loc(mc.rotation_bound_reason)));
}

void add_virtual_work(Ctx& c, std::size_t ci) {
  virtual_work_table(c, c.a.kase.mechanism.candidates.at(ci).chain, c.candidate(ci).result);
}
void add_quantities(Ctx& c, std::size_t ci) { quantities_table(c, c.candidate(ci).result); }
void add_curve_table(Ctx& c, std::size_t ci) { curve_table(c, c.candidate(ci).result); }
void add_adrs(Ctx& c, std::size_t ci, const std::string& id) { adrs_figure(c, ci, id); }

void add_formulas(Ctx& c) {
  c.d.add_heading(c.t("formulas.heading"));
  c.d.add_paragraph(c.t("formulas.intro"));
  std::vector<std::vector<Cell>> rows;
  auto row = [&](const char* what, const char* formula, const char* clause) {
    rows.push_back({Cell(c.t(what)), Cell(c.t(formula)), Cell(clause)});
  };
  row("f.alpha0", "f.alpha0_formula", "C8.7.1.1; C8A.4.1");
  row("f.M", "f.M_formula", "C8.7.1.2; C8A.4.2");
  row("f.e", "f.e_formula", "C8.7.1.5; C8A.4.3");
  row("f.a0", "f.a0_formula", "C8.7.1.3; C8A.4.4");
  row("f.dstar", "f.dstar_formula", "C8.7.1.4; C8A.4.5");
  row("f.curve", "f.curve_formula", "C8.7.1.4; C8A.4.5");
  row("f.du", "f.du_formula", "C8A.4.6-7");
  row("f.dSLV", "f.dSLV_formula", "C8.7.1.2.1.6");
  row("f.TSLV", "f.TSLV_formula", "C8.7.1.10-11");
  row("f.lin", "f.lin_formula", "C8.7.1.2.1.7; C8A.4.9");
  row("f.SDe", "f.SDe_formula", "NTC 2018 [3.2.10], [3.2.4]");
  row("f.disp", "f.disp_formula", "C8.7.1.2.1.8; C8A.4.11");
  if (any_at_height(c.a)) {
    row("f.mode", "f.mode_formula", "C7.2.10");
    row("f.aZ", "f.aZ_formula", "C7.2.7-8");
    row("f.lin_h", "f.lin_h_formula", "C8.7.1.2.1.7; C8A.4.10");
    row("f.SeZ", "f.SeZ_formula", "C7.2.6");
    row("f.SeZ_lb", "f.SeZ_lb_formula", "C7.2.5");
    row("f.disp_h", "f.disp_h_formula", "C8.7.1.12");
    row("f.disp_h08", "f.disp_h08_formula", "C8A.4.12");
  }
  row("f.zeta", "f.zeta_formula", "D.P.C.M. 9/2/2011; C8.3");
  c.d.add_cell_table({Cell(c.t("kin.quantity")), Cell(c.t("formulas.formula")), Cell(c.t("kin.clause"))}, rows, "");
}

void add_mechanism(Ctx& c) {
  const FacadeAssessment& a = c.a;
  c.d.add_heading(c.t("mech.heading"), 2, true, true, "mechanism");
  const std::size_t ci = body_candidate(a);
  const std::size_t n = a.kinematic.candidates.size();
  // The body develops the candidate whose check decides the conclusion
  // (issue 36: one section of a few pages per mechanism); every candidate,
  // with its virtual work and capacity curve, is in the tabulati.
  Inline intro{Span{c.t("mech.type") + ": " + mechanism_name(c.L, a.kase.mechanism.type) + ". " +
                    msgf(c.L, n > 1 ? "mech.body_one" : "mech.body_single", c.loc(c.candidate(ci).label), n)}};
  if (c.tabulati) {
    intro.push_back(Span{" "});
    intro.push_back(reference(c.t("mech.see_tab_candidates"), c.here("candidates"), tabulati_key));
  }
  c.d.add_paragraph(intro);
  const std::string gov = governs_text(c, ci);
  if (!gov.empty()) c.d.add_paragraph(c.t("mech.governs_methods") + ": " + gov + ".", "note");
  c.d.add_heading(c.t("mech.bodies"), 3, false);
  add_candidate_data(c, ci, "fig-mechanism", 3);
  // A building's mechanism (issue 36: 2-4 pages each): the virtual-work table
  // and the ADRS plot of the candidate are in the tabulati, referred to here;
  // the body keeps its data, drawing, kinematic quantities and checks.
  const bool brief = c.building && c.tabulati;
  if (brief) {
    c.d.add_paragraph(Inline{reference(c.t("mech.vw_in_tab"), c.here("cand-" + std::to_string(ci)), tabulati_key)}, "note");
  } else {
    c.d.add_heading(c.t("mech.vw"), 3, false);
    add_virtual_work(c, ci);
  }
  c.d.add_heading(c.t("kin.heading_linear"), 3, false);
  add_quantities(c, ci);
  add_choice_notes(c, {"FC", "lumped_masses", "displacement_bound", "friction_activation", "seat_friction", "dSLV_over_d0",
                   "dSLC_over_d0"});
  if (c.candidate(ci).result.curve_complete() && !brief) {
    c.d.add_heading(c.t("kin.heading_curve"), 3, false);
    if (c.tabulati)
      c.d.add_paragraph(Inline{reference(c.t("kin.curve_in_tab"), c.here("cand-" + std::to_string(ci)), tabulati_key)}, "note");
    else
      add_curve_table(c, ci);
    add_adrs(c, ci, "fig-adrs");
  }
  // Every candidate examined (C8.7.1: the most unfavourable governs), each with where it is developed.
  if (n > 1) {
    c.d.add_heading(c.t("mech.candidates"), 3, false);
    std::vector<Cell> head{Cell(c.t("mech.candidate")), numeric_cell(c.loc(a.kase.mechanism.parameter_name)), numeric_cell("Z (m)"),
                           numeric_cell("α0 (–)"), numeric_cell("a0* (m/s²)")};
    for (const auto& [code, gi] : a.kinematic.governing_by_code) head.push_back(numeric_cell("D/C " + code_name(code)));
    // The candidate's lowest safety index of the code in force (issue 41).
    const std::string zcode = a.kinematic.governing_by_code.count("NTC2018") ? "NTC2018"
                              : a.kinematic.governing_by_code.empty()          ? ""
                                                                               : a.kinematic.governing_by_code.begin()->first;
    if (!zcode.empty()) head.push_back(numeric_cell("ζE " + code_name(zcode)));
    head.push_back(Cell(c.t("mech.where")));
    std::vector<std::vector<Cell>> rows;
    std::size_t omitted = 0;
    for (std::size_t i = 0; i < n; ++i) {
      const CandidateResult& cr = a.kinematic.candidates[i];
      // A building's body lists the candidate developed, those that govern a
      // method and those whose check is not satisfied; the others (every check
      // satisfied) are counted and listed in the tabulati (issue 36: length).
      if (brief && i != ci && governs_text(c, i).empty()) {
        bool all_ok = !cr.max_dc.empty();
        for (const auto& [code, dc] : cr.max_dc) all_ok = all_ok && check_satisfied(dc, false);
        if (all_ok) {
          ++omitted;
          continue;
        }
      }
      std::vector<Cell> row{Cell(c.loc(cr.label)), c.num(cr.parameter, 3), c.num(cr.Z, 2), c.num(cr.result.alpha0, 4),
                            c.num(cr.result.a0_star, 3)};
      for (const auto& [code, gi] : a.kinematic.governing_by_code) {
        const auto it = cr.max_dc.find(code);
        row.push_back(it == cr.max_dc.end() ? c.num(std::nan(""), 3)
                                            : c.dc_cell(it->second, outcome_of(check_satisfied(it->second, false), false)));
      }
      if (!zcode.empty()) {
        const auto z = cr.zeta_min.find(zcode);
        const auto d = cr.max_dc.find(zcode);
        Cell zc = c.num(z == cr.zeta_min.end() ? std::nan("") : z->second, 3);
        if (d != cr.max_dc.end()) zc.tone = verdict_tone(outcome_of(check_satisfied(d->second, false), false));
        row.push_back(zc);
      }
      const std::string g = governs_text(c, i);
      Cell where(i == ci ? c.t("mech.in_body") : c.t("mech.in_tab"), g);
      if (c.tabulati && i != ci) {
        where.text = c.t("mech.in_tab_ref");
        where.link = c.here("cand-" + std::to_string(i));
        where.doc = tabulati_key;
      }
      row.push_back(where);
      for (Cell& x : row) x.highlight = i == ci;
      rows.push_back(row);
    }
    c.d.add_cell_table(head, rows, msgf(c.L, "mech.candidates_cap2", c.loc(a.kase.mechanism.parameter_name)));
    if (omitted > 0)
      c.d.add_paragraph(Inline{reference(msgf(c.L, "mech.candidates_omitted", omitted), c.here("candidates"), tabulati_key)}, "note");
  }
}

}  // namespace assess::relazione
