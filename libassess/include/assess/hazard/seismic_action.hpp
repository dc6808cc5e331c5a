// seismic_action.hpp: reference period and return period of the seismic
// action (NTC 2018 §2.4, §3.2.1; Circ. 2019 C3.2.1).
#pragma once

#include <array>
#include <string>

namespace assess {

/// Limit states of NTC 2018 §3.2.1.
enum class LimitState { SLO, SLD, SLV, SLC };

inline constexpr std::array<LimitState, 4> all_limit_states{LimitState::SLO, LimitState::SLD,
                                                             LimitState::SLV, LimitState::SLC};

/// "SLO", "SLD", "SLV", "SLC".
std::string to_string(LimitState ls);
/// Parses "SLO".."SLC" (case-insensitive); throws InputError otherwise.
LimitState parse_limit_state(const std::string& s);

/// Probability of exceedance P_VR in the reference period (NTC 2018
/// Tab. 3.2.I): SLO 0.81, SLD 0.63, SLV 0.10, SLC 0.05 (fraction).
double exceedance_probability(LimitState ls);

/// Coefficient of use CU for use class 1..4 (I..IV), NTC 2018 Tab. 2.4.II:
/// 0.7, 1.0, 1.5, 2.0. Throws InputError for another class.
double use_coefficient(int use_class);
/// Parses "I".."IV" or "1".."4" into 1..4; throws InputError otherwise.
int parse_use_class(const std::string& s);

/// Reference period VR = VN * CU (years), NTC 2018 [2.4.1], with the floor
/// VR >= 35 years (NTC 2008 §2.4.3; Circ. 2019 Tab. C2.4.I; see docs/theory/spectra.md).
/// @param vn_years nominal life VN (years, > 0)
/// @param cu coefficient of use CU (> 0)
double reference_period(double vn_years, double cu);

/// Return period TR = -VR / ln(1 - P_VR) (years), NTC 2018 [3.2.0],
/// NOT clamped (the hazard lookup clamps to the tabulated range).
double return_period(double vn_years, double cu, LimitState ls);

/// The tabulated range of the hazard data (years): Circ. 2019 Tab. C3.2.I.
inline constexpr double tr_min_years = 30.0;
inline constexpr double tr_max_years = 2475.0;

}  // namespace assess
