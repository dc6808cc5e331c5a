// site.hpp: a construction site and its seismic action per limit state
// (NTC 2018 §2.4, §3.2): hazard from the grid (lat/lon), from an island of
// Allegato B Tab. 2, or given directly; subsoil and topography; VN and CU.
#pragma once

#include "assess/hazard/hazard.hpp"
#include "assess/hazard/seismic_action.hpp"
#include "assess/hazard/spectrum.hpp"

#include <map>
#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace assess {

/// How the site is described. Exactly one of (lat, lon), island, given.
struct SiteSpec {
  std::optional<double> lat;  ///< decimal degrees (north)
  std::optional<double> lon;  ///< decimal degrees (east)
  std::optional<std::string> island;  ///< island name of Allegato B Tab. 2
  /// When the site was given by comune: "L'Aquila (AQ), ISTAT 066049"; lat
  /// and lon then hold the municipal seat (ComuneTable, comuni.hpp).
  std::string comune;
  /// Hazard given directly, per limit state (ag in g, F0, TC* in s); a limit
  /// state without an entry cannot be evaluated.
  std::map<LimitState, HazardParams> given;
  SiteConditions conditions;
  double vn_years = 50.0;  ///< nominal life VN (years)
  double cu = 1.0;         ///< coefficient of use CU (-)
  /// Hazard data files; empty = the files shipped in data_dir()/spectra.
  std::string grid_path;
  std::string islands_path;
};

/// The seismic action of one limit state at the site.
struct SeismicAction {
  LimitState limit_state = LimitState::SLV;
  double PVR = 0.0;  ///< probability of exceedance in VR (fraction)
  double TR = 0.0;   ///< return period (years), as computed, before clamping
  HazardParams hazard;  ///< ag (g), F0, TC* (s) at the (clamped) TR
};

/// A site with its hazard source. Cheap to copy (shares the grid).
class Site {
 public:
  /// Validates the spec (InputError naming the field) and loads the default
  /// hazard grid / islands table when needed (once per process).
  explicit Site(const SiteSpec& spec);

  const SiteSpec& spec() const { return spec_; }
  double VR() const;  ///< reference period (years), >= 35
  /// Hazard of a limit state (TR from VN, CU).
  SeismicAction action(LimitState ls) const;
  /// Hazard for an arbitrary return period (years); clamped to [30, 2475].
  HazardParams hazard_at_tr(double tr_years) const;
  /// The site's hazard along the return-period axis, for the return period
  /// at which a check reaches D/C = 1 (issue 41; docs/theory/building.md §4):
  /// inside [30, 2475] years exactly hazard_at_tr (Allegato A, log-log in
  /// TR); outside, ag continues the power law of the end segment (30-50 or
  /// 975-2475 years, the extrapolation of the hazard curve, hazard_curve.hpp)
  /// and F0, TC* are held at the end values (the clamp of Allegato A) [I].
  /// `tr_clamped` tells that TR was outside [30, 2475] years.
  /// @throws InputError for a site whose hazard is given per limit state.
  HazardParams hazard_extrapolated(double tr_years) const;
  /// True when the hazard comes from the grid or an island (a return-period axis exists).
  bool has_hazard_curve() const { return grid_ || islands_; }
  /// Elastic spectrum of a limit state at damping xi (%).
  ElasticSpectrum spectrum(LimitState ls, double damping_pct = 5.0) const;
  /// Grid nodes used for the site (the enclosing cell), empty unless lat/lon.
  std::vector<int> grid_nodes() const;
  /// Human-readable description ("lat 42.35, lon 13.40", "island Lipari",
  /// "given"; with a comune: "comune L'Aquila (AQ), ISTAT 066049: lat 42.354, lon 13.392 (municipal seat)").
  std::string describe() const;

 private:
  SiteSpec spec_;
  std::shared_ptr<const HazardGrid> grid_;
  std::shared_ptr<const IslandTable> islands_;
};

}  // namespace assess
