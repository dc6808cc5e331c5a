// friction_overturning.hpp: simple overturning of a façade held by the
// friction of its interlocking with the side walls (issue 33; "ribaltamento
// con ammorsamento / attrito delle pareti di spina"; the Casapulla family of
// models, docs/theory/mechanisms.md §2).
//
// The façade (height h above its hinge, thickness t, length L) turns about
// its outer base edge; its ends are toothed into the side walls (thickness b)
// through a running bond of units unit_length x course_height. Two limit
// mechanisms of the side walls, both candidates of the set, the lower
// governing (Circ. 2019 C8.7.1: the most unfavourable one):
//  - "friction": the façade slides out of the side walls: the bed joints at
//    the steps of the side walls' stepped crack (at alpha_b from the vertical,
//    tan alpha_b = (unit_length/2)/course_height) slide and resist by friction
//    (Argiento, Maione, Casapulla 2018, eqs. (5)-(6) [V-p], continuum form [D]):
//      F_g = f gamma b tan(alpha_b) h^2 / 2 at h/3,  F_q = f q tan(alpha_b) h at h/2
//    per side wall, times the activation kappa (1: every step slides, the
//    mechanism's own sliding; 0: none), lost once the façade has slipped by
//    the units' overlap unit_length/2 at the resultant's height;
//  - "wedge": the side walls' wedges bounded by the same crack turn with the
//    façade (composite overturning, no friction work).
// Each candidate reports alpha0 of the bare façade (no interlocking), of the
// frictional mechanism and of the wedge (before/after). A floor simply
// supported on the façade adds, when the building holds it, the friction of
// its seat mu_s P_s at its level (docs/theory/mechanisms.md §2.2).
#pragma once

#include "assess/kinematic/mechanism_catalogue.hpp"

#include <limits>
#include <optional>
#include <vector>

namespace assess {

/// A floor (or roof) simply supported on the façade, without anchors.
struct SupportedFloor {
  double weight = 0.0;                    ///< its reaction on the façade P_s (N), >= 0
  double z = 0.0;                         ///< level of the seat above the foundation (m)
  double distance_from_inner_face = 0.0;  ///< of the reaction (m), 0..thickness
  double friction = 0.0;                  ///< mu_s of the seat (-), >= 0
  /// true: the floor is held by the rest of the building (a diaphragm): its
  /// weight bears, its mass does not push, its seat's friction resists;
  /// false (issue 38, the default: every load moves with the block it rests
  /// on unless the case holds it): it moves with the façade (its mass
  /// pushes), no friction.
  bool held = false;
  /// The seat's length (m): past that slip the friction is lost.
  double seat_length = std::numeric_limits<double>::infinity();
};

struct FrictionOverturningParams {
  double height = 0.0;          ///< façade height above the hinge (m)
  double thickness = 0.0;       ///< façade thickness (m)
  double length = 0.0;          ///< façade width (m)
  double unit_weight = 0.0;     ///< N/m^3 (façade and side walls)
  double base_z = 0.0;          ///< hinge height above the foundation (m)
  int side_walls = 2;           ///< interlocked side walls (1 or 2)
  double side_thickness = 0.0;  ///< b (m)
  double side_length = 0.0;     ///< length of the side walls available to the crack (m)
  double unit_length = 0.0;     ///< the texture: unit length (m), > 0
  double course_height = 0.0;   ///< course height (m), > 0
  double friction = 0.0;        ///< f of the bed joints (-), > 0
  double activation = 1.0;      ///< kappa in [0, 1]
  /// q: vertical load per metre on top of each side wall over the crack's
  /// reach (floors and roof bearing on it) (N/m), >= 0. In the wedge
  /// candidate it rests on the wedges and moves with them (issue 38: its
  /// mass pushes, C8.7.1.1) unless `side_load_held`; in the frictional one
  /// the side walls stay and it only presses their steps.
  double side_load = 0.0;
  bool side_load_held = false;
  double top_weight = 0.0;      ///< roof or floor on the façade's top at mid-thickness (N), bearing
  bool top_weight_held = false; ///< issue 38: its mass held by the building (default: it pushes with the façade)
  double tie = 0.0;             ///< tie at the top (N)
  std::vector<SupportedFloor> floors;
};

/// The two candidates ("friction", "wedge"), type "friction_overturning".
MechanismSet friction_overturning(const FrictionOverturningParams& p);

/// Resultant of the side wall's frictional resistance (per side wall, kappa 1).
struct SideWallFriction {
  double tan_alpha = 0.0;  ///< tan alpha_b = (unit_length/2)/course_height (-)
  double reach = 0.0;      ///< of the crack at the top, min(h tan alpha_b, side_length) (m)
  double crack_height = 0.0;  ///< height over which the crack steps through the side wall (m)
  double F_g = 0.0, z_g = 0.0;  ///< from the masonry's weight (N), height above the hinge (m)
  double F_q = 0.0, z_q = 0.0;  ///< from the load q (N), height above the hinge (m)
};
SideWallFriction side_wall_friction(const FrictionOverturningParams& p);

}  // namespace assess
