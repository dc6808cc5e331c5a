// spectrum_columns.cpp: the hazard of each column of a spectrum table
// (hazard/spectrum_columns.hpp).
#include "assess/hazard/spectrum_columns.hpp"

#include "assess/support/error.hpp"

#include <cmath>
#include <string>

namespace assess {

std::vector<SpectrumColumn> spectrum_columns(const Site& site, const std::vector<LimitState>& states,
                                             bool state_named, std::optional<double> tr) {
  std::vector<SpectrumColumn> cols;
  if (tr) {
    if (!(*tr > 0.0) || !std::isfinite(*tr))
      throw InputError("--tr " + std::to_string(*tr) + ": expected a return period in years > 0");
    if (!site.spec().given.empty()) throw InputError("--tr cannot be used with --ag/--F0/--Tc-star");
    SpectrumColumn c;
    c.label = "TR";
    c.TR = *tr;
    c.hazard = site.hazard_at_tr(*tr);
    cols.push_back(c);
    return cols;
  }
  if (states.empty()) throw InputError("no limit state to evaluate (expected SLO, SLD, SLV or SLC)");
  if (!site.spec().given.empty()) {  // one hazard given directly: one column
    SpectrumColumn c;
    c.label = "given";
    if (state_named) c.ls = states[0];
    c.hazard = site.action(states[0]).hazard;
    c.hazard.TR = 0.0;
    cols.push_back(c);
    return cols;
  }
  for (LimitState ls : states) {
    SpectrumColumn c;
    c.ls = ls;
    c.label = to_string(ls);
    const SeismicAction act = site.action(ls);
    c.PVR = act.PVR;
    c.TR = act.TR;
    c.hazard = act.hazard;
    cols.push_back(c);
  }
  return cols;
}

}  // namespace assess
