// case_file.hpp: the façade case JSON (schema version 1, see
// docs/user/case-file.md and docs/schema/case.schema.json) and the kinematic
// assessment of the case: every candidate mechanism analysed and checked by the
// requested code editions; the governing one per code is the candidate with
// the largest D/C over its checks (docs/theory/facade.md §6).
#pragma once

#include "assess/assessment/case_default.hpp"
#include "assess/assessment/verdict.hpp"
#include "assess/kinematic/code_checks.hpp"
#include "assess/kinematic/floor_spectrum.hpp"
#include "assess/kinematic/kinematic_analysis.hpp"
#include "assess/kinematic/mechanism_catalogue.hpp"
#include "assess/kinematic/tie.hpp"
#include "assess/kinematic/tie_design.hpp"
#include "assess/hazard/site.hpp"

#include <nlohmann/json.hpp>

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace assess {

/// What the relazione says of the work and of its engineer (case key
/// "report", issue 28, item 7; docs/user/case-file.md §Report): the
/// frontespizio, the description of the building, the survey and
/// investigations that justify the knowledge level, the masonry and the
/// criteria of the mechanisms' choice. Text as the engineer writes it (any
/// language); empty: the relazione says that it is not given.
struct ReportInfo {
  std::string client;          ///< committente
  std::string work;            ///< opera (the building, its name)
  std::string location;        ///< ubicazione (address); the site's coordinates are printed anyway
  std::string engineer;        ///< tecnico: name
  std::string registration;    ///< albo professionale and number
  std::string revision;        ///< revisione of the document
  std::string place;           ///< luogo of the signature
  std::string description;     ///< descrizione dell'edificio
  std::string investigations;  ///< rilievo, indagini, what justifies LC and FC (C8.5.4)
  std::string masonry;         ///< tipologia muraria (Tab. C8.5.I)
  /// Masonry parameters (MPa; NaN when not given): fm, tau0, E, G.
  double fm = std::numeric_limits<double>::quiet_NaN(), tau0 = std::numeric_limits<double>::quiet_NaN();
  double E = std::numeric_limits<double>::quiet_NaN(), G = std::numeric_limits<double>::quiet_NaN();
  std::string mechanism_criteria;  ///< criteri di scelta dei meccanismi
  bool heritage = false;           ///< bene tutelato: the DPCM 9/2/2011 indices are named
};

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
  /// The values the case did not give that move a result (issue 41): listed in
  /// the JSON and the relazione (the dynamic section's in DynamicSpec::defaults).
  std::vector<CaseDefault> defaults;
  CheckInput checks;              ///< codes, q, damping, SLD (hazard filled from the site when run)
  /// The procedure the engineer adopts (Circ. 2019 C8.7.1.2, alternatives):
  /// "linear", "nonlinear" (default) or "dynamic"; its verdict is the
  /// conclusion (assessment/verdict.hpp, docs/theory/facade.md §6).
  std::string method = "nonlinear";
  ReportInfo report;              ///< "report": what the relazione says of the work (issue 28)
  /// Issues 23, 29: the tie levels that act in this case's analyses, SI
  /// inside (the file uses mm, MPa, kN, m: docs/user/case-file.md §Ties);
  /// every candidate is analysed with the levels whose anchor lies on one of
  /// its moving blocks. As read from a file: the ties marked "existing" (the
  /// stato di fatto); the intervention adds new_ties or a design's.
  std::vector<Tie> ties;
  /// Issue 29: the given ties that are not "existing": the intervention (stato
  /// di progetto), assessed by assessment/tie_intervention.hpp.
  std::vector<Tie> new_ties;
  /// Issue 23: "design": {"ties": ...}: the ties to design (assessment/tie_intervention.hpp).
  std::optional<TieDesignSpec> tie_design;
  /// Reserved for the façade issue: the raw "dynamic" section, not parsed here.
  nlohmann::json dynamic;
  /// Plausibility warnings of the input (field, value, unit, why); the run goes on.
  std::vector<std::string> warnings;
  /// Issue 36: the knowledge levels the engineer's text of the investigations
  /// ("report"/"investigations") names ("LC1" ...), in order, each once. The
  /// level has one source, the case key: a text that names another level
  /// than knowledge_level (or one whose FC differs from a given "FC") is
  /// flagged in the warnings and in the relazione (knowledge_level_conflict).
  std::vector<std::string> knowledge_levels_stated;
  /// The document the case was parsed from (issue 36): the modelling
  /// choices' alternatives are this case with one key changed
  /// (assessment/modelling_choices.hpp), named by its JSON path.
  nlohmann::json source;
};

/// The levels of c.knowledge_levels_stated that contradict the adopted one
/// (another level; with a given FC, a level whose FC of Tab. C8.5.IV differs).
std::vector<std::string> knowledge_level_conflict(const CaseFile& c);

/// Parses a case document; errors name `file` and the JSON path.
CaseFile parse_case(const nlohmann::json& doc, const std::string& file);
/// The values `doc` does not give that move a result, as parse_case assumed
/// them in `c` (issue 41; case_default.hpp).
std::vector<CaseDefault> case_defaults(const nlohmann::json& doc, const CaseFile& c);
/// Reads and parses a case file.
CaseFile read_case_file(const std::string& path);

/// The analysis of one candidate mechanism.
struct CandidateResult {
  std::string label;
  double parameter = 0.0;
  double Z = 0.0;  ///< m
  KinematicResult result;
  std::vector<CheckRow> checks;  ///< its checks, every requested code (empty without a site)
  /// Per code ("NTC2008", "NTC2018"): the largest D/C over its checks (-).
  std::map<std::string, double> max_dc;
  /// Per code: the lowest safety index zetaE over its checks (-; check_index.hpp),
  /// below 1 exactly where max_dc is above 1; absent without a defined index.
  std::map<std::string, double> zeta_min;
};

struct KinematicCaseResult {
  std::vector<CandidateResult> candidates;
  /// The governing candidate: the largest D/C over its checks for NTC 2018
  /// (equivalently the lowest PGA capacity), else for the first code; without
  /// a site, the smallest alpha0. The dynamic analysis uses this one.
  std::size_t governing = 0;
  /// The governing candidate of each code (largest D/C over its checks).
  std::map<std::string, std::size_t> governing_by_code;
  /// The checks of each code's governing candidate (empty without a site).
  std::vector<CheckRow> checks;
  std::map<LimitState, SeismicAction> actions;  ///< the site's hazard per limit state
  /// What the checks were given (hazard, site, building, q, damping, codes);
  /// Z is each candidate's own (CandidateResult::Z). Empty without a site.
  std::optional<CheckInput> check_input;
  /// Summary by approach over every candidate (kinematic rows only).
  Verdict verdict;
  /// The case's warnings, then those of the analysis (alpha0 > 1, Z > H).
  std::vector<std::string> warnings;
};

/// Issue 23: the restraints of the case's tie levels on one candidate's chain
/// (levels whose anchor is on none of its moving blocks are left out).
std::vector<TieRestraint> case_tie_restraints(const CaseFile& c, const Chain& chain);

/// Analyses and checks every candidate and picks the governing one per code.
/// @throws InputError when a candidate is statically unstable (alpha0 <= 0:
///   it overturns under its static loads alone), naming alpha0 and the loads;
///   for a building block that cannot be used (naming the file and /building).
/// `indices` false leaves the checks' safety indices undefined (a
/// recomputation that only needs their D/C: sensitivity.hpp).
KinematicCaseResult run_kinematic_case(const CaseFile& c, bool indices = true);
/// The same case with other readings that leave every candidate's chain and
/// tie levels as they are (FC, d_SLV/d0*, d_SLC/d0*, the damping, Z, the
/// rotation bounds): each candidate's analysis re-derived on the marched path
/// of `marched` (rederive_kinematic), bit for bit the result of
/// run_kinematic_case(c, indices) without marching again. `marched` must be a
/// result of this case's chains and levels; null: run_kinematic_case(c, indices).
KinematicCaseResult run_kinematic_case(const CaseFile& c, bool indices, const KinematicCaseResult* marched);

}  // namespace assess
