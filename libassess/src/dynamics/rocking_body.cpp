// rocking_body.cpp: rigid rocking body per unit depth.
//
// Notation (research notes rocking.md §0, seed paper Eq. 1):
//   W      weight per unit depth (N/m)         b      half base width (m)
//   R      toe-centroid distance (m)           alpha  slenderness angle atan(x_G/z_G) (rad)
//   I0     inertia about the toe (kg m^2/m)    p      sqrt(W R / I0) (rad/s), §1.1
#include "assess/dynamics/rocking_body.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <string>

namespace assess {
namespace {

void require_positive(double v, const char* field, const char* unit) {
  if (!(std::isfinite(v) && v > 0.0))
    throw InputError(std::string(field) + " must be a positive number (" + unit + "), got " +
                     std::to_string(v));
}

}  // namespace

RockingBody RockingBody::rectangle(double thickness_m, double height_m, double unit_weight_N_m3) {
  require_positive(thickness_m, "thickness", "m");
  require_positive(height_m, "height", "m");
  require_positive(unit_weight_N_m3, "unit weight", "N/m^3");
  const double b = 0.5 * thickness_m;
  const double h = 0.5 * height_m;
  RockingBody body;
  body.W = unit_weight_N_m3 * thickness_m * height_m;
  body.b = b;
  body.R = std::hypot(b, h);
  body.alpha = std::atan2(b, h);
  body.I0 = 4.0 / 3.0 * (body.W / units::g) * body.R * body.R;  // rectangle about a corner
  return body;
}

RockingBody RockingBody::from_centroid(double weight_N_m, double x_G_m, double z_G_m,
                                       double I0_kg_m, double half_base_m, double M_ext_N) {
  RockingBody body;
  body.W = weight_N_m;
  body.b = half_base_m;
  body.R = std::hypot(x_G_m, z_G_m);
  body.alpha = std::atan2(x_G_m, z_G_m);
  body.I0 = I0_kg_m;
  body.M_ext = M_ext_N;
  require_positive(x_G_m, "centroid distance from the toe x_G", "m");
  require_positive(z_G_m, "centroid height z_G", "m");
  body.validate();
  return body;
}

double RockingBody::mass() const { return W / units::g; }
double RockingBody::x_G() const { return R * std::sin(alpha); }
double RockingBody::z_G() const { return R * std::cos(alpha); }
double RockingBody::p() const { return std::sqrt(W * R / I0); }

void RockingBody::validate() const {
  require_positive(W, "weight W", "N/m");
  require_positive(b, "half base width b", "m");
  require_positive(R, "toe-centroid distance R", "m");
  if (!(std::isfinite(alpha) && alpha > 0.0 && alpha < 0.5 * units::pi))
    throw InputError("slenderness angle alpha must be in (0, pi/2) rad, got " + std::to_string(alpha));
  require_positive(I0, "moment of inertia about the toe I0", "kg m^2/m");
  // Parallel-axis theorem: I0 = I_G + m R^2 >= m R^2.
  if (I0 < mass() * R * R * (1.0 - 1e-12))
    throw InputError("moment of inertia about the toe I0 (kg m^2/m) must be at least (W/g) R^2 = " +
                     std::to_string(mass() * R * R));
  if (!std::isfinite(M_ext)) throw InputError("external moment M_ext (N m/m) must be finite");
}

}  // namespace assess
