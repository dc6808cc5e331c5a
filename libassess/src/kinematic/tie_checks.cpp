// tie_checks.cpp: the design strengths, the capacity design and the checks
// of a tie (docs/theory/ties.md §3; constants in kinematic/tie_catalogue.hpp).
#include "assess/kinematic/tie_checks.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>

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

TieResistance tie_resistance(const Tie& tie) {
  namespace C = tie_catalogue;
  tie.validate();
  TieResistance r;
  // Rod: N_pl,Rd = A fyk / gamma_M0, NTC 2018 §4.2.4.1.2 [4.2.6].
  r.rod = tie.rod.area * tie.rod.fyk / tie.rod.gamma_M0;
  // Threaded end as a bolt in tension: 0.9 ftk A_res / gamma_M2, NTC 2018 §4.2.8.1.1.
  r.thread = C::thread_k2 * tie.rod.ftk * tie.rod.thread_area / C::gamma_M2;
  // Masonry design strengths: mean strength / (FC gamma_M).
  const double div = tie.masonry.FC * tie.masonry.gamma_M;
  r.fd = tie.masonry.fm / div;
  r.fvd = tie.masonry.tau / div;
  const double a = tie.anchor.a, b = tie.anchor.b, s = tie.masonry.thickness;
  // Local compression under the anchor: beta fd A_b, beta = 1.
  r.bearing_area = a * b;
  r.bearing = C::bearing_beta * r.fd * r.bearing_area;
  // Punching: a wedge spreading at 45 degrees through the thickness s; shear
  // on its lateral surface taken as its mean perimeter times s.
  const double spread = s * std::tan(C::punching_angle_deg * units::deg);
  r.punching_area = s * (2.0 * (a + b) + 4.0 * spread);
  r.punching = r.fvd * r.punching_area;
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
  const std::pair<const char*, double> brittle[] = {
      {"thread", r.thread}, {"bearing", r.bearing}, {"punching", r.punching}, {"anchor bending", r.anchor_bending}};
  r.weakest_brittle_capacity = 1e300;
  for (const auto& [name, cap] : brittle) {
    if (cap < r.design) r.design = cap, r.governing = name;
    if (cap < r.weakest_brittle_capacity) r.weakest_brittle_capacity = cap, r.weakest_brittle = name;
  }
  // Capacity design: ductile when every brittle capacity >= gamma_Rd gamma_ov A fyk.
  r.yield_force = tie.rod.area * tie.rod.fyk;
  r.hierarchy_demand = C::gamma_Rd * C::gamma_ov * r.yield_force;
  r.ductile = r.weakest_brittle_capacity >= r.hierarchy_demand;
  r.stiffness = tie.rod.E * tie.rod.area / tie.free_length;
  if (!(tie.pretension < r.design))
    throw InputError("tie \"" + tie.name + "\": pretension = " + num(tie.pretension / units::kN) +
                     " kN: expected below the tie's design strength T_Rd = " + num(r.design / units::kN) + " kN (" +
                     r.governing + ")");
  r.yield_elongation = (r.design - tie.pretension) / r.stiffness;
  r.ultimate_elongation = r.ductile ? std::max(C::eps_ud_over_A * tie.rod.elongation * tie.free_length, r.yield_elongation)
                                    : r.yield_elongation;
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
    row.dc = d / capacity;  // every capacity > 0 (validate)
    row.satisfied = row.dc <= 1.0;
    rows.push_back(row);
  };
  const char* ntc_rod = "NTC 2018 §4.2.4.1.2 [4.2.6]";
  const char* ntc_thread = "NTC 2018 §4.2.8.1.1";
  const char* practice = "designer's assumption";
  const char* plate = tie.anchor.type == AnchorType::Plate ? "2 a b t^2 fyk / (4 gamma_M0 c^2), c = (max(a, b) - s_nut) / 2"
                                                           : "8 b^3 fyk / (6 gamma_M0 a)";
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
  if (r.ductile) {
    // The rod yields first: its static demand, the brittle components against
    // the rod's overstrength (gerarchia delle resistenze), the elongation.
    add("rod yield", ntc_rod, "A fyk / gamma_M0", demand.static_force, r.rod, "kN");
    const char* capacity_design = "EN 1998-1 §6.5.5";
    add("hierarchy thread", capacity_design, "0.9 ftk A_res / gamma_M2 >= gamma_Rd gamma_ov A fyk", r.hierarchy_demand,
        r.thread, "kN");
    add("hierarchy local compression", capacity_design, "beta fd A_b >= gamma_Rd gamma_ov A fyk", r.hierarchy_demand,
        r.bearing, "kN");
    add("hierarchy punching", capacity_design, "fvd A_p >= gamma_Rd gamma_ov A fyk", r.hierarchy_demand, r.punching,
        "kN");
    add("hierarchy anchor bending", capacity_design, "N_b,Rd >= gamma_Rd gamma_ov A fyk", r.hierarchy_demand,
        r.anchor_bending, "kN");
    if (demand.elongation)
      add("rod elongation", "EN 10025-2 Tab. 7", "eps_ud L, eps_ud = 0.9 A", std::max(0.0, *demand.elongation),
          r.ultimate_elongation, "mm");
  } else {
    // Not ductile: the tie must stay elastic; every component takes the
    // largest force it develops.
    const double N = demand.elastic_demand();
    add("rod yield", ntc_rod, "A fyk / gamma_M0", N, r.rod, "kN");
    add("thread", ntc_thread, "0.9 ftk A_res / gamma_M2", N, r.thread, "kN");
    add("local compression", practice, "beta fm / (FC gamma_M) A_b", N, r.bearing, "kN");
    add("punching", practice, "tau / (FC gamma_M) s (2(a + b) + 4 s)", N, r.punching, "kN");
    add("anchor bending", practice, plate, N, r.anchor_bending, "kN");
  }
  // Layout: the punching wedges of adjacent ties must not overlap, and the
  // first and last must lie inside the wall (else the punching strength of
  // the full wedge is not there).
  const double wedge = std::max(tie.anchor.a, tie.anchor.b) +
                       2.0 * tie.masonry.thickness * std::tan(tie_catalogue::punching_angle_deg * units::deg);
  if (tie.layout.count > 1)
    add("cone spacing", practice, "a + 2 s tan 45 <= i", wedge, tie.layout.centre_spacing(), "m");
  add("edge distance", practice, "a / 2 + s tan 45 <= e", wedge / 2.0, tie.layout.edge_distance, "m");
  return rows;
}

}  // namespace assess
