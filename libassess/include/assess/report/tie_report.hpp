// tie_report.hpp: text and JSON of the tie rods of a case (issue 23): each
// level's rod, anchor, design strengths, the force each check of the
// mechanism needs, the checks of the tie, and the mechanism before and after
// side by side with zeta_E. The HTML section is in tie_html.cpp.
#pragma once

#include "assess/assessment/tie_intervention.hpp"
#include "assess/report/messages.hpp"

#include <nlohmann/json.hpp>

#include <string>

namespace assess {

/// Terminal text (English with the Italian terms of the relazione).
std::string tie_text(const TieInterventionResult& t);
/// JSON: "designed", "found", "levels" (rod, anchor, strengths in kN,
/// required forces in kN and kN/m, checks), "before"/"after" (alpha0, a0*,
/// d0*, d_SLV ..., zeta_E, every check's D/C, the capacity curve with each
/// level's force and elongation at each point, the levels on the mechanism),
/// "dynamic" (summaries and runs); SI except forces in kN and lengths of the
/// rod and anchor in mm (named in the keys).
nlohmann::json tie_json(const TieInterventionResult& t);
/// The HTML section of the relazione (tie_html.cpp), below its heading
/// tie_section_title(): drawing of the ties on the mechanism, each level's
/// rod and anchor, the checks table, the force each check needs and the
/// before/after verdicts. Its subheadings are <h`heading_level`>; every id in
/// it (the section's "ties", the drawing's markers) starts with `id_prefix`
/// (the building relazione: one section per mechanism, "M3-").
std::string tie_html_section(const TieInterventionResult& t, Lang lang, const std::string& id_prefix = "",
                             int heading_level = 3);
std::string tie_section_title(Lang lang);

}  // namespace assess
