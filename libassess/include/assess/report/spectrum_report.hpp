// spectrum_report.hpp: the elastic spectra of a site as `assess spectrum`
// evaluates and prints them as JSON, for every front end (the command line,
// the Python module's assess.spectrum): which columns (limit states, a return
// period, a hazard given directly), their parameters and ordinates.
#pragma once

#include "assess/hazard/site.hpp"
#include "assess/hazard/spectrum_columns.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// The periods of `assess spectrum` without --periods (s): 0 to 4 s, 13 values.
std::vector<double> default_spectrum_periods();

/// The JSON of `assess spectrum --json` (without the version stamp): one
/// column's object (limit state, PVR, TR, ag, F0, TC*, SS, CC, ST, S, eta,
/// TB..TF, Fv, PGA in g, and "spectrum": T (s), Se (g), SDe (m), Sve (g),
/// with q also Sd (g)) when there is one column, else the site, VR and
/// "limit_states" with one object per column; the comune and its note when
/// the site was given by comune. Spectra at `damping_pct` (%).
nlohmann::json spectrum_json(const Site& site, const std::vector<SpectrumColumn>& columns, double damping_pct,
                             const std::vector<double>& periods, std::optional<double> q);

/// The warnings of the columns: a return period outside the tabulated
/// 30-2475 years, whose clamped hazard is used (Circ. 2019 Tab. C3.2.I).
std::vector<std::string> spectrum_warnings(const std::vector<SpectrumColumn>& columns);

}  // namespace assess
