// spectrum.cpp: NTC 2018 elastic spectra (§3.2.3.2).
//
// Notation (NTC 2018): ag peak ground acceleration on rock (here m/s^2;
// ag/g in the soil formulas), F0 maximum amplification, TC* (s), SS
// stratigraphic and ST topographic amplification, S = SS*ST [3.2.3],
// eta = damping correction [3.2.4], CC (TC = CC*TC*) [3.2.5], TB = TC/3
// [3.2.6], TD = 4 ag/g + 1.6 [3.2.7]; vertical: Fv = 1.35 F0 (ag/g)^0.5 [3.2.9];
// displacement: TE, TF of Tab. 3.2.VII.
#include "assess/hazard/spectrum.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace assess {

SoilClass parse_soil_class(const std::string& s) {
  if (s.size() == 1) {
    switch (std::toupper(static_cast<unsigned char>(s[0]))) {
      case 'A': return SoilClass::A;
      case 'B': return SoilClass::B;
      case 'C': return SoilClass::C;
      case 'D': return SoilClass::D;
      case 'E': return SoilClass::E;
    }
  }
  throw InputError("soil class '" + s + "': expected one of A, B, C, D, E (NTC 2018 Tab. 3.2.II)");
}

Topography parse_topography(const std::string& s) {
  std::string u = s;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  if (u == "T1") return Topography::T1;
  if (u == "T2") return Topography::T2;
  if (u == "T3") return Topography::T3;
  if (u == "T4") return Topography::T4;
  throw InputError("topographic class '" + s + "': expected one of T1, T2, T3, T4 (NTC 2018 Tab. 3.2.III)");
}

std::string to_string(SoilClass s) { return std::string(1, char('A' + static_cast<int>(s))); }
std::string to_string(Topography t) { return "T" + std::to_string(static_cast<int>(t) + 1); }

// NTC 2018 [3.2.4].
double damping_factor(double damping_pct) {
  if (!(damping_pct >= 0.0) || !std::isfinite(damping_pct))
    throw InputError("damping " + std::to_string(damping_pct) + " %: expected a viscous damping ratio >= 0 %");
  return std::max(0.55, std::sqrt(10.0 / (5.0 + damping_pct)));
}

// NTC 2018 Tab. 3.2.IV (the inequalities are clamps).
double soil_factor_SS(SoilClass soil, double ag_g, double F0) {
  const double x = F0 * ag_g;
  switch (soil) {
    case SoilClass::A: return 1.0;
    case SoilClass::B: return std::clamp(1.40 - 0.40 * x, 1.00, 1.20);
    case SoilClass::C: return std::clamp(1.70 - 0.60 * x, 1.00, 1.50);
    case SoilClass::D: return std::clamp(2.40 - 1.50 * x, 0.90, 1.80);
    case SoilClass::E: return std::clamp(2.00 - 1.10 * x, 1.00, 1.60);
  }
  return 1.0;
}

double soil_factor_CC(SoilClass soil, double Tc_star) {
  switch (soil) {
    case SoilClass::A: return 1.0;
    case SoilClass::B: return 1.10 * std::pow(Tc_star, -0.20);
    case SoilClass::C: return 1.05 * std::pow(Tc_star, -0.33);
    case SoilClass::D: return 1.25 * std::pow(Tc_star, -0.50);
    case SoilClass::E: return 1.15 * std::pow(Tc_star, -0.40);
  }
  return 1.0;
}

// NTC 2018 Tab. 3.2.V, varying linearly from the maximum at the top (h/H = 1)
// to 1 at the base (h/H = 0): reading of the note under the table.
double topographic_factor(Topography topo, double h_over_H) {
  if (!(h_over_H >= 0.0 && h_over_H <= 1.0))
    throw InputError("relative height of the site h/H = " + std::to_string(h_over_H) + ": expected 0..1");
  double st_max = 1.0;
  switch (topo) {
    case Topography::T1: st_max = 1.0; break;
    case Topography::T2: st_max = 1.2; break;
    case Topography::T3: st_max = 1.2; break;
    case Topography::T4: st_max = 1.4; break;
  }
  return 1.0 + (st_max - 1.0) * h_over_H;
}

namespace {
// Tab. 3.2.VII.
double te_of(SoilClass s) { return s == SoilClass::A ? 4.5 : s == SoilClass::B ? 5.0 : 6.0; }
constexpr double tf_all = 10.0;

void check_hazard(const HazardParams& h) {
  if (!(h.ag_g > 0.0) || !std::isfinite(h.ag_g))
    throw InputError("ag = " + std::to_string(h.ag_g) + " g: expected a peak ground acceleration > 0 g");
  if (!(h.F0 > 0.0) || !std::isfinite(h.F0))
    throw InputError("F0 = " + std::to_string(h.F0) + ": expected an amplification factor > 0");
  if (!(h.Tc_star > 0.0) || !std::isfinite(h.Tc_star))
    throw InputError("Tc* = " + std::to_string(h.Tc_star) + " s: expected a period > 0 s");
}

// The four branches of [3.2.2] (and of the vertical [3.2.8]) for amplitude
// A = ag*S*eta*F; `first` is the factor of (1 - T/TB) in the first branch.
double four_branches(double T, double A, double first, double TB, double TC, double TD) {
  if (T < TB) return A * (T / TB + first * (1.0 - T / TB));
  if (T < TC) return A;
  if (T < TD) return A * TC / T;
  return A * TC * TD / (T * T);
}

void check_period(double T) {
  if (!(T >= 0.0) || !std::isfinite(T))
    throw InputError("period T = " + std::to_string(T) + " s: expected a period >= 0 s");
}
}  // namespace

ElasticSpectrum::ElasticSpectrum(const HazardParams& hazard, const SiteConditions& site, double damping_pct)
    : hazard_(hazard), site_(site), damping_pct_(damping_pct) {
  check_hazard(hazard);
  ag_ = hazard.ag_g * units::g;
  SS_ = soil_factor_SS(site.soil, hazard.ag_g, hazard.F0);
  CC_ = soil_factor_CC(site.soil, hazard.Tc_star);
  ST_ = topographic_factor(site.topography, site.h_over_H);
  S_ = SS_ * ST_;                          // [3.2.3]
  eta_ = damping_factor(damping_pct);      // [3.2.4]
  TC_ = CC_ * hazard.Tc_star;              // [3.2.5]
  TB_ = TC_ / 3.0;                         // [3.2.6]
  TD_ = 4.0 * hazard.ag_g + 1.6;           // [3.2.7]
  TE_ = te_of(site.soil);                  // Tab. 3.2.VII
  TF_ = tf_all;
  Fv_ = 1.35 * hazard.F0 * std::sqrt(hazard.ag_g);  // [3.2.9]
}

// [3.2.2]
double ElasticSpectrum::Se(double T) const {
  check_period(T);
  return four_branches(T, ag_ * S_ * eta_ * hazard_.F0, 1.0 / (eta_ * hazard_.F0), TB_, TC_, TD_);
}

// §3.2.3.5: the elastic spectrum with eta replaced by 1/q, and Sd >= 0.2 ag.
double ElasticSpectrum::Sd(double T, double q) const {
  check_period(T);
  if (!(q >= 1.0) || !std::isfinite(q))
    throw InputError("behaviour factor q = " + std::to_string(q) + ": expected q >= 1");
  const double e = 1.0 / q;
  const double v = four_branches(T, ag_ * S_ * e * hazard_.F0, 1.0 / (e * hazard_.F0), TB_, TC_, TD_);
  return T < TB_ ? v : std::max(v, 0.2 * ag_);
}

// [3.2.8] with Tab. 3.2.VI: SS = 1, TB = 0.05 s, TC = 0.15 s, TD = 1.0 s.
// The first branch carries 1/(eta*F0) as printed in NTC 2018 [3.2.8].
double ElasticSpectrum::Sve(double T) const {
  check_period(T);
  const double Sv = 1.0 * ST_;
  return four_branches(T, ag_ * Sv * eta_ * Fv_, 1.0 / (eta_ * hazard_.F0), 0.05, 0.15, 1.0);
}

// [3.2.10] up to TE, [3.2.11] between TE and TF, dg [3.2.12] beyond.
double ElasticSpectrum::SDe(double T) const {
  check_period(T);
  if (T <= TE_) {
    const double w = T / (2.0 * units::pi);
    return Se(T) * w * w;
  }
  const double dg = 0.025 * ag_ * S_ * TC_ * TD_;
  if (T <= TF_) {
    const double fe = hazard_.F0 * eta_;
    return dg * (fe + (1.0 - fe) * (T - TE_) / (TF_ - TE_));
  }
  return dg;
}

}  // namespace assess
