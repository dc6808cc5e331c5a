// rocking_body.hpp: the rigid body of a rocking wall, per unit depth.
//
// Geometry about the toe O (the edge it rocks on, seed paper Fig. 1,
// research notes rocking.md §0): R is the distance toe-centroid, alpha the
// angle of OG from the vertical, b the half-width of the base, I0 the
// moment of inertia about the toe. x (horizontal) and theta are positive
// outward.
#pragma once

namespace assess {

/// Rigid rocking body per unit depth of wall (SI units).
struct RockingBody {
  double W = 0.0;      ///< weight per unit depth (N/m)
  double b = 0.0;      ///< half-width of the base (m)
  double R = 0.0;      ///< distance from the toe to the centroid (m)
  double alpha = 0.0;  ///< angle of the toe-centroid line from the vertical (rad)
  double I0 = 0.0;     ///< moment of inertia about the toe (kg m^2/m)
  double M_ext = 0.0;  ///< constant external moment about the toe, positive outward (N m/m)

  /// Rectangle of full thickness 2b and full height 2h:
  /// R = sqrt(b^2 + h^2), alpha = atan(b/h), I0 = 4/3 (W/g) R^2.
  /// @param thickness_m   full thickness 2b (m), > 0
  /// @param height_m      full height 2h (m), > 0
  /// @param unit_weight_N_m3 unit weight gamma (N/m^3), > 0
  /// @throws InputError naming the invalid field and its unit
  static RockingBody rectangle(double thickness_m, double height_m, double unit_weight_N_m3);

  /// General body (e.g. a kinematic chain with carried loads).
  /// @param weight_N_m   total weight per unit depth W (N/m), > 0
  /// @param x_G_m        horizontal distance of the centroid from the toe (m), > 0
  /// @param z_G_m        height of the centroid above the base (m), > 0
  /// @param I0_kg_m      moment of inertia about the toe (kg m^2/m), >= (W/g)(x_G^2 + z_G^2)
  /// @param half_base_m  half-width b of the base (m), > 0
  /// @param M_ext_N      constant external moment about the toe, positive outward (N m/m)
  static RockingBody from_centroid(double weight_N_m, double x_G_m, double z_G_m, double I0_kg_m,
                                   double half_base_m, double M_ext_N = 0.0);

  double mass() const;      ///< W/g (kg/m), g = units::g
  double x_G() const;       ///< R sin(alpha): horizontal toe-centroid distance (m)
  double z_G() const;       ///< R cos(alpha): height of the centroid (m)
  double p() const;         ///< frequency parameter sqrt(W R / I0) (rad/s)

  /// Throws InputError naming the first invalid field and its unit.
  void validate() const;
};

}  // namespace assess
