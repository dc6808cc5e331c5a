// fragility_report.hpp: the outputs of a fragility analysis: summary JSON,
// CSV tables (curves, stripes, hazard curve) and a self-contained HTML page
// with SVG plots (fragility curves with the stripe points and the
// bootstrap band, the hazard curve, the integrand of the risk), beside the
// code's SLV/SLC return periods and checks (docs/user/fragility.md).
#pragma once

#include "assess/report/probabilistic_result.hpp"
#include "assess/risk/fragility_result.hpp"
#include "assess/risk/fragility_study.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace assess {

/// Everything of the result as JSON (SI units, keys name them).
nlohmann::json fragility_to_json(const FragilityStudy& study, const FragilityResult& result);

/// A plain-text summary (a few lines per restitution value).
std::string fragility_text(const FragilityStudy& study, const FragilityResult& result);

struct FragilityReportFiles {
  std::string summary, curves_csv, stripes_csv, hazard_csv, html;
};

/// Writes summary.json, curves.csv, stripes.csv, hazard.csv and report.html
/// (with plots unless `plots` is false) into out_dir.
/// @throws InputError if a file cannot be written
FragilityReportFiles write_fragility_report(const FragilityStudy& study, const FragilityResult& result,
                                            const std::string& out_dir, bool plots);

/// Reads dir/summary.json written by write_fragility_report, checking that it
/// is the fragility of `case_file` (same file). @throws InputError naming the
/// file and what differs.
nlohmann::json read_fragility_summary(const std::string& dir, const std::string& case_file);

/// One line for other reports (e.g. `assess run`): the governing overturning
/// curve's median, return period and probability in VN beside the code's SLV
/// return period, or why there is no risk figure.
std::string fragility_line(const nlohmann::json& summary);

/// The same for the façade report's box and JSON (report/probabilistic_result):
/// the governing overturning curve of a summary read by read_fragility_summary
/// from `source`. @throws InputError naming the missing or malformed key.
ProbabilisticResult probabilistic_result(const nlohmann::json& summary, const std::string& source);

}  // namespace assess
