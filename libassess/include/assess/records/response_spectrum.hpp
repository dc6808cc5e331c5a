// response_spectrum.hpp: elastic response of a linear SDOF oscillator to a
// piecewise-linear accelerogram by the exact recurrence of Nigam & Jennings
// (1969), and the elastic response spectra of a record.
#pragma once

#include "assess/records/record.hpp"

#include <vector>

namespace assess {

/// Settings of the SDOF response computation.
struct ResponseOptions {
  /// Viscous damping ratio xi as a FRACTION of critical (0.05 = 5 %), >= 0.
  /// Over-damped values (>= 1) are accepted: the propagator is exact for any xi.
  double damping_ratio = 0.05;
  /// The record step is split into equal sub-steps so that each is at most
  /// T / min_steps_per_period (>= 1). The excitation is linear inside a record
  /// step, so sub-stepping is exact; it only refines where the peaks are
  /// sampled. Peaks of u are further refined between sub-steps by cubic
  /// Hermite interpolation of (u, v), relative error O((w h)^4): about 2e-5
  /// at 20 steps per period (measured on El Centro at T = 0.1 s). SV and SA
  /// are maxima over the sub-steps (error <= 1 - cos(pi/20) = 1.2 %).
  int min_steps_per_period = 20;

  /// Throws InputError naming the field when a value is out of range.
  void validate() const;
};

/// Precomputed exact recurrence for one (T, xi, h): with p = -ag (m/s^2),
///   u1 = a_uu u0 + a_uv v0 + a_up0 p0 + a_up1 p1
///   v1 = a_vu u0 + a_vv v0 + a_vp0 p0 + a_vp1 p1
/// Nigam & Jennings (1969) eq. 23-24; Chopra, Dynamics of Structures §5.2,
/// Tab. 5.2.1 (there A, B, C, D and A', B', C', D', with p/k).
struct SdofRecurrence {
  double a_uu = 1, a_uv = 0, a_up0 = 0, a_up1 = 0;  ///< -, s, s^2, s^2
  double a_vu = 0, a_vv = 1, a_vp0 = 0, a_vp1 = 0;  ///< 1/s, -, s, s
};

/// The exact recurrence coefficients for period T (s) > 0, damping ratio xi
/// (fraction) >= 0 and step h (s) > 0. Computed as the exponential of the
/// augmented state matrix (scaling and squaring of its Taylor series), which
/// is the exact propagator of the piecewise-linear excitation and stays
/// accurate both for omega*h -> 0 (very long T) and omega*h >> 1 (T -> 0).
SdofRecurrence sdof_recurrence(double T, double damping_ratio, double h);

/// Relative response history of an SDOF oscillator at the record samples.
struct SdofHistory {
  std::vector<double> u;  ///< relative displacement (m)
  std::vector<double> v;  ///< relative velocity (m/s)
  std::vector<double> a_abs;  ///< absolute acceleration u'' + ag (m/s^2)
};

/// Response u'' + 2 xi w u' + w^2 u = -ag(t), at rest at t = 0, at the record
/// samples t_i = i dt (no sub-stepping). @param T period (s) > 0
SdofHistory sdof_response(const Record& record, double T, double damping_ratio);

/// Spectral ordinates of one record at one period.
struct SpectralOrdinates {
  double T = 0.0;    ///< period (s)
  double SD = 0.0;   ///< max |u| (m)
  double SV = 0.0;   ///< max |v| sampled at sub-steps (m/s)
  double PSA = 0.0;  ///< pseudo-acceleration w^2 SD (m/s^2); PGA at T = 0
  double PSV = 0.0;  ///< pseudo-velocity w SD (m/s)
  double SA = 0.0;   ///< max absolute acceleration sampled at sub-steps (m/s^2)
};

/// Elastic response spectra of a record on a period grid.
struct ResponseSpectrum {
  double damping_ratio = 0.05;  ///< xi (fraction)
  std::vector<SpectralOrdinates> ordinates;  ///< one per period, in input order

  std::vector<double> periods() const;  ///< s
  std::vector<double> psa() const;      ///< m/s^2
  std::vector<double> sd() const;       ///< m
};

/// Spectral ordinates at one period T (s) >= 0. T = 0 is the rigid
/// oscillator: SD = SV = 0, PSA = SA = PGA. The peaks are taken over the
/// record duration (no free-vibration tail; see docs/theory/record-selection.md).
SpectralOrdinates spectral_ordinates(const Record& record, double T,
                                     const ResponseOptions& opts = {});

/// Spectra at every period of `periods` (s, each >= 0, any order).
ResponseSpectrum response_spectrum(const Record& record, const std::vector<double>& periods,
                                   const ResponseOptions& opts = {});

/// n periods log-spaced from T_min to T_max (s), 0 < T_min < T_max, n >= 2.
std::vector<double> log_spaced_periods(double T_min, double T_max, int n);

}  // namespace assess
