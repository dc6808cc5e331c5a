// tie_checks.hpp: the strengths and checks of a tie (issues 23, 29), each
// with its clause or source (docs/theory/ties.md §3; constants and their
// certainty in kinematic/tie_catalogue.hpp):
//   rod yield            N_pl,Rd = A fyk / gamma_M0                 NTC 2018 §4.2.4.1.2 [4.2.6]
//   threaded end         N_t,Rd = 0.9 ftk A_res / gamma_M2          NTC 2018 §4.2.8.1.1
//   local compression    N_c,Rd = beta fm / (FC gamma_M) A_b        designer's assumption (practice)
//   punching of masonry  N_p,Rd = tau / (FC gamma_M) s (2(a + b) + 4 s tan 45)  designer's assumption (practice)
//   anchor bending       plate: cantilever strips from the nut; bar: simply supported  designer's assumption
// and the capacity design (gerarchia delle resistenze): the tie is ductile
// when every brittle capacity (thread, local compression, punching, anchor)
// is at least gamma_Rd gamma_ov A fyk; otherwise it must stay elastic and
// every component is checked against the largest force it develops.
#pragma once

#include "assess/kinematic/tie.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// The design strengths of one tie (N), the weakest, and its ductility.
struct TieResistance {
  double rod = 0.0;              ///< N_pl,Rd: gross section yield (N)
  double thread = 0.0;           ///< N_t,Rd: rupture of the threaded end (N)
  double bearing = 0.0;          ///< local compression under the anchor (N)
  double punching = 0.0;         ///< punching of the masonry wedge (N)
  double anchor_bending = 0.0;   ///< bending of the plate or bar (N)
  double design = 0.0;           ///< min of the above: T_Rd (N)
  std::string governing;         ///< "rod" | "thread" | "bearing" | "punching" | "anchor bending"
  /// Capacity design: R_fy = A fyk (N) and the demand on the brittle
  /// components of a ductile tie, gamma_Rd gamma_ov R_fy (N).
  double yield_force = 0.0;
  double hierarchy_demand = 0.0;
  bool ductile = false;          ///< every brittle capacity >= hierarchy_demand
  std::string weakest_brittle;   ///< the brittle component of the smallest capacity
  double weakest_brittle_capacity = 0.0;  ///< N
  double fd = 0.0;               ///< masonry design compressive strength fm / (FC gamma_M) (Pa)
  double fvd = 0.0;              ///< masonry design shear strength tau / (FC gamma_M) (Pa)
  double bearing_area = 0.0;     ///< m^2
  double punching_area = 0.0;    ///< lateral area of the wedge s (2(a + b) + 4 s) (m^2)
  double cantilever = 0.0;       ///< plate: c = (max(a, b) - s_nut) / 2 (m); 0 for a bar
  double stiffness = 0.0;        ///< E A / L of one tie (N/m)
  double yield_elongation = 0.0; ///< (T_Rd - P0) / (E A / L): elongation at the tie's strength (m)
  double ultimate_elongation = 0.0;  ///< ductile: eps_ud L, eps_ud = 0.9 A of the grade (m); else = yield_elongation
};
/// @throws InputError (Tie::validate) for a tie out of its bounds or a pretension above T_Rd.
TieResistance tie_resistance(const Tie& tie);

/// The restraint of a tie level on a chain of out-of-plane length `length`
/// (m): count = length / spacing (ties on the chain, -), capacity = count x
/// T_Rd, the level's ductility and failure elongation.
TieRestraint tie_restraint(const Tie& tie, int block, double length);

/// What a tie develops in the analyses (one tie; N, m), the demand of its checks.
struct TieDemand {
  double static_force = 0.0;   ///< the largest force the kinematic checks need (N)
  bool reachable = true;       ///< false: some check needs a force no tie can give (the reason below)
  std::string unreachable;     ///< which check, and why
  std::optional<double> curve_force;    ///< force at the largest displacement demand on the capacity curve (N)
  std::optional<double> dynamic_force;  ///< the largest force of the dynamic analyses (N)
  std::optional<double> elongation;     ///< the largest elongation (m): dynamic, else at the displacement demand
  int dynamic_runs = 0;                 ///< dynamic analyses of the tie's state
  int dynamic_breaks = 0;               ///< of which the tie broke in (issue 29: a failure of the tie)
  std::string dynamic_component;        ///< how it broke first ("thread", "punching", ..., "elongation")
  /// The force the checks of a tie that must stay elastic take: the largest of the above (N).
  double elastic_demand() const;
};

/// One check of a tie: demand, capacity, D/C = demand / capacity.
struct TieCheckRow {
  /// "rod yield", "thread", "local compression", "punching", "anchor bending",
  /// "hierarchy thread" (...: the capacity design of a ductile tie), "rod
  /// elongation", "cone spacing", "edge distance", "required force" (a force
  /// no tie can give), "dynamic rupture" (unit "analyses": demand = analyses
  /// in which the tie broke, capacity 0).
  std::string check;
  std::string clause;   ///< clause or source (no certainty tag: the readings are listed apart)
  std::string formula;  ///< the capacity, in symbols
  double demand = 0.0;
  double capacity = 0.0;
  std::string unit;     ///< "kN" | "mm" | "m" | "analyses" (as printed; values are SI: N, m)
  double dc = 0.0;      ///< 0 when not reachable
  bool satisfied = false;
  bool reachable = true;  ///< false: the demand is a force no tie can give ("non raggiungibile")
};

/// The checks of one tie under its demand: a ductile tie (capacity design
/// satisfied) checks the rod against the force the checks need, every brittle
/// component against gamma_Rd gamma_ov A fyk and the elongation against
/// eps_ud L; a tie that is not ductile checks every component against the
/// largest force it develops. Both check the layout (the punching wedges of
/// adjacent ties apart, the first and last inside the wall).
std::vector<TieCheckRow> tie_checks(const Tie& tie, const TieDemand& demand);

}  // namespace assess
