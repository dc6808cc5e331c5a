// units.hpp: the unit conventions of libassess.
//
// Inside the library every quantity is SI: m, s, N, kg, rad, Pa, J. Values in
// other units cross the interface only with a suffix naming the unit
// (ag_g, theta_deg, damping_pct) and are converted at the edges, by
// multiplying with the factors below, e.g. `ag_g * units::g`.
#pragma once

namespace assess::units {

/// Acceleration of gravity used by the code formulas (m/s^2). NTC 2018
/// §3.2.3.2.3 converts Se from g to m/s^2 with g = 9.81 m/s^2, and the
/// Circolare's worked values use it too; libassess uses it for every
/// conversion of spectral values and for the weight/mass relation m = W/g.
inline constexpr double g = 9.81;

/// Standard gravity g_n (m/s^2, CGPM 1901). Accelerograms stored "in g"
/// (PEER AT2) and the cm/s^2 -> g conversions of strong-motion databases use
/// it; record readers convert with this factor, nothing else does.
inline constexpr double g_n = 9.80665;

inline constexpr double pi = 3.14159265358979323846;
inline constexpr double deg = pi / 180.0;  ///< one degree in rad
inline constexpr double kN = 1000.0;       ///< one kilonewton in N
inline constexpr double kPa = 1000.0;      ///< one kilopascal in Pa
inline constexpr double cm = 0.01;         ///< one centimetre in m
inline constexpr double percent = 0.01;    ///< 1 % as a fraction
inline constexpr double tonne = 1000.0;    ///< 1 t = 1 kN s^2/m, in kg

}  // namespace assess::units
