// seismic_action.cpp: reference and return periods (NTC 2018 §2.4, §3.2.1).
//
// Notation: VN nominal life (years), CU coefficient of use, VR = VN*CU
// reference period (years), P_VR probability of exceedance in VR, TR return
// period (years).
#include "assess/hazard/seismic_action.hpp"

#include "assess/support/error.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>

namespace assess {

std::string to_string(LimitState ls) {
  switch (ls) {
    case LimitState::SLO: return "SLO";
    case LimitState::SLD: return "SLD";
    case LimitState::SLV: return "SLV";
    case LimitState::SLC: return "SLC";
  }
  return "?";
}

LimitState parse_limit_state(const std::string& s) {
  std::string u = s;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  for (LimitState ls : all_limit_states)
    if (u == to_string(ls)) return ls;
  throw InputError("limit state '" + s + "': expected one of SLO, SLD, SLV, SLC");
}

// NTC 2018 Tab. 3.2.I.
double exceedance_probability(LimitState ls) {
  switch (ls) {
    case LimitState::SLO: return 0.81;
    case LimitState::SLD: return 0.63;
    case LimitState::SLV: return 0.10;
    case LimitState::SLC: return 0.05;
  }
  return 0.0;
}

// NTC 2018 Tab. 2.4.II.
double use_coefficient(int use_class) {
  switch (use_class) {
    case 1: return 0.7;
    case 2: return 1.0;
    case 3: return 1.5;
    case 4: return 2.0;
  }
  throw InputError("use class " + std::to_string(use_class) + ": expected I, II, III or IV");
}

int parse_use_class(const std::string& s) {
  std::string u = s;
  std::transform(u.begin(), u.end(), u.begin(), [](unsigned char c) { return std::toupper(c); });
  if (u == "I" || u == "1") return 1;
  if (u == "II" || u == "2") return 2;
  if (u == "III" || u == "3") return 3;
  if (u == "IV" || u == "4") return 4;
  throw InputError("use class '" + s + "': expected I, II, III or IV");
}

// NTC 2018 [2.4.1]; the 35-year floor is NTC 2008 §2.4.3 / Circ. 2019 Tab. C2.4.I.
double reference_period(double vn_years, double cu) {
  if (!(vn_years > 0.0) || !std::isfinite(vn_years))
    throw InputError("nominal life VN = " + std::to_string(vn_years) + " years: expected > 0 years");
  if (!(cu > 0.0) || !std::isfinite(cu))
    throw InputError("coefficient of use CU = " + std::to_string(cu) + ": expected > 0");
  return std::max(35.0, vn_years * cu);
}

// NTC 2018 [3.2.0]: TR = -VR / ln(1 - P_VR).
double return_period(double vn_years, double cu, LimitState ls) {
  const double vr = reference_period(vn_years, cu);
  return -vr / std::log1p(-exceedance_probability(ls));
}

}  // namespace assess
