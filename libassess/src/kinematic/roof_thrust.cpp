// roof_thrust.cpp: V and H of a pitched roof on its wall (issue 33;
// docs/theory/mechanisms.md §3.1). Notation in roof_thrust.hpp.
#include "assess/kinematic/roof_thrust.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>

namespace assess {

std::string to_string(RoofScheme s) {
  switch (s) {
    case RoofScheme::AFrame: return "a_frame";
    case RoofScheme::Strut: return "strut";
    case RoofScheme::RidgeBeam: return "ridge_beam";
    case RoofScheme::Truss: return "truss";
  }
  return "?";
}

void RoofSpec::validate(const std::string& where) const {
  if (!(load >= 0.0) || !std::isfinite(load)) throw InputError(where + "load must be >= 0 kN/m^2");
  if (!(span > 0.0) || !std::isfinite(span)) throw InputError(where + "span must be > 0 m");
  if (!(pitch_deg > 0.0 && pitch_deg < 90.0)) throw InputError(where + "pitch must lie in (0, 90) deg");
  if (!(seat_from_inner_face >= 0.0) || !std::isfinite(seat_from_inner_face))
    throw InputError(where + "seat distance from the inner face must be >= 0 m");
}

RoofLoads roof_loads(const RoofSpec& r) {
  const double ql = r.load * r.span, tp = std::tan(r.pitch_deg * units::deg);
  switch (r.scheme) {
    // Three-hinged A-frame: half the roof, moments about the ridge hinge
    // (rise l tan phi): H l tan(phi) = q l^2 / 2.
    case RoofScheme::AFrame: return {ql, ql / (2.0 * tp)};
    // A strut carries its load along its axis: H / V = 1 / tan(phi).
    case RoofScheme::Strut: return {ql, ql / tp};
    // Rafter simply supported on the seat and on a ridge beam: vertical reactions only.
    case RoofScheme::RidgeBeam: return {0.5 * ql, 0.0};
    // A truss with a working tie: its supports take no horizontal force.
    case RoofScheme::Truss: return {ql, 0.0};
  }
  return {};
}

std::string roof_thrust_formula(RoofScheme s) {
  switch (s) {
    case RoofScheme::AFrame: return "V = q·l, H = V/(2·tan φ)";
    case RoofScheme::Strut: return "V = q·l, H = V/tan φ";
    case RoofScheme::RidgeBeam: return "V = q·l/2, H = 0";
    case RoofScheme::Truss: return "V = q·l, H = 0";
  }
  return "";
}

}  // namespace assess
