// free_wall_capacity.cpp: closed-form capacity curve of a free-standing
// rectangular wall (seed paper Lipo & de Felice 2017, Eq. 2-8; Circ. 2009
// C8A.4, Circ. 2019 C8.7.1.2.1).
//
// Notation (code name -> symbol):
//   b, h      half-thickness b, half-height h of the wall (thickness t = 2b, height H = 2h)
//   alpha0    load multiplier that activates rotation about the toe, alpha0 = b/h
//   e_star    e* = g M* / sum P_i
//   a0_star   a0* = alpha0 sum P_i / (M* FC) = alpha0 g / (e* FC)            (Eq. 3)
//   d0_star   d0*: spectral displacement at which alpha vanishes             (Eq. 2, 5)
//   du_star   du* = 0.4 d0*, ds_star = ds* = 0.4 du*                         (C8.7.1.2.1.7)
//   as_star   as* = a0* (1 - ds*/d0*), Ts = 2 pi sqrt(ds*/as*)               (C8.7.1.2.1.7)
//
// Derivation. The wall is a column of elementary weights dP = gamma t dz, whose
// virtual horizontal displacement for a rotation dtheta about the toe is
// delta_x(z) = z dtheta. Eq. 4 gives
//   M* = (int z dP)^2 / (g int z^2 dP) = (gamma t H^2/2)^2 / (g gamma t H^3/3) = (3/4) W/g,
// so e* = 3/4 (a single lumped weight at the centroid would give e* = 1).
// With the control point at the centroid (delta_x,k = h dtheta), Eq. 5 gives
//   d* = d_k (int z^2 dP) / (delta_x,k int z dP) = d_k (H^3/3) / (h H^2/2) = (4/3) d_k,
// and d_k vanishes the multiplier when the centroid is above the toe,
// d_k0 = b (linearised Eq. 2), hence d0* = (4/3) b = 2t/3.
#include "assess/kinematic/free_wall_capacity.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>
#include <string>

namespace assess {

FreeWallCapacity free_wall_capacity(double b_m, double h_m, double FC) {
  if (!(b_m > 0.0) || !std::isfinite(b_m))
    throw InputError("wall half-thickness b must be a positive length (m), got " + std::to_string(b_m));
  if (!(h_m > b_m) || !std::isfinite(h_m))
    throw InputError("wall half-height h must be a length (m) larger than b, got " + std::to_string(h_m));
  if (!(FC >= 1.0) || !std::isfinite(FC))
    throw InputError("confidence factor FC must be >= 1, got " + std::to_string(FC));
  FreeWallCapacity c;
  c.alpha0 = b_m / h_m;                                   // Eq. 2: W b = alpha0 W h
  c.e_star = 0.75;                                        // Eq. 4, distributed mass
  c.a0_star = c.alpha0 * units::g / (c.e_star * FC);      // Eq. 3
  c.d0_star = 4.0 / 3.0 * b_m;                            // Eq. 5 with d_k0 = b
  c.du_star = 0.4 * c.d0_star;                            // C8.7.1.2.1.7
  c.ds_star = 0.4 * c.du_star;                            // C8.7.1.2.1.7
  c.as_star = c.a0_star * (1.0 - c.ds_star / c.d0_star);  // linear capacity curve, Eq. 2
  c.Ts = 2.0 * units::pi * std::sqrt(c.ds_star / c.as_star);
  return c;
}

CodeRatios code_ratios(const FreeWallCapacity& cap, double pga_m_s2, double SDe_m) {
  return CodeRatios{pga_m_s2 / (2.0 * cap.a0_star),  // Eq. 8 left (Eq. 6, S = 1, q = 2)
                    SDe_m / cap.du_star};             // Eq. 8 right (Eq. 7)
}

}  // namespace assess
