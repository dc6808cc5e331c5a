// tie_checks.hpp: the checks of a tie (issue 23), each with its clause or
// source and certainty tag (docs/theory/ties.md; constants in
// kinematic/tie_catalogue.hpp):
//   rod yield            N_pl,Rd = A fyk / gamma_M0      NTC 2018 §4.2.4.1.2 [4.2.6] [R]
//   local compression    N_c,Rd = fm / (FC gamma_M) A_b   practice [R]
//   punching of masonry  N_p,Rd = tau / (FC gamma_M) s (2(a + b) + 4 s)  practice, 45-degree wedge [R]
//   anchor bending       plate: cantilever strips; bar: simply supported [I]
//   rod elongation       e_Ed <= eps_ud L                 [I]
#pragma once

#include "assess/kinematic/tie.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// The design strengths of one tie (N) and the weakest.
struct TieResistance {
  double rod = 0.0;              ///< N_pl,Rd (N)
  double bearing = 0.0;          ///< local compression under the anchor (N)
  double punching = 0.0;         ///< punching of the masonry wedge (N)
  double anchor_bending = 0.0;   ///< bending of the plate or bar (N)
  double design = 0.0;           ///< min of the above (N)
  std::string governing;         ///< "rod" | "bearing" | "punching" | "anchor bending"
  double fd = 0.0;               ///< masonry design compressive strength fm / (FC gamma_M) (Pa)
  double fvd = 0.0;              ///< masonry design shear strength tau / (FC gamma_M) (Pa)
  double bearing_area = 0.0;     ///< m^2
  double punching_area = 0.0;    ///< lateral area of the wedge s (2(a + b) + 4 s) (m^2)
  double stiffness = 0.0;        ///< E A / L of one tie (N/m)
  double ultimate_elongation = 0.0;  ///< eps_ud L (m)
};
TieResistance tie_resistance(const Tie& tie);

/// The restraint of a tie level on a chain of out-of-plane length `length`
/// (m): count = length / spacing, capacity = count x design strength.
TieRestraint tie_restraint(const Tie& tie, int block, double length);

/// One check of a tie: demand, capacity, D/C = demand / capacity.
struct TieCheckRow {
  std::string check;    ///< "rod yield", "local compression", "punching", "anchor bending", "rod elongation"
  std::string clause;   ///< clause or source and certainty tag
  std::string formula;  ///< the capacity, in symbols
  double demand = 0.0;
  double capacity = 0.0;
  std::string unit;     ///< "kN" | "mm" (as printed; values are SI: N, m)
  double dc = 0.0;
  bool satisfied = false;
};

/// The checks of one tie under the force N_Ed (N, one tie) and, when known,
/// the rod's elongation demand (m).
std::vector<TieCheckRow> tie_checks(const Tie& tie, double N_Ed, std::optional<double> elongation_demand);

}  // namespace assess
