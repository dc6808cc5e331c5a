// free_wall_capacity.hpp: the seed's Eq. 2-8 for a free-standing rectangular
// wall overturning about its toe (linear and non-linear kinematic analysis of
// Circ. 2009/2019 C8A.4 / C8.7.1.2.1), in closed form.
//
// This is a stand-in for the general kinematic engine: the campaigns call it
// through one function so it can be swapped for the kinematic-chain analysis.
#pragma once

namespace assess {

/// Capacity curve of a free-standing rectangular wall of thickness 2b and
/// height 2h rocking about its toe, with the mass distributed over the wall
/// (one column of elementary weights) and the control point at the centroid.
struct FreeWallCapacity {
  double alpha0 = 0.0;   ///< activation multiplier alpha0 = b/h (-), seed Eq. 2
  double e_star = 0.0;   ///< participating mass fraction e* = g M* / sum P = 3/4 (-), seed Eq. 4
  double a0_star = 0.0;  ///< spectral activation acceleration a0* (m/s^2), seed Eq. 3
  double d0_star = 0.0;  ///< spectral displacement where alpha vanishes d0* (m), seed Eq. 5
  double du_star = 0.0;  ///< ultimate spectral displacement du* = 0.4 d0* (m), C8.7.1.2.1.7
  double ds_star = 0.0;  ///< secant displacement ds* = 0.4 du* (m), C8.7.1.2.1.7
  double as_star = 0.0;  ///< secant acceleration as* = a0* (1 - ds*/d0*) (m/s^2)
  double Ts = 0.0;       ///< secant period Ts = 2 pi sqrt(ds*/as*) (s)
};

/// The seed's Eq. 2-7 for a free-standing rectangular wall.
/// @param b_m  half-thickness b (m), > 0
/// @param h_m  half-height h (m), > b
/// @param FC   confidence factor (-), >= 1 (the seed's parametric study: 1)
/// @throws InputError naming the invalid argument
FreeWallCapacity free_wall_capacity(double b_m, double h_m, double FC = 1.0);

/// The seed's Eq. 8 demand/capacity ratios of the code checks.
struct CodeRatios {
  double strength = 0.0;      ///< PGA / (2 a0*) (-): Eq. 6 with S = 1, q = 2
  double displacement = 0.0;  ///< SDe(Ts) / du* (-): Eq. 7
};

/// @param cap      capacity of the wall
/// @param pga_m_s2 peak ground acceleration of the record as applied (m/s^2)
/// @param SDe_m    5 % elastic displacement spectrum of that record at cap.Ts (m)
CodeRatios code_ratios(const FreeWallCapacity& cap, double pga_m_s2, double SDe_m);

}  // namespace assess
