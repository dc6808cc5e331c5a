// site.cpp: seismic action of a site per limit state (NTC 2018 §2.4, §3.2).
#include "assess/hazard/site.hpp"

#include "assess/support/error.hpp"

#include <cmath>
#include <mutex>
#include <sstream>

namespace assess {

namespace {
// The shipped grid and islands table are loaded once per process and shared.
std::shared_ptr<const HazardGrid> default_grid() {
  static std::mutex m;
  static std::shared_ptr<const HazardGrid> g;
  std::lock_guard<std::mutex> lock(m);
  if (!g) g = std::make_shared<const HazardGrid>(HazardGrid::load_default());
  return g;
}
std::shared_ptr<const IslandTable> default_islands() {
  static std::mutex m;
  static std::shared_ptr<const IslandTable> t;
  std::lock_guard<std::mutex> lock(m);
  if (!t) t = std::make_shared<const IslandTable>(IslandTable::load_default());
  return t;
}
}  // namespace

Site::Site(const SiteSpec& spec) : spec_(spec) {
  const int sources = int(spec.lat.has_value() || spec.lon.has_value()) + int(spec.island.has_value()) +
                      int(!spec.given.empty());
  if (sources != 1)
    throw InputError("site: give exactly one of latitude/longitude, an island name, or the hazard values "
                     "(ag, F0, Tc*) directly");
  if (spec.lat.has_value() != spec.lon.has_value())
    throw InputError("site: latitude and longitude must be given together (decimal degrees)");
  reference_period(spec.vn_years, spec.cu);  // validates VN and CU
  topographic_factor(spec.conditions.topography, spec.conditions.h_over_H);
  if (spec.lat) {
    grid_ = spec.grid_path.empty() ? default_grid()
                                   : std::make_shared<const HazardGrid>(HazardGrid::load(spec.grid_path));
    grid_->cell_nodes(*spec.lat, *spec.lon);  // fails now for a point outside the grid
  }
  if (spec.island) {
    islands_ = spec.islands_path.empty()
                   ? default_islands()
                   : std::make_shared<const IslandTable>(IslandTable::load(spec.islands_path));
    islands_->at(*spec.island, 475.0);  // fails now for an unknown island
  }
}

double Site::VR() const { return reference_period(spec_.vn_years, spec_.cu); }

HazardParams Site::hazard_at_tr(double tr_years) const {
  if (grid_) return grid_->at(*spec_.lat, *spec_.lon, tr_years);
  if (islands_) return islands_->at(*spec_.island, tr_years);
  throw InputError("site: the hazard is given per limit state; a return period of " + std::to_string(tr_years) +
                   " years cannot be evaluated");
}

HazardParams Site::hazard_extrapolated(double tr_years) const {
  HazardParams h = hazard_at_tr(tr_years);  // validates TR > 0; clamps
  if (!h.tr_clamped) return h;
  // The end segment of the tabulated return periods (Allegato A eq. 2 is a
  // power law in TR between two of them): continued beyond the end.
  const bool below = tr_years < tr_min_years;
  const double T1 = below ? grid_return_periods[0] : grid_return_periods[7];
  const double T2 = below ? grid_return_periods[1] : grid_return_periods[8];
  const double a1 = hazard_at_tr(T1).ag_g, a2 = hazard_at_tr(T2).ag_g;
  const double k = std::log(a2 / a1) / std::log(T2 / T1);
  h.ag_g = (below ? a1 : a2) * std::pow(tr_years / (below ? T1 : T2), k);
  return h;
}

SeismicAction Site::action(LimitState ls) const {
  SeismicAction a;
  a.limit_state = ls;
  a.PVR = exceedance_probability(ls);
  a.TR = return_period(spec_.vn_years, spec_.cu, ls);
  if (!spec_.given.empty()) {
    const auto it = spec_.given.find(ls);
    if (it == spec_.given.end())
      throw InputError("site: no hazard values (ag, F0, Tc*) given for limit state " + to_string(ls));
    a.hazard = it->second;
    a.hazard.TR = a.TR;
    a.hazard.tr_requested = a.TR;
    return a;
  }
  a.hazard = hazard_at_tr(a.TR);
  return a;
}

ElasticSpectrum Site::spectrum(LimitState ls, double damping_pct) const {
  return ElasticSpectrum(action(ls).hazard, spec_.conditions, damping_pct);
}

std::vector<int> Site::grid_nodes() const {
  return grid_ ? grid_->cell_nodes(*spec_.lat, *spec_.lon) : std::vector<int>{};
}

std::string Site::describe() const {
  std::ostringstream os;
  os.precision(8);
  if (!spec_.comune.empty()) os << "comune " << spec_.comune << ": ";
  if (spec_.lat) os << "lat " << *spec_.lat << ", lon " << *spec_.lon << (spec_.comune.empty() ? "" : " (municipal seat)");
  else if (spec_.island) os << "island " << *spec_.island;
  else os << "hazard given per limit state";
  return os.str();
}

}  // namespace assess
