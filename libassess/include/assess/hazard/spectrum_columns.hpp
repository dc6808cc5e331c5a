// spectrum_columns.hpp: the hazard a spectrum is drawn for, per column —
// a limit state of NTC 2018 Tab. 3.2.I, a given return period, or a hazard
// given directly — as `assess spectrum` and `assess.spectrum` evaluate it
// (issue 41: the report prints these columns; it does not compute them).
#pragma once

#include "assess/hazard/site.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// One evaluated column: a limit state, a given return period or a given hazard.
struct SpectrumColumn {
  std::string label;              ///< "SLV", "TR" or "given"
  std::optional<LimitState> ls;
  std::optional<double> PVR;      ///< probability of exceedance in VR (fraction)
  std::optional<double> TR;       ///< return period as computed (years)
  HazardParams hazard;            ///< ag (g), F0, TC* (s) at the (clamped) TR
};

/// The columns of `assess spectrum`: the return period `tr` when given (one
/// column "TR"; not with a hazard given directly); for a site whose hazard is
/// given directly one column "given" (of states[0], its limit state when
/// `state_named`); else one column per limit state of `states`.
/// @throws InputError "--tr ...: expected a return period in years > 0"
std::vector<SpectrumColumn> spectrum_columns(const Site& site, const std::vector<LimitState>& states,
                                             bool state_named, std::optional<double> tr);

}  // namespace assess
