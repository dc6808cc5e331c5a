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

/// The same content as JSON: "building" (project, file, site, record sets),
/// "mechanisms" (id, wall, name, json_path, record set, alpha0, a0*, safety
/// indices, the expanded "case", and "assessment": facade_json of the mechanism),
/// "governing" (per code and approach) and "warnings".
nlohmann::json building_json(const BuildingAssessment& b);

/// The safety indices of one mechanism as JSON (an array; non-finite numbers null).
nlohmann::json safety_indices_json(const std::vector<SafetyIndex>& indices);

/// The relazione of the building as a document (issue 28): frontespizio, the
/// building's verdict (one sentence: verdict, zetaE,edificio, the mechanisms
/// that fail) and the governing mechanism of each approach, contents;
/// premessa, normativa, description, survey, the mechanisms examined; the
/// seismic action; the formulas; the summary (per-approach alpha0, a0*, D/C
/// and zetaE of every mechanism, the zetaE chart, NTC 2008, the record sets,
/// the ties); one section per mechanism (the façade relazione's sections,
/// anchors and figure ids prefixed with the mechanism's id); interventions;
/// conclusions and signature; appendices (other candidates, warnings,
/// legend, readings adopted, the case file).
Document building_document(const BuildingAssessment& b, const ReportOptions& options = {});

/// The summary of the building's assessment (issue 41): what `assess run
/// BUILDING.json` prints in the terminal, in the language of the options,
/// from the relazione's own sections (the building's verdict, the seismic
/// action, the mechanisms' table, the interventions, the warnings).
Document building_summary(const BuildingAssessment& b, const ReportOptions& options = {});

/// to_html(building_document(b, options)).
std::string building_html(const BuildingAssessment& b, const ReportOptions& options = {});

}  // namespace assess
