// site_hazard.hpp: the site's seismic hazard as a façade assessment uses it:
// the action and the 5 % elastic spectrum of each limit state (NTC 2018
// §3.2), the site's description and its reference period V_R (§2.4.3).
#pragma once

#include "assess/hazard/seismic_action.hpp"
#include "assess/hazard/spectrum.hpp"

#include <map>
#include <string>

namespace assess {

struct SiteHazard {
  std::map<LimitState, SeismicAction> actions;    ///< the site's limit states (all four from the grid)
  std::map<LimitState, ElasticSpectrum> spectra;  ///< 5 % elastic spectrum of each of them
  std::string description;                        ///< Site::describe()
  double VR = 0.0;                                ///< reference period (years)
};

}  // namespace assess
