// rocking_report.hpp: the results of one rocking analysis of a wall
// (dynamics/rocking_request.hpp) as `assess rocking --json` prints them and
// the Python module's assess.rocking returns them, and its history as the
// CSV of --history.
#pragma once

#include "assess/dynamics/rocking_analysis.hpp"
#include "assess/records/record.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace assess {

/// The results of an analysis (the keys of rocking_json but "record"): for
/// an analysis without a record too (free rocking, analyse_free).
nlohmann::json rocking_result_json(const RockingResult& r);

/// The JSON of `assess rocking --json` (without the version stamp): rotations
/// in rad, times in s, energies in kJ/m, d_max in m; "record" with its name,
/// format, points, dt (s), PGA (g), and the scale and polarity applied.
nlohmann::json rocking_json(const RockingResult& r, const Record& record, double scale, bool reverse);

/// A history as CSV: the header line `header` (e.g. "t_s,theta_rad,omega_rad_s"),
/// then t, theta, theta' per line with 9 significant digits (--history).
std::string rocking_history_csv(const RockingHistory& h, const std::string& header);

}  // namespace assess
