// spectrum.hpp: NTC 2018 elastic response spectra (§3.2.3.2): horizontal
// Se(T), vertical Sve(T), displacement SDe(T), and the design spectrum with q.
#pragma once

#include "assess/hazard/hazard.hpp"

#include <string>

namespace assess {

/// Subsoil classes of NTC 2018 §3.2.2 (Tab. 3.2.II).
enum class SoilClass { A, B, C, D, E };
/// Topographic classes of NTC 2018 Tab. 3.2.III.
enum class Topography { T1, T2, T3, T4 };

SoilClass parse_soil_class(const std::string& s);  ///< "A".."E"; InputError otherwise
Topography parse_topography(const std::string& s); ///< "T1".."T4"; InputError otherwise
std::string to_string(SoilClass s);
std::string to_string(Topography t);

/// Site conditions: subsoil, topography, and the relative height h/H of the
/// site on the slope or relief (1 = top/crest; ST varies linearly to 1 at the
/// base, NTC 2018 note to Tab. 3.2.V).
struct SiteConditions {
  SoilClass soil = SoilClass::A;
  Topography topography = Topography::T1;
  double h_over_H = 1.0;  ///< 0..1 (-)
};

/// Damping correction eta = sqrt(10 / (5 + xi)) >= 0.55, NTC 2018 [3.2.4].
/// @param damping_pct viscous damping ratio xi (%), >= 0
double damping_factor(double damping_pct);

/// Stratigraphic amplification SS (Tab. 3.2.IV, clamped).
/// @param ag_g ag on rock (g); @param F0 (-)
double soil_factor_SS(SoilClass soil, double ag_g, double F0);
/// CC = coefficient on TC* (Tab. 3.2.IV). @param Tc_star (s)
double soil_factor_CC(SoilClass soil, double Tc_star);
/// ST (Tab. 3.2.V) with the linear variation in h/H.
double topographic_factor(Topography topo, double h_over_H);

/// The horizontal (and associated vertical and displacement) elastic spectrum
/// of a site for one return period. Immutable; all periods in s, spectral
/// accelerations in m/s^2, displacements in m.
class ElasticSpectrum {
 public:
  /// @param hazard ag (g), F0, TC* (s) for the TR of the limit state
  /// @param site soil, topography
  /// @param damping_pct xi (%), default 5
  ElasticSpectrum(const HazardParams& hazard, const SiteConditions& site, double damping_pct = 5.0);

  /// Horizontal elastic spectral acceleration Se(T) (m/s^2), [3.2.2]. T >= 0 (s).
  double Se(double T) const;
  /// Design spectrum Sd(T) = Se(T) with eta replaced by 1/q (NTC 2018
  /// §3.2.3.5), floored at 0.2 ag. @param q behaviour factor (>= 1)
  double Sd(double T, double q) const;
  /// Vertical elastic spectrum Sve(T) (m/s^2), [3.2.8]-[3.2.9], Tab. 3.2.VI.
  double Sve(double T) const;
  /// Elastic displacement spectrum SDe(T) (m), [3.2.10]-[3.2.11] with TE, TF.
  double SDe(double T) const;

  double ag() const { return ag_; }  ///< ag on rock (m/s^2)
  double ag_g() const { return hazard_.ag_g; }
  double PGA() const { return ag_ * S_; }  ///< ag*S at the surface (m/s^2)
  const HazardParams& hazard() const { return hazard_; }
  const SiteConditions& site() const { return site_; }
  double F0() const { return hazard_.F0; }
  double Tc_star() const { return hazard_.Tc_star; }
  double SS() const { return SS_; }
  double CC() const { return CC_; }
  double ST() const { return ST_; }
  double S() const { return S_; }
  double eta() const { return eta_; }
  double damping_pct() const { return damping_pct_; }
  double TB() const { return TB_; }  ///< s
  double TC() const { return TC_; }  ///< s
  double TD() const { return TD_; }  ///< s
  double TE() const { return TE_; }  ///< s (Tab. 3.2.VII)
  double TF() const { return TF_; }  ///< s
  double Fv() const { return Fv_; }  ///< vertical amplification [3.2.9]

 private:
  HazardParams hazard_;
  SiteConditions site_;
  double damping_pct_, ag_, SS_, CC_, ST_, S_, eta_, TB_, TC_, TD_, TE_, TF_, Fv_;
};

}  // namespace assess
