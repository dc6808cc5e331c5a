// tie_checks.hpp: the strengths and checks of a tie (issues 23, 29, 37), each
// with its clause or source (docs/theory/ties.md §3; constants and their
// certainty in kinematic/tie_catalogue.hpp):
//   rod yield            N_pl,Rd = A_c fyk / gamma_M0                NTC 2018 §4.2.4.1.2 [4.2.6]
//   threaded end         N_t,Rd = 0.9 ftk A_res,c / gamma_M2         NTC 2018 §4.2.8.1.1
//     (A_c, A_res,c: the sections after the corrosion allowance, EN 1993-5 §4.4)
//   local compression    N_c,Rd = beta fm / (FC gamma_M) A_b         designer's assumption (practice)
//   punching of masonry  N_p,Rd = tau / (FC gamma_M) A_p,  A_p = integral over the depth of the wedge's
//                        lateral boundary that lies in masonry (the 45 degree wedge cut by the crown,
//                        the wall's ends, its openings and the adjacent wedges)  practice, issue 37
//   sliding              N_s,Rd = f_vd A_sides + (f_v0 / (FC gamma_M) + mu sigma_n / gamma_M) A_base: the
//                        masonry above the anchor's lower edge sliding on that bed joint  Eng. Struct. 2016, issue 37
//   anchor bending       plate: cantilever strips from the nut; bar: simply supported  designer's assumption
// and the capacity design (gerarchia delle resistenze): the tie is ductile
// when its ends are upset or welded and every brittle capacity (thread,
// local compression, punching, sliding, anchor) is at least gamma_Rd gamma_ov
// A fyk; a ductile rod yields up to eps_ud L (the grade's uniform elongation);
// otherwise it must stay elastic and every component is checked against the
// largest force it develops. The temperature action on the restrained rod is
// checked in the fundamental combination (NTC 2018 §2.5.3), and a new tie's
// pretension must take up the temperature range.
#pragma once

#include "assess/kinematic/tie.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// The punched wedge and the sliding block of one tie of a level (issue 37;
/// docs/theory/ties.md §3.1-3.2), in the wall's elevation: x along the wall,
/// z up; y the depth through the thickness s from the outer face. At depth y
/// the wedge is the rectangle [x - w/2 - y, x + w/2 + y] x [z - h/2 - y,
/// z + h/2 + y] (45 degrees from the anchor's edges, w x h its footprint); the
/// tie owns the strip [x_lo, x_hi] of the wall between the midpoints to its
/// neighbours (or the wall's ends): the part of each edge of the rectangle that
/// lies in masonry (inside the strip, between the wall's base and crown, off
/// every opening) is a shear surface. The lateral area is the integral of that
/// length over y in [0, s] (exact: the length is piecewise linear in y and is
/// integrated by two-point Gauss between its breakpoints).
struct AnchorWedge {
  int tie = 0;                  ///< index of the tie along the level (0 = the first)
  double x = 0.0;               ///< its position along the wall (m)
  double x_lo = 0.0, x_hi = 0.0;  ///< the strip it owns (m)
  double area = 0.0;            ///< lateral area of the wedge in masonry (m^2)
  double full_area = 0.0;       ///< the same uncut: s (2 (w + h) + 4 s) (m^2)
  // Sliding of the masonry above the anchor's lower edge z_b = z - h/2 on
  // that bed joint: the block spreads at 45 degrees through the thickness as
  // the wedge does, up to the crown (or the first opening above the anchor).
  double block_top = 0.0;       ///< z of the top of the sliding block (m)
  double side_area = 0.0;       ///< its two lateral faces in masonry, integrated over the depth (m^2)
  double base_area = 0.0;       ///< its base on the bed joint, in masonry (m^2)
  double sigma_n = 0.0;         ///< overburden on the base (Pa): unit weight x height (+ crown load / s)
};
/// The wedge of tie j (0 .. count - 1) of the level.
AnchorWedge anchor_wedge(const Tie& tie, int j);

/// The design strengths of one tie (N), the weakest, and its ductility.
struct TieResistance {
  double rod = 0.0;              ///< N_pl,Rd: gross section yield, corroded section (N)
  double thread = 0.0;           ///< N_t,Rd: rupture of the threaded end, corroded section (N)
  double bearing = 0.0;          ///< local compression under the anchor (N)
  double punching = 0.0;         ///< punching of the masonry wedge, the weakest tie of the level (N)
  double sliding = 0.0;          ///< sliding of the masonry above the anchor, the weakest tie (N; infinity: no crown)
  double anchor_bending = 0.0;   ///< bending of the plate or bar (N)
  double design = 0.0;           ///< min of the above: T_Rd (N)
  std::string governing;         ///< "rod" | "thread" | "bearing" | "punching" | "sliding" | "anchor bending"
  /// Capacity design: R_fy = A fyk (N, the gross section: the rod as it may be
  /// delivered, uncorroded) and the demand on the brittle components of a
  /// ductile tie, gamma_Rd gamma_ov R_fy (N).
  double yield_force = 0.0;
  double hierarchy_demand = 0.0;
  bool ductile = false;          ///< upset or welded ends and every brittle capacity >= hierarchy_demand
  std::string weakest_brittle;   ///< the brittle component of the smallest capacity
  double weakest_brittle_capacity = 0.0;  ///< N
  double fd = 0.0;               ///< masonry design compressive strength fm / (FC gamma_M) (Pa)
  double fvd = 0.0;              ///< masonry design shear strength tau / (FC gamma_M) (Pa)
  double fv0d = 0.0;             ///< cohesion of the bed joint fv0 / (FC gamma_M) (Pa)
  double sliding_strength = 0.0; ///< fv0d + mu sigma_n / gamma_M on the sliding tie's base (Pa)
  double bearing_area = 0.0;     ///< m^2
  AnchorWedge wedge;             ///< the wedge of the tie of the smallest punching strength
  AnchorWedge slide;             ///< the sliding block of the tie of the smallest sliding strength
  double punching_area = 0.0;    ///< = wedge.area (m^2)
  double cantilever = 0.0;       ///< plate: c = (max(a, b) - s_nut) / 2 (m); 0 for a bar
  double area_c = 0.0;           ///< rod section after the corrosion allowance (m^2)
  double thread_area_c = 0.0;    ///< thread stress section after the corrosion allowance (m^2)
  double stiffness = 0.0;        ///< E A / L of one tie (N/m)
  double yield_elongation = 0.0; ///< (T_Rd - P0) / (E A / L): elongation at the tie's strength (m)
  double eps_ud = 0.0;           ///< design uniform elongation 0.9 eps_uk (ductile; 0 otherwise)
  double ultimate_elongation = 0.0;  ///< ductile: max(eps_ud L, yield); else = yield_elongation (m)
  double thermal_force = 0.0;    ///< E A alpha_T dT: the force of the restrained rod cooled by dT (N)
  double temperature_demand = 0.0;  ///< gamma_P P0 + gamma_Q E A alpha_T dT (N)
};
/// @throws InputError (Tie::validate) for a tie out of its bounds or a pretension above T_Rd.
TieResistance tie_resistance(const Tie& tie);

/// The pretension that takes up the temperature range of a new tie (N):
/// E A alpha_T dT, rounded up to 0.1 kN (issue 37).
double thermal_pretension(const Tie& tie);

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
  /// "rod yield", "thread", "local compression", "punching", "sliding",
  /// "anchor bending", "hierarchy thread" (...: the capacity design of a
  /// ductile tie), "rod elongation", "temperature rod", "temperature thread"
  /// (the fundamental combination), "pretension" (a new tie's pretension
  /// against E A alpha_T dT), "required force" (a force no tie can give),
  /// "dynamic rupture" (unit "analyses": demand = analyses in which the tie
  /// broke, capacity 0).
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
/// largest force it develops. Both check the rod and thread under the
/// temperature action; a new tie checks its pretension against it.
std::vector<TieCheckRow> tie_checks(const Tie& tie, const TieDemand& demand);

}  // namespace assess
