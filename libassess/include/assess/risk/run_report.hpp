// run_report.hpp: what `assess run CASE --json` and `assess kinematic CASE
// --json` print for a single-mechanism case, for every front end (the command
// line, the Python module's assess.run and assess.kinematic): the façade
// assessment's JSON, its safety indices, the tie rods and the fragility
// result of the case when there is one; the kinematic analysis's JSON and its
// tie rods.
#pragma once

#include "assess/assessment/facade_assessment.hpp"
#include "assess/assessment/tie_intervention.hpp"
#include "assess/report/probabilistic_result.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// A fragility result of the case (`assess fragility`), shown beside the run.
struct RunFragility {
  nlohmann::json summary;     ///< DIR/summary.json, read by read_fragility_summary
  std::string dir;            ///< DIR
  ProbabilisticResult result; ///< its governing overturning curve at the site
};

/// The fragility result of a run of `case_file`: the one in `dir` when given
/// (`--fragility DIR`; an InputError when it is not this case's), else the one
/// in CASE.fragility of the working directory (the default output of
/// `assess fragility`) when it holds this case's; none otherwise.
std::optional<RunFragility> run_fragility(const std::string& case_file, const std::string& dir = "");

/// The JSON of `assess run --json` of a single-mechanism case, without the
/// version stamp (support/version.hpp): facade_json, "safety_indices"
/// (ζE = PGA_C/PGA_D and TR_C/TR_D per approach), "fragility" and "ties"
/// when present.
nlohmann::json facade_run_json(const FacadeAssessment& a, const std::optional<TieInterventionResult>& ties,
                               const std::optional<RunFragility>& fragility);

/// The tie step of `assess kinematic`: nothing when the case has no ties
/// (has_ties); the two states from the kinematic analyses alone when it has a
/// site (run_tie_intervention); without a site none, and for a design of ties
/// the warning that it needs the site's hazard is appended to `warnings`.
std::optional<TieInterventionResult> kinematic_ties(const CaseFile& c, std::vector<std::string>& warnings);

/// The JSON of `assess kinematic --json` (without the version stamp):
/// kinematic_json and "ties" when there are.
nlohmann::json kinematic_run_json(const CaseFile& c, const KinematicCaseResult& res,
                                  const std::optional<TieInterventionResult>& ties);

}  // namespace assess
