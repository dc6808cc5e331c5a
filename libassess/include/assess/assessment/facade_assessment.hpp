// facade_assessment.hpp: the façade assessment of one case file: the code's
// linear (strength) and non-linear (displacement) kinematic checks and the
// non-linear dynamic rocking analysis under real records, side by side
// (seed paper §4, Fig. 8; Circ. 2019 C8.7.1.2.1.9).
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/assessment/dynamic_case.hpp"
#include "assess/assessment/dynamic_part.hpp"
#include "assess/assessment/acceptability.hpp"
#include "assess/assessment/judgement.hpp"
#include "assess/assessment/mechanism_dynamics.hpp"
#include "assess/assessment/modelling_choices.hpp"
#include "assess/assessment/report_curves.hpp"
#include "assess/assessment/safety_index.hpp"
#include "assess/assessment/selection_summary.hpp"
#include "assess/assessment/sensitivity.hpp"
#include "assess/assessment/site_hazard.hpp"
#include "assess/assessment/verdict.hpp"
#include "assess/records/record_selection.hpp"
#include "assess/dynamics/rocking_from_chain.hpp"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace assess {

struct FacadeOptions {
  /// Continue with the records that can be read when some cannot (the
  /// failures are listed in the result); default: a record that cannot be
  /// read is an error.
  bool keep_going = false;
  /// Keep theta(t) of every analysis (for plots). Default true.
  bool histories = true;
  /// Issue 36: the review of the result a relazione and its summary print:
  /// the modelling choices with their alternatives computed, the checks of
  /// acceptability (NTC 2018 §10.2) and the judgement (review.hpp). Off for
  /// the analyses that only need the verdict (`--json`, the alternatives
  /// themselves, the other candidates' dynamics, campaigns).
  bool review = true;
  /// With the review, the records' alternative (the selection's windows)
  /// even when it cannot change the adopted verdict: the relazione's table of
  /// the modelling choices (`assess run` with a report file).
  bool review_records = true;
  /// Compute the sensitivity of the adopted verdict (sensitivity.hpp); the
  /// other candidates' dynamic assessments do without.
  bool sensitivity = true;
  /// The kinematic results of a case whose kinematic inputs (mechanism, ties,
  /// readings, site, building) are this case's, already computed by
  /// run_kinematic_case: reused as they are (the modelling choices'
  /// alternative of the record selection, which changes /dynamic alone).
  const KinematicCaseResult* kinematic = nullptr;
};

/// The result of a façade assessment, in typed parts: the case and its
/// kinematic analysis, the site's hazard, the checks and their verdict, the
/// record selection and the dynamic analysis, the review, and the curves of the
/// report (docs/architecture.md, "The result model").
struct FacadeAssessment {
  CaseFile kase;
  KinematicCaseResult kinematic;
  SiteHazard site;               ///< the site's actions and spectra per limit state
  SelectionSummary selection;    ///< how the records were chosen (selected or listed)
  DynamicPart dynamics;          ///< the dynamic analysis (when the case has a "dynamic" section)
  /// Every check: the kinematic rows of both editions, then "dynamic" rows.
  std::vector<CheckRow> checks;
  /// Summary by approach and overall verdict per code (every candidate's
  /// checks, the dynamic rows and dynamics.energy_rows): the reports format it.
  Verdict verdict;
  /// The safety indices per code and approach (safety_index.hpp): the lowest
  /// index of the approach's checks beside its verdict, computed once here.
  std::vector<SafetyIndex> indices;
  /// The adopted method's D/C under the readings a verificatore questions
  /// first (FC, d_SLV/d0*, xi): sensitivity.hpp, computed once here.
  std::vector<SensitivityRow> sensitivity;
  /// Plausibility and compatibility warnings (field, value, unit, why).
  std::vector<std::string> warnings;
  /// Issue 36 (FacadeOptions::review): the modelling choices with their
  /// alternatives computed, the checks of acceptability, and the judgement
  /// of the adopted verdict drawn from them (absent without the review).
  std::vector<ModellingChoice> choices;
  std::vector<AcceptabilityCheck> acceptability;
  std::optional<Judgement> judgement;

  /// The curves of the report (computed here so the report never recomputes physics).
  ReportCurves curves;

  /// The dynamic analyses of the other candidates (issue 24; docs/theory/facade.md §6.3):
  /// every candidate besides the governing one that governs a code or fails one of
  /// its kinematic checks, so that no mechanism that fails is left without its
  /// dynamic check. Each is the assessment of the case restricted to that
  /// candidate: the same code path, and the same numbers, as a run of that
  /// candidate alone. Their dynamic rows are in `checks` and their energy rows
  /// in `dynamics.energy_rows`, so the dynamic verdict is the worst over all of them.
  /// Histories are kept when the options ask for them (the relazione shows the
  /// histories of the candidate that governs the dynamic verdict).
  std::vector<FacadeAssessment> other_dynamics;
  /// The candidate index (in kinematic.candidates) of each of other_dynamics.
  std::vector<std::size_t> other_dynamics_candidate;
};

/// The candidates whose dynamic analysis the assessment adds to the governing
/// one's: those that govern a code or fail (or cannot give a verdict in) one of
/// their kinematic checks, in candidate order, the governing one excluded.
std::vector<std::size_t> dynamic_candidates(const KinematicCaseResult& k);

/// The analyses of the model `md` (every restitution value, record and
/// polarity, in this order, on all cores) under the base motions of `a`
/// (records, scales and polarities of its dynamic section), the
/// C8.7.1.2.1.9 displacements measured at the control point of `kin`.
std::vector<DynamicRun> dynamic_runs(const FacadeAssessment& a, const MechanismDynamics& md, const KinematicResult& kin,
                                     bool histories);

/// The capacity d_SLV (m) of the dynamic check: kin.d_SLV, the one capacity
/// of the state (issue 37: with tie levels, the curve with each level breaking
/// where it fails; docs/theory/ties.md §2, §6).
double dynamic_d_SLV(const KinematicResult& kin);

/// The analyses of each restitution value summarised against `kin`'s d_SLV
/// (Circ. 2019 C8.7.1.2.1.9, NTC 2018 §7.3.5 on the records' count).
std::vector<RestitutionSummary> summarise_runs(const std::vector<DynamicRun>& runs, const std::vector<double>& e,
                                               const KinematicResult& kin);

/// Every value the case did not give that moves a result (issue 41): the
/// case's (CaseFile::defaults) and its dynamic section's (DynamicSpec::defaults).
std::vector<CaseDefault> assessment_defaults(const FacadeAssessment& a);

/// Whether the record set a case's selection gives over its own
/// /dynamic/select/period_range_s can be used (docs/theory/building.md §3):
/// a compatible set whose mean spectrum stays within the -10 %/+30 % band of
/// the SLV spectrum over the range (NTC 2018 §3.2.3.6). The same selection
/// the assessment makes (memoised per process: no second cost). Empty when
/// usable, else why not (a note as data). @throws InputError for a bad selection section.
NoteText shared_selection_problem(const CaseFile& kase);

/// Runs the whole assessment of a case. Throws InputError for bad input
/// (naming the JSON path); physical outcomes are results.
FacadeAssessment assess_facade(const CaseFile& kase, const FacadeOptions& options = {});


}  // namespace assess
