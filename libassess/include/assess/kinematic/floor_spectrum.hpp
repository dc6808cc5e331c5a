// floor_spectrum.hpp: the acceleration spectrum at height z of a building,
// first mode only, Circ. 2019 §C7.2.3 [C7.2.5]-[C7.2.10].
#pragma once

#include "assess/hazard/hazard.hpp"
#include "assess/hazard/spectrum.hpp"

namespace assess {

/// The main structure seen by a local mechanism at height.
struct BuildingModel {
  double H = 0.0;        ///< height above the foundation (m), > 0
  int storeys = 1;       ///< N (-), >= 1
  double T1 = 0.0;       ///< first-mode period (s), > 0 (code_rules::T1_simplified)
  double damping_pct = 5.0;  ///< xi_1 of the building (%)
  void validate() const;     ///< throws InputError naming the field
};

/// S_eZ(T, xi, z) of Circ. 2019 [C7.2.5]-[C7.2.6] with the first mode
/// (gamma1 = 3N/(2N+1), psi1 = z/H [C7.2.10]) for one limit state's hazard.
class FloorSpectrum {
 public:
  /// @param hazard ag (g), F0, TC* (s) of the limit state
  /// @param site soil and topography
  /// @param building H (m), N, T1 (s), xi_1 (%)
  /// @param z height above the foundation (m), >= 0 (z > H: psi = z/H > 1, the first mode extended)
  /// @param element_damping_pct xi of the local mechanism (%)
  FloorSpectrum(const HazardParams& hazard, const SiteConditions& site, const BuildingModel& building,
                double z, double element_damping_pct);

  /// Peak floor acceleration a_Z (m/s^2) [C7.2.7]-[C7.2.8]:
  /// Se(T1, xi_1) |gamma1 psi1(z)| sqrt(1 + 0.0004 xi_1^2).
  double a_Z() const { return a_Z_; }
  /// Floor spectral acceleration S_eZ(T) (m/s^2) [C7.2.6], not below the
  /// ground spectrum Se(T, xi) for T > T1 [C7.2.5]. @param T (s), >= 0
  double Se(double T) const;
  /// Floor displacement spectrum S_eZ(T) T^2 / (4 pi^2) (m).
  double SDe(double T) const;
  /// Which part of [C7.2.5]-[C7.2.6] gives S_eZ(T) (issue 28: the relazione
  /// names the branch that governs): "rising" (T < a T1), "plateau"
  /// (a T1 <= T < b T1), "falling" (T >= b T1), or "ground" when the ground
  /// spectrum Se(T, xi) is larger (T > T1, the lower bound of [C7.2.5]).
  const char* branch(double T) const;
  double gamma() const { return gamma_; }
  double psi() const { return psi_; }
  double T1() const { return building_.T1; }

 private:
  ElasticSpectrum building_spectrum_;  // at xi_1
  ElasticSpectrum element_spectrum_;   // at xi (lower bound)
  BuildingModel building_;
  double gamma_, psi_, a_Z_, amp_;
};

}  // namespace assess
