// tie_checks.cpp: the design strengths, the capacity design and the checks
// of a tie (docs/theory/ties.md §3; constants in kinematic/tie_catalogue.hpp).
#include "assess/kinematic/tie_checks.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <vector>

namespace assess {
namespace {

std::string num(double v) {
  std::ostringstream os;
  os << v;
  return os.str();
}

}  // namespace

double TieDemand::elastic_demand() const {
  double n = static_force;
  if (curve_force) n = std::max(n, *curve_force);
  if (dynamic_force) n = std::max(n, *dynamic_force);
  return n;
}

namespace {

// Length of [a, b] not covered by the intervals `cut` (m).
double uncovered(double a, double b, std::vector<std::pair<double, double>> cut) {
  if (!(b > a)) return 0.0;
  std::sort(cut.begin(), cut.end());
  double len = 0.0, at = a;
  for (const auto& [c0, c1] : cut) {
    if (c1 <= at) continue;
    if (c0 >= b) break;
    if (c0 > at) len += c0 - at;
    at = std::max(at, c1);
    if (at >= b) break;
  }
  if (at < b) len += b - at;
  return len;
}

// Integral over y in [0, s] of f(y), f piecewise linear between the sorted
// breakpoints `cuts` (two-point Gauss on each piece: exact for linear pieces).
template <class F>
double integrate_depth(double s, std::vector<double> cuts, F f) {
  cuts.push_back(0.0);
  cuts.push_back(s);
  std::sort(cuts.begin(), cuts.end());
  const double g = 0.5 / std::sqrt(3.0);
  double sum = 0.0;
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    const double y0 = std::max(0.0, cuts[i]), y1 = std::min(s, cuts[i + 1]);
    if (!(y1 > y0)) continue;
    const double m = 0.5 * (y0 + y1), d = y1 - y0;
    sum += 0.5 * d * (f(m - g * d) + f(m + g * d));
  }
  return sum;
}

}  // namespace

AnchorWedge anchor_wedge(const Tie& tie, int j) {
  const TieLayout& L = tie.layout;
  const double w = tie.anchor.width(), h = tie.anchor.height(), s = tie.masonry.thickness;
  const double spread = std::tan(tie_catalogue::punching_angle_deg * units::deg);  // 1 at 45 degrees
  AnchorWedge W;
  W.tie = j;
  W.x = L.position(j);
  const double half = L.count > 1 ? L.centre_spacing() / 2.0 : std::numeric_limits<double>::infinity();
  W.x_lo = j == 0 ? 0.0 : W.x - half;
  W.x_hi = j == L.count - 1 ? L.wall_length : W.x + half;
  const double zc = tie.point.y(), xc = W.x;
  const double z_lo = L.base, z_hi = L.crown;
  // The breakpoints in y: where an edge of the rectangle meets a line of the
  // region (the strip's sides, the base, the crown, an opening's sides).
  std::vector<double> xs{W.x_lo, W.x_hi}, zs{z_lo};
  if (std::isfinite(z_hi)) zs.push_back(z_hi);
  for (const WallOpening& o : L.openings) {
    xs.insert(xs.end(), {o.x0, o.x1});
    zs.insert(zs.end(), {o.z0, o.z1});
  }
  std::vector<double> cuts;
  for (double X : xs) cuts.push_back((std::fabs(X - xc) - w / 2.0) / spread);
  for (double Z : zs) cuts.push_back((std::fabs(Z - zc) - h / 2.0) / spread);
  // Length in masonry of a horizontal edge at height z from xa to xb, and of a
  // vertical edge at x from za to zb.
  auto horizontal = [&](double z, double xa, double xb) {
    if (!(z > z_lo && z < z_hi)) return 0.0;
    std::vector<std::pair<double, double>> cut;
    for (const WallOpening& o : L.openings)
      if (z > o.z0 && z < o.z1) cut.push_back({o.x0, o.x1});
    return uncovered(std::max(xa, W.x_lo), std::min(xb, W.x_hi), cut);
  };
  auto vertical = [&](double x, double za, double zb) {
    if (!(x > W.x_lo && x < W.x_hi)) return 0.0;
    std::vector<std::pair<double, double>> cut;
    for (const WallOpening& o : L.openings)
      if (x > o.x0 && x < o.x1) cut.push_back({o.z0, o.z1});
    return uncovered(std::max(za, z_lo), std::min(zb, z_hi), cut);
  };
  W.area = integrate_depth(s, cuts, [&](double y) {
    const double xa = xc - w / 2.0 - spread * y, xb = xc + w / 2.0 + spread * y;
    const double za = zc - h / 2.0 - spread * y, zb = zc + h / 2.0 + spread * y;
    return horizontal(zb, xa, xb) + horizontal(za, xa, xb) + vertical(xa, za, zb) + vertical(xb, za, zb);
  });
  W.full_area = s * (2.0 * (w + h) + 4.0 * spread * s);
  // The sliding block: above the bed joint at the anchor's lower edge, up to
  // the crown or the first opening over the anchor.
  const double z_b = zc - h / 2.0;
  W.block_top = z_hi;
  bool crown_reached = true;
  for (const WallOpening& o : L.openings)
    if (o.x1 > xc - w / 2.0 && o.x0 < xc + w / 2.0 && o.z0 >= zc + h / 2.0 - 1e-12 && o.z0 < W.block_top) {
      W.block_top = o.z0;
      crown_reached = false;
    }
  if (std::isfinite(W.block_top)) {
    std::vector<double> xcuts;
    for (double X : xs) xcuts.push_back((std::fabs(X - xc) - w / 2.0) / spread);
    W.side_area = integrate_depth(s, xcuts, [&](double y) {
      const double xa = xc - w / 2.0 - spread * y, xb = xc + w / 2.0 + spread * y;
      return vertical(xa, z_b, W.block_top) + vertical(xb, z_b, W.block_top);
    });
    W.base_area = integrate_depth(s, xcuts, [&](double y) {
      const double xa = xc - w / 2.0 - spread * y, xb = xc + w / 2.0 + spread * y;
      // The bed joint itself (z = z_b) lies in masonry: just above the base of the region.
      if (!(z_b >= z_lo && z_b < z_hi)) return 0.0;
      std::vector<std::pair<double, double>> cut;
      for (const WallOpening& o : L.openings)
        if (z_b >= o.z0 && z_b < o.z1) cut.push_back({o.x0, o.x1});
      return uncovered(std::max(xa, W.x_lo), std::min(xb, W.x_hi), cut);
    });
    W.sigma_n = tie.masonry.unit_weight * (W.block_top - z_b) + (crown_reached ? L.crown_load / s : 0.0);
  }
  return W;
}

double thermal_pretension(const Tie& tie) {
  const double f = tie.rod.E * tie.rod.area * tie_catalogue::thermal_alpha * tie.delta_T;
  return std::ceil(f / 100.0 - 1e-9) * 100.0;
}

TieResistance tie_resistance(const Tie& tie) {
  namespace C = tie_catalogue;
  tie.validate();
  TieResistance r;
  // The sections after the corrosion allowance (EN 1993-5 §4.4 [R], issue 37).
  r.area_c = tie.rod.corroded_area();
  r.thread_area_c = tie.rod.corroded_thread_area();
  // Rod: N_pl,Rd = A fyk / gamma_M0, NTC 2018 §4.2.4.1.2 [4.2.6].
  r.rod = r.area_c * tie.rod.fyk / tie.rod.gamma_M0;
  // Threaded end as a bolt in tension: 0.9 ftk A_res / gamma_M2, NTC 2018 §4.2.8.1.1.
  r.thread = C::thread_k2 * tie.rod.ftk * r.thread_area_c / C::gamma_M2;
  // Masonry design strengths: mean strength / (FC gamma_M).
  const double div = tie.masonry.FC * tie.masonry.gamma_M;
  r.fd = tie.masonry.fm / div;
  r.fvd = tie.masonry.tau / div;
  r.fv0d = (tie.masonry.fv0 > 0.0 ? tie.masonry.fv0 : tie.masonry.tau) / div;
  const double a = tie.anchor.a, b = tie.anchor.b;
  // Local compression under the anchor: beta fd A_b, beta = 1.
  r.bearing_area = a * b;
  r.bearing = C::bearing_beta * r.fd * r.bearing_area;
  // Punching (issue 37): the 45 degree wedge of each tie of the level, cut by
  // the wall; the weakest tie governs. Sliding of the masonry above the
  // anchor on the bed joint at its lower edge, with its overburden.
  r.punching = r.sliding = std::numeric_limits<double>::infinity();
  for (int j = 0; j < tie.layout.count; ++j) {
    const AnchorWedge W = anchor_wedge(tie, j);
    const double p = r.fvd * W.area;
    if (p < r.punching) r.punching = p, r.wedge = W;
    if (std::isfinite(W.block_top)) {
      const double f_base = r.fv0d + tie.masonry.mu * W.sigma_n / tie.masonry.gamma_M;
      const double sl = r.fvd * W.side_area + f_base * W.base_area;
      if (sl < r.sliding) r.sliding = sl, r.slide = W, r.sliding_strength = f_base;
    }
    // Without openings only the end ties and one inner tie differ (the layout is symmetric).
    if (tie.layout.openings.empty() && j == 1 && tie.layout.count > 3) j = tie.layout.count - 2;
  }
  r.punching_area = r.wedge.area;
  if (tie.anchor.type == AnchorType::Plate) {
    // Cantilever strips from the nut's flats (width s_nut) under the uniform
    // bearing pressure p = N / (a b): p c^2 / 2 <= t^2 fyk / (4 gamma_M0),
    // c = (max(a, b) - s_nut) / 2 > 0 (a plate no wider than its nut is refused by validate()).
    r.cantilever = (std::max(a, b) - tie.rod.nut_width) / 2.0;
    r.anchor_bending = 2.0 * a * b * tie.anchor.t * tie.anchor.t * tie.anchor.fyk / (4.0 * C::gamma_M0 * r.cantilever * r.cantilever);
  } else {
    // A bar of length a and diameter b, loaded at its middle by the rod and
    // bearing uniformly: M = N a / 8 <= b^3 fyk / (6 gamma_M0) (plastic modulus of a circle).
    r.anchor_bending = 8.0 * b * b * b * tie.anchor.fyk / (6.0 * C::gamma_M0 * a);
  }
  r.design = r.rod;
  r.governing = "rod";
  const std::pair<const char*, double> brittle[] = {{"thread", r.thread},
                                                    {"bearing", r.bearing},
                                                    {"punching", r.punching},
                                                    {"sliding", r.sliding},
                                                    {"anchor bending", r.anchor_bending}};
  r.weakest_brittle_capacity = std::numeric_limits<double>::infinity();
  for (const auto& [name, cap] : brittle) {
    if (cap < r.design) r.design = cap, r.governing = name;
    if (cap < r.weakest_brittle_capacity) r.weakest_brittle_capacity = cap, r.weakest_brittle = name;
  }
  // Capacity design: ductile when the ends are stronger than the rod (upset or
  // welded: a rod threaded on its own diameter yields only in its thread) and
  // every brittle capacity >= gamma_Rd gamma_ov A fyk.
  r.yield_force = tie.rod.area * tie.rod.fyk;
  r.hierarchy_demand = C::gamma_Rd * C::gamma_ov * r.yield_force;
  r.ductile = tie.rod.ends != TieEnds::Threaded && r.weakest_brittle_capacity >= r.hierarchy_demand;
  r.stiffness = tie.rod.E * tie.rod.area / tie.free_length;
  if (!(tie.pretension < r.design))
    throw InputError("tie \"" + tie.name + "\": pretension = " + num(tie.pretension / units::kN) +
                     " kN: expected below the tie's design strength T_Rd = " + num(r.design / units::kN) + " kN (" +
                     r.governing + ")");
  r.yield_elongation = (r.design - tie.pretension) / r.stiffness;
  r.eps_ud = r.ductile ? C::eps_ud_over_eps_uk * tie.rod.eps_uk : 0.0;
  r.ultimate_elongation = r.ductile ? std::max(r.eps_ud * tie.free_length, r.yield_elongation) : r.yield_elongation;
  // The temperature action on the restrained rod (fundamental combination).
  r.thermal_force = tie.rod.E * tie.rod.area * C::thermal_alpha * tie.delta_T;
  r.temperature_demand = C::gamma_P * tie.pretension + C::gamma_Q * r.thermal_force;
  return r;
}

TieRestraint tie_restraint(const Tie& tie, int block, double length) {
  const TieResistance res = tie_resistance(tie);
  TieRestraint r;
  r.name = tie.name;
  r.block = block;
  r.point = tie.point;
  r.direction = tie.direction.normalized();
  r.count = length / tie.spacing;
  r.stiffness = r.count * res.stiffness;
  r.capacity = r.count * res.design;
  r.pretension = r.count * tie.pretension;
  r.ductile = res.ductile;
  r.ultimate_elongation = res.ultimate_elongation;
  r.governing = res.governing;
  return r;
}

std::vector<TieCheckRow> tie_checks(const Tie& tie, const TieDemand& demand) {
  const TieResistance r = tie_resistance(tie);
  std::vector<TieCheckRow> rows;
  auto add = [&](const char* check, const char* clause, const char* formula, double d, double capacity,
                 const char* unit) {
    TieCheckRow row{check, clause, formula, d, capacity, unit, 0.0, false, true};
    row.dc = capacity > 0.0 ? d / capacity : (d > 0.0 ? std::numeric_limits<double>::infinity() : 0.0);
    row.satisfied = row.dc <= 1.0;
    rows.push_back(row);
  };
  const char* ntc_rod = "NTC 2018 §4.2.4.1.2 [4.2.6]";
  const char* ntc_thread = "NTC 2018 §4.2.8.1.1";
  const char* practice = "designer's assumption";
  const char* plate = tie.anchor.type == AnchorType::Plate ? "2 a b t^2 fyk / (4 gamma_M0 c^2), c = (max(a, b) - s_nut) / 2"
                                                           : "8 b^3 fyk / (6 gamma_M0 a)";
  const char* sliding = "f_vd A_sides + (f_v0 / (FC gamma_M) + mu sigma_n / gamma_M) A_base";
  const char* punching = "tau / (FC gamma_M) A_p, A_p the wedge's lateral area in masonry";
  if (!demand.reachable) {
    TieCheckRow row{"required force", "", "", 0.0, r.design, "kN", 0.0, false, false};
    rows.push_back(row);
  }
  if (demand.dynamic_runs > 0) {
    // A tie that breaks in an analysis has failed, whatever its D/C.
    TieCheckRow row{"dynamic rupture", "Circ. 2019 C8.7.1.2.1.9", "", double(demand.dynamic_breaks), 0.0, "analyses",
                    0.0, demand.dynamic_breaks == 0, true};
    rows.push_back(row);
  }
  const bool sliding_applies = std::isfinite(r.sliding);
  if (r.ductile) {
    // The rod yields first: its static demand, the brittle components against
    // the rod's overstrength (gerarchia delle resistenze), the elongation.
    add("rod yield", ntc_rod, "A_c fyk / gamma_M0", demand.static_force, r.rod, "kN");
    const char* capacity_design = "EN 1998-1 §6.5.5";
    add("hierarchy thread", capacity_design, "0.9 ftk A_res,c / gamma_M2 >= gamma_Rd gamma_ov A fyk", r.hierarchy_demand,
        r.thread, "kN");
    add("hierarchy local compression", capacity_design, "beta fd A_b >= gamma_Rd gamma_ov A fyk", r.hierarchy_demand,
        r.bearing, "kN");
    add("hierarchy punching", capacity_design, "fvd A_p >= gamma_Rd gamma_ov A fyk", r.hierarchy_demand, r.punching,
        "kN");
    if (sliding_applies)
      add("hierarchy sliding", capacity_design, "N_s,Rd >= gamma_Rd gamma_ov A fyk", r.hierarchy_demand, r.sliding, "kN");
    add("hierarchy anchor bending", capacity_design, "N_b,Rd >= gamma_Rd gamma_ov A fyk", r.hierarchy_demand,
        r.anchor_bending, "kN");
    if (demand.elongation)
      add("rod elongation", "EN 1993-1-1 §3.2.2", "eps_ud L, eps_ud = 0.9 eps_uk",
          std::max(0.0, *demand.elongation), r.ultimate_elongation, "mm");
  } else {
    // Not ductile: the tie must stay elastic; every component takes the
    // largest force it develops.
    const double N = demand.elastic_demand();
    add("rod yield", ntc_rod, "A_c fyk / gamma_M0", N, r.rod, "kN");
    add("thread", ntc_thread, "0.9 ftk A_res,c / gamma_M2", N, r.thread, "kN");
    add("local compression", practice, "beta fm / (FC gamma_M) A_b", N, r.bearing, "kN");
    add("punching", practice, punching, N, r.punching, "kN");
    if (sliding_applies) add("sliding", practice, sliding, N, r.sliding, "kN");
    add("anchor bending", practice, plate, N, r.anchor_bending, "kN");
  }
  // The temperature action on the restrained rod, in the fundamental
  // combination (not with the earthquake: psi2 = 0), on the rod and its thread;
  // a new tie's pretension takes up the range (the warmed rod does not go slack).
  if (r.thermal_force > 0.0) {
    add("temperature rod", "NTC 2018 §3.5.5", "gamma_P P0 + gamma_Q E A alpha_T dT <= A_c fyk / gamma_M0",
        r.temperature_demand, r.rod, "kN");
    add("temperature thread", "NTC 2018 §3.5.5", "gamma_P P0 + gamma_Q E A alpha_T dT <= N_t,Rd",
        r.temperature_demand, r.thread, "kN");
    if (!tie.existing)
      add("pretension", "NTC 2018 §3.5.5", "E A alpha_T dT <= P0", r.thermal_force, tie.pretension, "kN");
  }
  return rows;
}

}  // namespace assess
