// code_rules.hpp: every code constant and every recalled rule used by the
// kinematic checks of local mechanisms, in ONE place, each with its clause and
// certainty tag (see docs/theory/kinematic.md, "Certainty of the rules").
//
// Tags: [V-T] seen in a transcription of the official text; [V-S] seen in a
// secondary source; [R] recalled, not verified: correct it HERE if the
// official text says otherwise; [I] an interpretation of ours.
//
// NTC 2008 = DM 14/01/2008 with Circolare 617/2009 §C8A.4;
// NTC 2018 = DM 17/01/2018 with Circolare 7/2019 §C8.7.1 and §C7.2.3.
#pragma once

#include "assess/support/error.hpp"

#include <cmath>
#include <string>

namespace assess::code_rules {

/// Knowledge level (livello di conoscenza) of the building.
enum class KnowledgeLevel { LC1, LC2, LC3 };

/// Confidence factor FC by knowledge level: LC1 1.35, LC2 1.20, LC3 1.00.
/// Circ. 617/2009 Tab. C8A.1.1 (masonry) [R]; Circ. 2019 Tab. C8.5.IV (RC and
/// steel) [V-T]; the same values are used for masonry [R].
inline double confidence_factor(KnowledgeLevel lc) {
  switch (lc) {
    case KnowledgeLevel::LC1: return 1.35;
    case KnowledgeLevel::LC2: return 1.20;
    case KnowledgeLevel::LC3: return 1.00;
  }
  return 1.35;
}

/// Behaviour factor of the linear (strength) SLV check of a local mechanism:
/// q = 2.0. Circ. 617/2009 C8A.4.9-10 [R]; Circ. 2019 §C8.7.1.2.1.7 "q = 2
/// unless better evaluated" [V-T].
inline constexpr double q_local_mechanism = 2.0;

/// NTC 2008: ultimate spectral displacement du* = 0.4 d0* (C8A.4, §6) [R].
inline constexpr double du_over_d0_2008 = 0.4;
/// NTC 2008: secant-period displacement ds* = 0.4 du* (C8A.4, §6) [R].
inline constexpr double ds_over_du_2008 = 0.4;

/// NTC 2018: d_SLV = 0.40 d0 (Circ. 2019 §C8.7.1.2.1.6) [V-T].
inline constexpr double dSLV_over_d0_2018 = 0.40;
/// NTC 2018: d_SLC = 0.60 d0 (Circ. 2019 §C8.7.1.2.1.6) [V-T].
inline constexpr double dSLC_over_d0_2018 = 0.60;
/// NTC 2018: T_SLV = 1.68 pi sqrt(d_SLV / a(d_SLV)) [C8.7.1.10] [V-T].
inline constexpr double T_SLV_factor_of_pi = 1.68;
/// NTC 2018: T_SLC = 1.56 pi sqrt(d_SLC / a(d_SLC)) [C8.7.1.11] [V-T].
inline constexpr double T_SLC_factor_of_pi = 1.56;

/// Damping of the local mechanism, "in the absence of more accurate
/// evaluations" (Circ. 2019 §C8.7.1.2.1.8) [V-T]: 8 % at SLV, 10 % at SLC.
/// libassess applies them to the displacement demand at ground level and at
/// height [I] (docs/theory/kinematic.md).
inline constexpr double mechanism_damping_SLV_pct = 8.0;
inline constexpr double mechanism_damping_SLC_pct = 10.0;
/// Damping of the building's first mode when not given (%) [I]: 5 %.
inline constexpr double building_damping_default_pct = 5.0;

/// Period of the building T1 = C1 H^(3/4) (s), NTC 2008 §7.3.3.2 [7.3.5],
/// C1 = 0.050 for masonry [R]; repeated by Circ. 2019 [R].
inline constexpr double C1_masonry = 0.050;
/// @param H height of the building above the foundation (m), > 0
inline double T1_simplified(double H) { return C1_masonry * std::pow(H, 0.75); }

/// Modal participation factor of the first mode, uniform mass and linear mode
/// shape normalised to 1 at the top: gamma = 3N/(2N+1), N storeys.
/// Circ. 617/2009 C8A.4.10 [R]; Circ. 2019 [C7.2.10] [V-T].
inline double gamma_first_mode(int storeys) { return 3.0 * storeys / (2.0 * storeys + 1.0); }
/// First mode shape psi(Z) = Z/H (-) [R].
/// @param Z height of the constraint centroid above the foundation (m); @param H (m)
inline double psi_first_mode(double Z, double H) { return Z / H; }

/// Floor spectrum shape constants a = 0.8, b = 1.1 (Circ. 2019 [C7.2.6]) [V-T].
inline constexpr double floor_spectrum_a = 0.8;
inline constexpr double floor_spectrum_b = 1.1;
/// Plateau amplification of the floor spectrum 1.1 xi_k^-0.5 eta(xi) [C7.2.6]
/// [V-T], with xi_k the building damping as a FRACTION (0.05 -> 4.92) [I]: with
/// xi_k in percent the "amplification" would be 0.49 < 1, which is not physical.
/// @param building_damping_pct xi_k (%); @param eta eta(xi) of the element (-)
inline double floor_amplification(double building_damping_pct, double eta) {
  return 1.1 / std::sqrt(building_damping_pct / 100.0) * eta;
}
/// Damping correction of the floor acceleration sqrt(1 + 0.0004 xi_k^2),
/// xi_k in percent [C7.2.7] [V-T].
inline double floor_damping_correction(double building_damping_pct) {
  return std::sqrt(1.0 + 0.0004 * building_damping_pct * building_damping_pct);
}

/// NTC 2008 non-linear check at height [C8A.4.12] [R]: demand
/// SDe(T1) psi gamma (Ts/T1)^2 / sqrt((1 - Ts/T1)^2 + 0.02 Ts/T1) (m).
/// @param SDe_T1 SDe(T1) (m); @param psi, gamma (-); @param Ts, T1 (s)
inline double demand_at_height_2008(double SDe_T1, double psi, double gamma, double Ts, double T1) {
  const double r = Ts / T1;
  return SDe_T1 * psi * gamma * r * r / std::sqrt((1.0 - r) * (1.0 - r) + 0.02 * r);
}

/// NTC 2008: at-height mechanisms must satisfy the ground-level check too
/// (C8A.4.9 with C8A.4.10 [V-S]; extended to C8A.4.11 with C8A.4.12 [I]).
inline constexpr bool height_also_checks_ground_2008 = true;

/// Number of time-history analyses and how their results combine (NTC 2018
/// §7.3.5, repeated for local mechanisms by Circ. 2019 C8.7.1.2.1.9 "in number
/// sufficient to give a significant mean response") [R: recalled, the
/// paragraph of §7.3.5 was not re-read]: with at least 7 groups of
/// accelerograms the mean of the results may be used, with 3 to 6 the most
/// unfavourable result; fewer than 3 cannot support a verdict.
inline constexpr int records_for_mean = 7;
inline constexpr int records_min = 3;
/// Spectrum compatibility of the records' mean (NTC 2018 §3.2.3.6): within
/// -10 % / +30 % of the elastic spectrum over the period range [V-T as in
/// record_selection's defaults].
inline constexpr double compatibility_lower_tol = 0.10;
inline constexpr double compatibility_upper_tol = 0.30;

/// Interlocking friction of the side walls (Circ. 2019 [C8.7.1.2]) [V-T as
/// transcribed]: F = 0.4 n (n+1) Phi mu l^2 t_s w (N), n = h/h_b, Phi = h_b/l.
/// @param h height of the interlocked wedge (m); @param h_b course height (m)
/// @param l length of the units (m); @param mu friction coefficient (-)
/// @param t_s thickness of the side wall (m); @param w unit weight (N/m^3)
inline double interlocking_friction(double h, double h_b, double l, double mu, double t_s,
                                    double w) {
  if (!(h > 0) || !(h_b > 0) || !(l > 0) || !(mu >= 0) || !(t_s > 0) || !(w >= 0))
    throw InputError("interlocking friction: h, h_b, l, t_s must be > 0 m, mu >= 0, w >= 0");
  const double n = h / h_b, Phi = h_b / l;
  return 0.4 * n * (n + 1.0) * Phi * mu * l * l * t_s * w;
}

}  // namespace assess::code_rules
