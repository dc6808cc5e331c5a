// building_report.hpp: the report of a building assessment (issue 22): a
// summary first (every mechanism with alpha0, a0*, the D/C and zetaE of each
// approach, the governing one marked, zetaE against 1), then one section per
// mechanism as the façade report gives it; as terminal text, JSON and the
// HTML relazione (report layer: formatting only; every number comes from
// BuildingAssessment).
#pragma once

#include "assess/assessment/building_assessment.hpp"
#include "assess/report/facade_report.hpp"
#include "assess/report/kinematic_report.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace assess {

/// The terminal summary: site, record sets, the table of mechanisms (NTC 2018
/// and NTC 2008), the governing mechanism per approach with the counts.
/// Tables within 120 columns unless `width` is TextWidth::wide.
std::string building_text(const BuildingAssessment& b, TextWidth width = TextWidth::columns120);

/// The same content as JSON: "building" (project, file, site, record sets),
/// "mechanisms" (id, wall, name, json_path, record set, alpha0, a0*, safety
/// indices, the expanded "case", and "assessment": facade_json of the mechanism),
/// "governing" (per code and approach) and "warnings".
nlohmann::json building_json(const BuildingAssessment& b);

/// The safety indices of one mechanism as JSON (an array; non-finite numbers null).
nlohmann::json safety_indices_json(const std::vector<SafetyIndex>& indices);

/// The relazione of the building as one self-contained HTML page: header,
/// premessa and normativa, the site, the summary (table with a link to each
/// mechanism's section, the governing mechanisms marked, the bar chart of
/// zetaE against 1), then one section per mechanism (the façade report's
/// sections, ids prefixed with the mechanism's id), conclusions, the case file.
std::string building_html(const BuildingAssessment& b, const ReportOptions& options = {});

}  // namespace assess
