// run_report.cpp: the JSON of `assess run` of a single-mechanism case and the
// fragility result that goes with it, and the JSON of `assess kinematic` with
// its tie rods (risk/run_report.hpp), moved from apps/cmd_run.cpp and
// apps/cmd_kinematic.cpp for issue 40 so that the Python module returns the same.
#include "assess/risk/run_report.hpp"

#include "assess/assessment/building_assessment.hpp"
#include "assess/report/building_report.hpp"
#include "assess/report/facade_report.hpp"
#include "assess/report/kinematic_report.hpp"
#include "assess/report/tie_report.hpp"
#include "assess/risk/fragility_report.hpp"
#include "assess/support/error.hpp"

#include <filesystem>

namespace assess {

std::optional<RunFragility> run_fragility(const std::string& case_file, const std::string& dir) {
  RunFragility f;
  if (!dir.empty()) {
    f.summary = read_fragility_summary(dir, case_file);
    f.dir = dir;
  } else {
    const std::string auto_dir = std::filesystem::path(case_file).stem().string() + ".fragility";
    if (!std::filesystem::exists(auto_dir + "/summary.json")) return std::nullopt;
    try {
      f.summary = read_fragility_summary(auto_dir, case_file);
      f.dir = auto_dir;
    } catch (const InputError&) {
      return std::nullopt;  // another case's results: not this run's business
    }
  }
  f.result = probabilistic_result(f.summary, f.dir + "/summary.json");
  return f;
}

nlohmann::json facade_run_json(const FacadeAssessment& a, const std::optional<TieInterventionResult>& ties,
                               const std::optional<RunFragility>& fragility) {
  nlohmann::json j = facade_json(a);
  // zetaE = PGA_C/PGA_D and TR_C/TR_D per approach (docs/theory/building.md §4), as the building report gives them.
  j["safety_indices"] = safety_indices_json(a.indices);
  if (fragility) {
    nlohmann::json f = probabilistic_result_json(fragility->result);
    f["line"] = fragility_line(fragility->summary);
    const nlohmann::json& s = fragility->summary;
    f["governing"] = s.is_object() && s.contains("governing") ? s.at("governing") : nlohmann::json(nullptr);
    j["fragility"] = f;
  }
  if (ties) j["ties"] = tie_json(*ties);
  return j;
}

std::optional<TieInterventionResult> kinematic_ties(const CaseFile& c, std::vector<std::string>& warnings) {
  if (c.tie_design && !c.site)
    warnings.push_back(c.file + ": /design: the design of ties needs the site's hazard (\"site\"): not done");
  if (!has_ties(c) || !c.site) return std::nullopt;
  return run_tie_intervention(c);
}

nlohmann::json kinematic_run_json(const CaseFile& c, const KinematicCaseResult& res,
                                  const std::optional<TieInterventionResult>& ties) {
  nlohmann::json j = kinematic_json(c, res);
  if (ties) j["ties"] = tie_json(*ties);
  return j;
}

}  // namespace assess
