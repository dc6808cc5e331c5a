// roof_thrust.hpp: the loads a pitched roof puts on the wall that carries its
// rafters' feet (issue 33, "spinta della copertura"): the vertical reaction V
// and the horizontal thrust H per metre of wall, from the roof's load, its
// geometry and its structural scheme (docs/theory/mechanisms.md §3).
//
//   q    load per m^2 of roof plan (N/m^2): the seismic combination's G1 + G2 + psi2 Q
//   l    horizontal projection of the rafter from the wall's seat to the ridge (m)
//   phi  rafter angle from the horizontal (deg)
//   A-frame (rafters pinned at the ridge, no tie):   V = q l,    H = V / (2 tan phi)   [D]
//   strut (an axially loaded puntone on the seat):   V = q l,    H = V / tan phi       [D]
//   ridge beam carried by gables or trusses:         V = q l/2,  H = 0                 [D]
//   truss with a working tie (capriata):              V = q l,    H = 0                 [D]
// The thrust is a constant force: it does not scale with alpha (C8.7.1.2:
// thrusting struts among the causes of local mechanisms [V-T]).
#pragma once

#include <string>

namespace assess {

enum class RoofScheme { AFrame, Strut, RidgeBeam, Truss };

/// "a_frame", "strut", "ridge_beam", "truss".
std::string to_string(RoofScheme s);

struct RoofSpec {
  RoofScheme scheme = RoofScheme::AFrame;
  double load = 0.0;       ///< q (N/m^2 of plan), >= 0
  double span = 0.0;       ///< l (m), > 0
  double pitch_deg = 0.0;  ///< phi (deg), in (0, 90)
  /// Distance of the seat (the line of the rafters' reaction) from the wall's
  /// inner face (m), 0..thickness of the wall under it.
  double seat_from_inner_face = 0.0;
  /// Issue 38: the roof's mass is held by the rest of the building (its
  /// weight V bears on the wall, its mass does not push it); default false:
  /// the roof's mass moves with the wall it rests on (C8.7.1.1's Q weights,
  /// docs/theory/mechanisms.md §0).
  bool held = false;
  /// Throws InputError naming the field (with `where` as prefix).
  void validate(const std::string& where) const;
};

/// The roof's reaction on the wall per metre of wall (N/m).
struct RoofLoads {
  double V = 0.0;  ///< vertical, downward
  double H = 0.0;  ///< horizontal thrust, outward
};

/// V and H of the scheme (formulas above).
RoofLoads roof_loads(const RoofSpec& roof);
/// The formula of the scheme's thrust, for the reports ("H = V/(2 tan phi)").
std::string roof_thrust_formula(RoofScheme s);

}  // namespace assess
