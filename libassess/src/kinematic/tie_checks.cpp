// tie_checks.cpp: the design strengths and checks of a tie
// (docs/theory/ties.md §3; constants in kinematic/tie_catalogue.hpp).
#include "assess/kinematic/tie_checks.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace assess {

TieResistance tie_resistance(const Tie& tie) {
  tie.validate();
  TieResistance r;
  // Rod: N_pl,Rd = A fyk / gamma_M0, NTC 2018 §4.2.4.1.2 [4.2.6] [R].
  r.rod = tie.rod.area * tie.rod.fyk / tie.rod.gamma_M0;
  // Masonry design strengths: mean strength / (FC gamma_M) [R]/[I].
  const double div = tie.masonry.FC * tie.masonry.gamma_M;
  r.fd = tie.masonry.fm / div;
  r.fvd = tie.masonry.tau / div;
  const double a = tie.anchor.a, b = tie.anchor.b, s = tie.masonry.thickness;
  // Local compression under the anchor: fd times the bearing area [R].
  r.bearing_area = a * b;
  r.bearing = r.fd * r.bearing_area;
  // Punching: a wedge spreading at 45 degrees through the thickness s; shear
  // on its lateral surface taken as its mean perimeter times s [R].
  const double spread = s * std::tan(tie_catalogue::punching_angle_deg * units::deg);
  r.punching_area = s * (2.0 * (a + b) + 4.0 * spread);
  r.punching = r.fvd * r.punching_area;
  // Anchor bending [I].
  if (tie.anchor.type == AnchorType::Plate) {
    // One-way cantilever strips from the nut (width ~ 2 d of the rod) under
    // the uniform bearing pressure p = N / (a b): p c^2 / 2 <= t^2 fyk / (4 gamma_M0).
    const double d = tie.rod.diameter > 0.0 ? tie.rod.diameter : std::sqrt(4.0 * tie.rod.area / units::pi);
    const double c = (std::max(a, b) - 2.0 * d) / 2.0;
    r.anchor_bending = c > 0.0 ? 2.0 * a * b * tie.anchor.t * tie.anchor.t * tie.anchor.fyk /
                                     (4.0 * tie_catalogue::gamma_M0 * c * c)
                               : std::numeric_limits<double>::infinity();
  } else {
    // A bar of length a and diameter b, loaded at its middle by the rod and
    // bearing uniformly: M = N a / 8 <= b^3 fyk / (6 gamma_M0) (plastic modulus of a circle).
    r.anchor_bending = 8.0 * b * b * b * tie.anchor.fyk / (6.0 * tie_catalogue::gamma_M0 * a);
  }
  r.design = r.rod;
  r.governing = "rod";
  if (r.bearing < r.design) r.design = r.bearing, r.governing = "bearing";
  if (r.punching < r.design) r.design = r.punching, r.governing = "punching";
  if (r.anchor_bending < r.design) r.design = r.anchor_bending, r.governing = "anchor bending";
  r.stiffness = tie.rod.E * tie.rod.area / tie.free_length;
  r.ultimate_elongation = tie_catalogue::eps_ud_over_eps_uk * tie_catalogue::eps_uk * tie.free_length;
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
  r.pretension = r.count * std::min(tie.pretension, res.design);
  return r;
}

std::vector<TieCheckRow> tie_checks(const Tie& tie, double N_Ed, std::optional<double> e_Ed) {
  const TieResistance r = tie_resistance(tie);
  std::vector<TieCheckRow> rows;
  auto add = [&](const char* check, const char* clause, const char* formula, double demand, double capacity,
                 const char* unit) {
    TieCheckRow row{check, clause, formula, demand, capacity, unit, 0.0, false};
    row.dc = capacity > 0.0 ? demand / capacity : std::numeric_limits<double>::infinity();
    row.satisfied = row.dc <= 1.0;
    rows.push_back(row);
  };
  add("rod yield", "NTC 2018 §4.2.4.1.2 [4.2.6] [R]", "A fyk / gamma_M0", N_Ed, r.rod, "kN");
  add("local compression", "masonry under the anchor, practice [R]", "fm / (FC gamma_M) A_b", N_Ed, r.bearing, "kN");
  add("punching", "45-degree masonry wedge, practice [R]", "tau / (FC gamma_M) s (2(a + b) + 4 s)", N_Ed, r.punching,
      "kN");
  add("anchor bending", tie.anchor.type == AnchorType::Plate ? "plate as cantilever strips [I]" : "bar, simply supported [I]",
      tie.anchor.type == AnchorType::Plate ? "2 a b t^2 fyk / (4 gamma_M0 c^2)" : "8 b^3 fyk / (6 gamma_M0 a)", N_Ed,
      r.anchor_bending, "kN");
  if (e_Ed) add("rod elongation", "eps_ud = 0.9 eps_uk, eps_uk = 7.5 % [I]", "eps_ud L", *e_Ed, r.ultimate_elongation, "mm");
  return rows;
}

}  // namespace assess
