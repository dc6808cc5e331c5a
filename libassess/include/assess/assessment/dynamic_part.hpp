// dynamic_part.hpp: the dynamic part of a façade assessment (Circ. 2019
// C8.7.1.2.1.9, seed paper §4): the model of the governing candidate, the
// records used, every time-history analysis, their summaries per restitution
// value, the records' compatibility with the SLV spectrum and the seed paper's
// energy rows.
#pragma once

#include "assess/assessment/dynamic_case.hpp"
#include "assess/assessment/mechanism_dynamics.hpp"
#include "assess/support/note.hpp"
#include "assess/dynamics/rocking_from_chain.hpp"
#include "assess/kinematic/code_checks.hpp"
#include "assess/kinematic/outcome.hpp"
#include "assess/records/record_io.hpp"
#include "assess/records/record_selection.hpp"

#include <cstddef>
#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace assess {

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
  /// stated class its Vs30 contradicts, scale above the default cap, no metadata:
  /// notes as data (note.hpp).
  std::vector<Note> flags;
  double duration_s = 0.0;       ///< length of the record file (s)
  double integrated_s = 0.0;     ///< excitation integrated (s): the whole motion at the mechanism's base
};

/// One time-history analysis.
struct DynamicRun {
  std::size_t record = 0;       ///< index in DynamicPart::records
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
  NoteText message;  ///< the comparison in words, as data ("mean spectrum of the 7 records / SLV spectrum ...")
};

/// The dynamic part of FacadeAssessment (present when the case has a
/// "dynamic" section): what was analysed, under which records, and the results.
struct DynamicPart {
  std::optional<DynamicSpec> spec;  ///< the case's "dynamic" section, parsed (empty without one)
  bool applies = false;             ///< the mechanism has a dynamic model and it was analysed
  NoteText note;                    ///< why it does not apply, or the model's description (as data)
  std::optional<ChainRockingBody> body;  ///< one rotating body (rocking model); empty for a multi-block chain
  std::optional<RockingModel> model;     ///< model of the first restitution value (geometry, theta_u, capacity)
  /// The dynamic model of the governing mechanism: rocking body or chain, and its base motion.
  std::optional<MechanismDynamics> mechanism;
  std::vector<RecordUsed> records;
  std::vector<DynamicRun> runs;
  /// The motion at the mechanism's base of each record (unscaled): the
  /// analyses' inputs (also of the tie rods' before/after, issue 23).
  std::vector<Record> base_motions;
  std::vector<RestitutionSummary> summaries;
  double free_tail_s = 0.0;  ///< cap on the free motion after each record (s; dynamics/analysis_end.hpp)
  /// Compatibility of the records used with the SLV spectrum (listed or selected).
  SpectrumCompatibility compatibility;
  /// The seed paper's energy D/C per restitution value (code "seed", kind
  /// "dynamic energy"): informative, not a code check.
  std::vector<CheckRow> energy_rows;
};

}  // namespace assess
