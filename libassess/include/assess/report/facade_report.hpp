// facade_report.hpp: the report of a façade assessment, as terminal text,
// JSON and a self-contained printable HTML page with plots (report layer:
// formatting and plotting only; every number comes from FacadeAssessment).
#pragma once

#include "assess/assessment/facade_assessment.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace assess {

/// Readable report: site block per limit state, kinematic block with every
/// intermediate quantity, the checks table (kinematic and dynamic rows, verdicts
/// in Italian and English), the dynamic table and the D/C of all approaches.
std::string facade_text(const FacadeAssessment& a);

/// The same content as JSON: keys "project", "site", "kinematic" (the keys of
/// `assess kinematic --json`), "checks" (kinematic and "kind": "dynamic" rows),
/// "dynamic" (model, records, selection, analyses, summary per restitution),
/// "comparison" (D/C per approach, seed Fig. 8).
nlohmann::json facade_json(const FacadeAssessment& a);

/// Self-contained HTML report with SVG plots drawn by gnuplot: the four
/// limit-state spectra with the record spectra and their mean; the capacity
/// curve a*-d* with the displacement demands; the moment-rotation curve of the
/// rocking body; theta/theta_u time histories; the D/C bar chart.
/// @throws InputError if gnuplot is missing (names the package gnuplot-nox)
std::string facade_html(const FacadeAssessment& a);

}  // namespace assess
