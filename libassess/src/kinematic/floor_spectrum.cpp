// floor_spectrum.cpp: floor spectra of Circ. 2019 §C7.2.3, first mode.
//
// Notation: T_k = T1 period of the building's first mode (s); xi_k = xi_1 its
// damping (%); xi the damping of the local mechanism (%), eta = eta(xi);
// gamma1 = 3N/(2N+1), psi1(z) = z/H [C7.2.10]; a_Z = Se(T1, xi_1) |gamma1
// psi1| sqrt(1 + 0.0004 xi_1^2) [C7.2.7]; a = 0.8, b = 1.1 [C7.2.6];
// amplification A = 1.1 xi_1^-0.5 eta (code_rules::floor_amplification).
#include "assess/kinematic/floor_spectrum.hpp"

#include "assess/kinematic/code_rules.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>

namespace assess {

void BuildingModel::validate() const {
  if (!(H > 0.0) || !std::isfinite(H)) throw InputError("building height H: expected > 0 m");
  if (storeys < 1) throw InputError("building storeys: expected >= 1");
  if (!(T1 > 0.0) || !std::isfinite(T1)) throw InputError("building period T1: expected > 0 s");
  if (!(damping_pct > 0.0)) throw InputError("building damping: expected > 0 %");
}

FloorSpectrum::FloorSpectrum(const HazardParams& hazard, const SiteConditions& site,
                             const BuildingModel& building, double z, double element_damping_pct)
    : building_spectrum_(hazard, site, building.damping_pct),
      element_spectrum_(hazard, site, element_damping_pct),
      building_(building) {
  building.validate();
  // z > H is allowed (psi = z/H > 1, the first mode extended above H: a
  // gable above the eaves when H is taken at the eaves; docs/theory/facade.md).
  if (!(z >= 0.0 && std::isfinite(z)))
    throw InputError("height Z = " + std::to_string(z) + " m: expected Z >= 0 m");
  gamma_ = code_rules::gamma_first_mode(building.storeys);
  psi_ = code_rules::psi_first_mode(z, building.H);
  a_Z_ = building_spectrum_.Se(building.T1) * std::fabs(gamma_ * psi_) *
         code_rules::floor_damping_correction(building.damping_pct);  // [C7.2.7], [C7.2.8]
  amp_ = code_rules::floor_amplification(building.damping_pct, element_spectrum_.eta());
}

double FloorSpectrum::Se(double T) const {
  const double a = code_rules::floor_spectrum_a, b = code_rules::floor_spectrum_b, Tk = building_.T1;
  double s;  // [C7.2.6]
  if (T < a * Tk)
    s = a_Z_ * amp_ / (1.0 + (amp_ - 1.0) * std::pow(1.0 - T / (a * Tk), 1.6));
  else if (T < b * Tk)
    s = a_Z_ * amp_;
  else
    s = a_Z_ * amp_ / (1.0 + (amp_ - 1.0) * std::pow(T / (b * Tk) - 1.0, 1.2));
  if (T > Tk) s = std::max(s, element_spectrum_.Se(T));  // [C7.2.5]
  return s;
}

const char* FloorSpectrum::branch(double T) const {
  const double a = code_rules::floor_spectrum_a, b = code_rules::floor_spectrum_b, Tk = building_.T1;
  double s;
  const char* which;
  if (T < a * Tk) {
    s = a_Z_ * amp_ / (1.0 + (amp_ - 1.0) * std::pow(1.0 - T / (a * Tk), 1.6));
    which = "rising";
  } else if (T < b * Tk) {
    s = a_Z_ * amp_;
    which = "plateau";
  } else {
    s = a_Z_ * amp_ / (1.0 + (amp_ - 1.0) * std::pow(T / (b * Tk) - 1.0, 1.2));
    which = "falling";
  }
  if (T > Tk && element_spectrum_.Se(T) > s) which = "ground";
  return which;
}

double FloorSpectrum::SDe(double T) const {
  const double w = T / (2.0 * units::pi);
  return Se(T) * w * w;
}

}  // namespace assess
