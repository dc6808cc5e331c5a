// case_file.hpp: the façade case JSON (schema version 1, see
// docs/user/case-file.md and docs/schema/case.schema.json) and the kinematic
// assessment of the case: every candidate mechanism analysed, the governing
// one (smallest alpha0) checked by the requested code editions.
#pragma once

#include "assess/kinematic/code_checks.hpp"
#include "assess/kinematic/floor_spectrum.hpp"
#include "assess/kinematic/kinematic_analysis.hpp"
#include "assess/kinematic/mechanism_catalogue.hpp"
#include "assess/hazard/site.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// A parsed case file. Units inside are SI (the file uses m, kN, kN/m^3).
struct CaseFile {
  std::string file;          ///< path it was read from
  std::string project;
  std::optional<SiteSpec> site;   ///< none: no checks, analysis only
  MechanismSet mechanism;
  std::optional<double> Z;        ///< "building/Z_m" override of the mechanism's Z (m)
  std::optional<BuildingModel> building;
  KinematicOptions options;       ///< FC from knowledge_level or FC
  std::string knowledge_level;    ///< "LC1".."LC3" or "given"
  CheckInput checks;              ///< codes, q, damping (hazard filled from the site when run)
  /// Reserved for the façade issue: the raw "dynamic" section, not parsed here.
  nlohmann::json dynamic;
};

/// Parses a case document; errors name `file` and the JSON path.
CaseFile parse_case(const nlohmann::json& doc, const std::string& file);
/// Reads and parses a case file.
CaseFile read_case_file(const std::string& path);

/// The analysis of one candidate mechanism.
struct CandidateResult {
  std::string label;
  double parameter = 0.0;
  double Z = 0.0;  ///< m
  KinematicResult result;
};

struct KinematicCaseResult {
  std::vector<CandidateResult> candidates;
  std::size_t governing = 0;      ///< index of the smallest alpha0
  std::vector<CheckRow> checks;   ///< of the governing candidate (empty without a site)
  std::map<LimitState, SeismicAction> actions;  ///< the site's hazard per limit state
};

/// Analyses every candidate and checks the governing one.
KinematicCaseResult run_kinematic_case(const CaseFile& c);

}  // namespace assess
