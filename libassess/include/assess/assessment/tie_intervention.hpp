// tie_intervention.hpp: the tie rods of a case (issue 23): the mechanism
// before and after the ties, side by side, with the checks of every tie
// level, the force each check of the mechanism needs, and zeta_E before and
// after; with "design": {"ties": ...}, the smallest commercial rod and plate
// (kinematic/tie_catalogue.hpp) that make every check pass.
// docs/theory/ties.md §5.
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/assessment/facade_assessment.hpp"
#include "assess/kinematic/tie_checks.hpp"
#include "assess/kinematic/tie_design.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// One tied analysis (issue 23): the run of the façade assessment with the same
/// record, polarity and restitution, now with the tie (dynamics/tied_rocking.hpp).
struct TieDynamicRun {
  std::size_t run = 0;            ///< index of the analysis (restitution, record, polarity order of FacadeAssessment::runs)
  double theta_max = 0.0;         ///< rad
  double theta_collapse = 0.0;    ///< rad
  bool overturned = false;
  bool yielded = false;
  double max_force = 0.0;         ///< per tie (N)
  double plastic_elongation = 0.0;  ///< m
  double plastic_energy = 0.0;    ///< per tie (J)
  double max_elongation = 0.0;    ///< largest elongation of the rod (m)
  bool ruptured = false;          ///< max_elongation > eps_ud L (tie_checks): the rod breaks [I]
  double d_star = 0.0;            ///< peak d* (m)
  bool collapse = false;          ///< overturned, ruptured or d_control >= d_k0 of the tied mechanism
  bool failed = false;            ///< the integration did not complete
};

/// The dynamic check (Circ. 2019 C8.7.1.2.1.9) before and after, per restitution value.
struct TieDynamicSummary {
  double e = 0.0;
  int records = 0;
  std::string rule;              ///< "mean" (N >= 7), "most unfavourable" (3..6), "none"
  int overturned_before = 0, overturned_after = 0;
  double d_demand_before = 0.0, d_demand_after = 0.0;  ///< m
  double d_SLV_before = 0.0, d_SLV_after = 0.0;        ///< m
  bool collapse_before = false, collapse_after = false;
  bool satisfied_before = false, satisfied_after = false;
  int yielded = 0;               ///< analyses in which the rod yielded
  int ruptured = 0;              ///< analyses in which its elongation exceeded eps_ud L
  double max_plastic_elongation = 0.0;  ///< m
};

struct TieDynamicResult {
  bool applies = false;
  std::string note;              ///< why not, or what was done
  std::vector<TieDynamicRun> runs;
  std::vector<TieDynamicSummary> summaries;
};

/// One tie level after the intervention.
struct TieLevelResult {
  Tie tie;
  TieResistance resistance;
  double count = 0.0;  ///< ties on the governing candidate's chain (-)
  /// Per check of the governing candidate (NTC 2018, else the first code):
  /// the force this level needs, the other levels as given.
  std::vector<RequiredTieForce> required;
  double N_Ed = 0.0;   ///< demand on one tie: the largest required force per tie (N)
  std::optional<double> elongation_demand;  ///< rod elongation at the largest displacement demand (m)
  std::vector<TieCheckRow> checks;
  bool satisfied = false;
};

struct TieInterventionResult {
  bool designed = false;      ///< from "design" (else the case's "ties" are assessed)
  bool found = false;         ///< design: a rod and plate of the lists satisfy every check
  std::string message;        ///< why no design was found
  int tried = 0;              ///< design: combinations analysed
  CaseFile case_before, case_after;  ///< the case without / with the ties (after: the designed ones)
  KinematicCaseResult before, after;
  std::vector<TieLevelResult> levels;
  /// zeta_E = PGA capacity / PGA demand (NTC 2018 rows of the adopted
  /// procedure, SLV and SLC, every candidate; the smallest) (-); NaN without NTC 2018.
  double zetaE_before = 0.0, zetaE_after = 0.0;
  bool passes_before = false, passes_after = false;  ///< every kinematic check satisfied
  /// The dynamic check before and after (filled by run_tie_dynamics when the
  /// case has a "dynamic" section; applies = false otherwise).
  TieDynamicResult dynamics;
};

/// Every kinematic check of every candidate satisfied (with a verdict): the
/// reading of passes_before / passes_after.
bool every_kinematic_check_satisfied(const KinematicCaseResult& r);

/// True when the case has ties or a design of ties.
bool has_ties(const CaseFile& c);

/// The intervention of the case (has_ties(c) must hold). Needs a site for
/// the checks; throws InputError otherwise.
TieInterventionResult run_tie_intervention(const CaseFile& c);

/// The dynamic check before and after the ties of `t`, per restitution value
/// (docs/theory/ties.md §6). The façade's analyses are those of its case, with
/// any given ties already holding the wall (mechanism_dynamics); the other
/// side is the same model, records, polarities and candidate with the other
/// tie levels: without the given ties, or with the designed ones. `runs` are
/// the tied analyses. applies = false, with `note`, when the façade has no
/// dynamic analysis or the tied model cannot represent it (two-sided rocking).
TieDynamicResult run_tie_dynamics(const FacadeAssessment& a, const TieInterventionResult& t);

/// The tie step of an assessment, as `assess run` and the building case do it:
/// nothing when the case has no ties (has_ties false); otherwise the
/// intervention (run_tie_intervention) and its dynamics (run_tie_dynamics).
std::optional<TieInterventionResult> assess_ties(const FacadeAssessment& a);

/// zeta_E of a kinematic result for the adopted `method` (see above).
double zeta_E(const KinematicCaseResult& r, const std::string& method);

}  // namespace assess
