// facade_assessment.hpp: the façade assessment of one case file: the code's
// linear (strength) and non-linear (displacement) kinematic checks and the
// non-linear dynamic rocking analysis under real records, side by side
// (seed paper §4, Fig. 8; Circ. 2019 C8.7.1.2.1.9).
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/assessment/dynamic_case.hpp"
#include "assess/assessment/acceptability.hpp"
#include "assess/assessment/judgement.hpp"
#include "assess/assessment/mechanism_dynamics.hpp"
#include "assess/assessment/modelling_choices.hpp"
#include "assess/assessment/safety_index.hpp"
#include "assess/assessment/sensitivity.hpp"
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

/// A record used by the dynamic analysis.
struct RecordUsed {
  std::string name, file, event, station, component;
  double scale = 1.0;    ///< scale factor applied (-)
  double pga = 0.0;      ///< PGA of the scaled record (m/s^2)
  std::string json_path; ///< where it was listed ("" if selected)
  // What the record is (the catalogue's metadata: selected records, and listed
  // records whose file is in the catalogue; NaN / "" when unknown).
  bool in_catalogue = false;     ///< metadata below come from the record library's catalogue
  std::string date, country, station_code;
  double Mw = std::numeric_limits<double>::quiet_NaN();
  double distance_km = std::numeric_limits<double>::quiet_NaN();
  std::string distance_kind, site_class, positive_direction;
  std::string site_class_basis;  ///< "stated" (by the source) or "Vs30" (NTC 2018 Tab. 3.2.II bands)
  std::string vs30_class;        ///< the class Vs30 implies (may differ from a stated class)
  double vs30_m_s = std::numeric_limits<double>::quiet_NaN();
  /// Longest usable period 1/f_low (s) where the source gives f_low; NaN unknown.
  double usable_period_s = std::numeric_limits<double>::quiet_NaN();
  std::string pulse;             ///< "pulse-like", "non-pulse" or "" (not classified)
  /// Why the record is near-fault or pulse-like ("" if its metadata do not say so).
  std::string near_fault;
  // Why it was chosen (selected records; NaN when listed).
  double deviation = std::numeric_limits<double>::quiet_NaN();  ///< individual misfit: RMS of f S/Se - 1 over the range (-)
  int rank = 0;                  ///< rank of that deviation among the eligible records (1 = best; 0 listed)
  bool misfit_flag = false;      ///< deviation above the selection's max_misfit
  /// The caveats of this record, computed (record-selection.md §2.8): near-fault
  /// or pulse-like, misfit above the limit, class other than the site's, a
  /// stated class its Vs30 contradicts, scale above the default cap, no metadata.
  std::vector<std::string> flags;
  double duration_s = 0.0;       ///< length of the record file (s)
  double integrated_s = 0.0;     ///< excitation integrated (s): the whole motion at the mechanism's base
};

/// One time-history analysis.
struct DynamicRun {
  std::size_t record = 0;       ///< index in FacadeAssessment::records
  bool reversed = false;        ///< polarity flipped
  std::size_t restitution = 0;  ///< index in DynamicSpec::restitutions
  double e = 0.0;               ///< coefficient used (velocity ratio)
  RockingResult result;
  double theta_ratio = 0.0;     ///< theta_max / theta_u (-)
  double d_control = 0.0;       ///< peak horizontal displacement of the control point (m)
  double d_star = 0.0;          ///< the same in the equivalent SDOF [C8.7.1.4] (m)
  bool ruptured = false;        ///< tied mechanism: a rod's elongation exceeded eps_ud L (it breaks) [I]
  bool collapse = false;        ///< overturned, d_control >= dk0 (the threshold d0 of C8.7.1.2.1.9), or a rod broken
};

/// The analyses of one restitution value, summarised (seed Fig. 8; Circ. 2019 C8.7.1.2.1.9).
struct RestitutionSummary {
  std::size_t restitution = 0;
  double e = 0.0;
  int analyses = 0;
  int overturned = 0;
  int ruptured = 0;               ///< analyses in which a tie rod broke (tied mechanisms)
  /// Analyses that failed (step or event limit, integrator error): left out
  /// of the statistics, and the check is then not satisfied (a result that
  /// cannot be trusted is a failure).
  int failed = 0;
  double mean_dc = 0.0, min_dc = 0.0, max_dc = 0.0;  ///< energy demand/capacity (-)
  double mean_theta_ratio = 0.0;                     ///< mean theta_max/theta_u (-)
  /// Mean over the records of the peak d* (envelope of the polarities) (m).
  double mean_d_star = 0.0;
  bool any_collapse = false;      ///< d0 exceeded (or overturning) in some analysis
  double max_d_star = 0.0;        ///< the largest peak d* over the records (m)
  int records = 0;                ///< number of records N
  /// NTC 2018 §7.3.5: "mean" (N >= 7), "most unfavourable" (3 <= N <= 6),
  /// "none" (N < 3: no verdict unless a collapse already fails it).
  std::string rule;
  double d_demand = 0.0;          ///< the demand of the rule: mean or largest peak d* (m)
  bool no_verdict = false;        ///< N < 3 and no collapse: the records cannot support a verdict
  bool slv_satisfied = false;     ///< no failed analysis, no collapse and d_demand <= d_SLV (and a verdict)
  Outcome outcome() const { return outcome_of(slv_satisfied, no_verdict); }
  double dc_slv = 0.0;            ///< d_demand / d_SLV (-); +inf with a collapse or a failed analysis
  /// Issue 28 (docs/theory/facade.md §6.4): with a collapse (d0 exceeded or
  /// overturned) the displacement demand is unbounded and d_demand = dc_slv =
  /// +inf; with a failed analysis there is no trustworthy demand and they are
  /// +inf too. The same figures over the records none of whose analyses
  /// collapsed or failed are given apart (NaN when there is none):
  int collapsed = 0;                    ///< analyses with a collapse
  int records_survived = 0;             ///< records none of whose analyses collapsed or failed
  double d_demand_survivors = std::numeric_limits<double>::quiet_NaN();  ///< rule's demand over them (m)
  double dc_survivors = std::numeric_limits<double>::quiet_NaN();        ///< d_demand_survivors / d_SLV (-)
  /// The seed energy D/C of the check: mean_dc when no analysis overturned or
  /// failed, else +inf; mean_dc_survivors is the mean over the analyses that
  /// did not overturn (NaN when none).
  double energy_dc = 0.0;
  double mean_dc_survivors = std::numeric_limits<double>::quiet_NaN();
};

/// Compatibility of the records' mean 5 % spectrum with the SLV elastic
/// spectrum over a period range (NTC 2018 §3.2.3.6: -10 %/+30 %).
struct SpectrumCompatibility {
  bool computed = false;
  PeriodRange range{};
  double min_ratio = 0.0, max_ratio = 0.0;  ///< min and max over the range of mean/Se (-)
  bool band_satisfied = false;
  std::string message;
};

/// The demand curve of one displacement check of the governing candidate in
/// the ADRS plane (issue 24): the check's own demand function of the secant
/// period (kinematic/code_checks.hpp displacement_demand, at its damping and,
/// at height, on the floor spectrum), Sd = d(T), Sa = d(T) (2 pi / T)^2.
struct AdrsDemand {
  std::string code, limit_state, location;  ///< as in its CheckRow
  double xi_pct = 5.0;                      ///< damping of the demand (%)
  std::vector<double> Sd;                   ///< m, at FacadeAssessment::adrs_periods
  std::vector<double> Sa;                   ///< m/s^2
};

struct FacadeAssessment {
  CaseFile kase;
  KinematicCaseResult kinematic;
  std::map<LimitState, SeismicAction> actions;  ///< the site's limit states (all four from the grid)
  std::map<LimitState, ElasticSpectrum> spectra;  ///< 5 % elastic spectrum of each of them
  std::string site_description;                   ///< Site::describe()
  double VR = 0.0;                                ///< reference period (years)
  /// Dynamic part (present when the case has a "dynamic" section).
  std::optional<DynamicSpec> dynamic;
  bool dynamic_applies = false;
  std::string dynamic_note;  ///< why it does not apply, or remarks
  std::optional<ChainRockingBody> body;  ///< one rotating body (rocking model); empty for a multi-block chain
  std::optional<RockingModel> model;  ///< model of the first restitution value (geometry, theta_u, capacity)
  /// The dynamic model of the governing mechanism: rocking body or chain, and its base motion.
  std::optional<MechanismDynamics> mechanism_dynamics;
  std::vector<RecordUsed> records;
  std::optional<SelectionResult> selection;
  PeriodRange selection_range{};
  std::string selection_limit_state = "SLV";  ///< spectrum the records are compatible with
  /// Why the range: the mechanism periods it spans (s), e.g. Ts and T_SLV.
  double selection_T_first = 0.0, selection_T_last = 0.0;
  std::vector<std::string> selection_warnings;  ///< default windows, relaxed site class, ...
  std::size_t selection_candidates = 0;         ///< records passing the catalogue filters
  std::vector<std::string> selection_site_classes;  ///< classes accepted in the end (empty = any)
  double selection_max_pga_ratio = 0.0;         ///< the PGA guard used (-)
  double selection_max_scale = 0.0, selection_max_mean_scale = 0.0;  ///< scale limits used (-)
  double selection_max_misfit = 0.0;            ///< misfit above which a record is flagged (-)
  bool selection_include_near_fault = false;    ///< near-fault / pulse-like records admitted
  double selection_near_fault_km = 0.0;         ///< distance threshold of the near-fault flag (km)
  std::size_t selection_near_fault_excluded = 0;  ///< near-fault / pulse-like records left out
  /// The site-class ladder tried: classes, candidates, outcome (the last is used).
  std::vector<std::string> selection_steps;
  std::string selection_spectra;   ///< "precomputed" (interpolated) or "integrated" candidates' spectra
  /// Why the period range is what it is (computed: the mechanism periods, the
  /// factors, the cap, and the limit-state periods it does not reach).
  std::string selection_range_note;
  /// Several candidates analysed dynamically (issue 24): how their selection
  /// was shared (one set over the union of their ranges, or each its own).
  std::string selection_shared_note;
  double free_tail_s = 0.0;   ///< cap on the free motion after each record (s; dynamics/analysis_end.hpp)
  std::vector<std::string> record_failures;  ///< "<path>: <message>" of records skipped (--keep-going)
  std::vector<DynamicRun> runs;
  /// The motion at the mechanism's base of each record (unscaled): the
  /// analyses' inputs (also of the tie rods' before/after, issue 23).
  std::vector<Record> base_motions;
  std::vector<RestitutionSummary> summaries;
  /// Every check: the kinematic rows of both editions, then "dynamic" rows.
  std::vector<CheckRow> checks;
  /// The seed paper's energy D/C per restitution value (code "seed", kind
  /// "dynamic energy"): informative, not a code check.
  std::vector<CheckRow> energy_rows;
  /// Compatibility of the records used with the SLV spectrum (listed or selected).
  SpectrumCompatibility compatibility;
  /// Summary by approach and overall verdict per code (every candidate's
  /// checks, the dynamic rows and the energy rows): the reports format it.
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

  // Curves for the report (computed here so the report never recomputes physics).
  std::vector<double> periods;                         ///< s (0 first, then log-spaced to 4 s)
  std::map<LimitState, std::vector<double>> site_Se;   ///< 5 % elastic Se at `periods` (m/s^2)
  std::vector<std::vector<double>> record_psa;         ///< scaled 5 % PSA of each record at `periods` (m/s^2)
  std::vector<double> mean_psa;                        ///< their mean (m/s^2)
  std::vector<double> mr_theta, mr_moment;             ///< moment-rotation curve of the body: rad, N m/m
                                                       ///< (chain: q and the generalised force per unit length)
  /// Mechanism at height with ground records filtered to the floor: the 5 %
  /// spectrum of the floor motions (mean over the records, scaled, m/s^2) and
  /// the code's floor spectrum S_eZ(T) [C7.2.6] at 5 % for the SLV hazard, at `periods`.
  std::vector<double> floor_mean_psa, code_floor_Se;
  /// The ADRS demand curves of the governing candidate's displacement checks (issue 24), at adrs_periods (s).
  std::vector<AdrsDemand> adrs;
  std::vector<double> adrs_periods;
  /// The same for every candidate (index as in kinematic.candidates; issue 28:
  /// the relazione develops each candidate that governs a method).
  std::vector<std::vector<AdrsDemand>> candidate_adrs;

  /// The dynamic analyses of the other candidates (issue 24; docs/theory/facade.md §6.3):
  /// every candidate besides the governing one that governs a code or fails one of
  /// its kinematic checks, so that no mechanism that fails is left without its
  /// dynamic check. Each is the assessment of the case restricted to that
  /// candidate: the same code path, and the same numbers, as a run of that
  /// candidate alone. Their dynamic rows are in `checks` and their energy rows
  /// in `energy_rows`, so the dynamic verdict is the worst over all of them.
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
/// the assessment makes (memoised per process: no second cost). "" when
/// usable, else why not. @throws InputError for a bad selection section.
std::string shared_selection_problem(const CaseFile& kase);

/// Runs the whole assessment of a case. Throws InputError for bad input
/// (naming the JSON path); physical outcomes are results.
FacadeAssessment assess_facade(const CaseFile& kase, const FacadeOptions& options = {});


}  // namespace assess
