// fragility_study.hpp: the set-up of a fragility analysis of a case's
// governing mechanism: its dynamic model (assessment/mechanism_dynamics, the
// one `assess run` uses: a rocking body or a chain of several blocks, with
// one analysis per restitution value of the case's dynamic section, and at
// height the first-mode floor motion), the site's hazard curve, and the
// intensity levels with their records and scale factors:
//  - multiple-stripe analysis (MSA): at each return period, records selected
//    from the catalogue compatible with the site's elastic spectrum at that
//    return period and scaled to its PGA (records/record_selection, rule Pga);
//  - incremental dynamic analysis (IDA): one fixed set (the case's listed
//    records, or its selection at SLV) scaled to each PGA level.
// The intensity measure is the PGA on the site's ground, IM = Se(0) = ag S
// (m/s^2), the same as the hazard curve's (also for a mechanism at height:
// the ground record is scaled, then filtered to the floor). See
// docs/theory/fragility.md.
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/assessment/dynamic_case.hpp"
#include "assess/assessment/mechanism_dynamics.hpp"
#include "assess/dynamics/rocking_analysis.hpp"
#include "assess/hazard/hazard_curve.hpp"
#include "assess/records/record.hpp"
#include "assess/records/record_selection.hpp"

#include <cstdint>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace assess {

enum class FragilityMethod { stripes, ida };
std::string to_string(FragilityMethod m);

/// Settings of a fragility analysis, with documented defaults.
struct FragilityOptions {
  FragilityMethod method = FragilityMethod::stripes;
  /// Stripes: return periods (years), each in [30, 2475]; default the nine
  /// return periods of the hazard grid.
  std::vector<double> return_periods;
  /// IDA: PGA levels (m/s^2), > 0; default 16 levels log-spaced from half the
  /// site's PGA at 30 years to three times its PGA at 2475 years.
  std::vector<double> ida_levels;
  /// Records per stripe (stripes) or in the set (IDA); 0 = the case's
  /// "select/count" (default 7). Listed records (IDA) are all used.
  int records = 0;
  /// Bootstrap replicates over records for the confidence bounds (default
  /// 500; 0 = none) and the seed of their generator (default 1).
  int bootstrap = 500;
  std::uint64_t seed = 1;
  /// Two-sided confidence level of the bounds (default 0.90: 5 % and 95 %).
  double confidence = 0.90;
  /// @throws InputError naming the field and its unit
  void validate() const;
};

/// A record of a stripe and its scale factor.
struct StripeRecord {
  std::size_t record = 0;  ///< index in FragilityStudy::records
  double scale = 1.0;      ///< linear factor (-): the record's PGA times it is the stripe's im
};

/// One intensity level.
struct Stripe {
  double im = 0.0;          ///< PGA on the site's ground (m/s^2)
  double TR = 0.0;          ///< its return period on the site's hazard curve (years)
  std::vector<StripeRecord> records;
  std::string selection;    ///< stripes: the selection's status and message; IDA: empty
  bool compatible = true;   ///< stripes: the mean spectrum is within the band
};

/// What one analysis of the mechanism gives the limit states (SI).
struct MechanismResponse {
  RockingTermination termination = RockingTermination::completed;
  std::string message;          ///< why the analysis failed, if it did
  double theta_max = 0.0, theta_u = 0.0;  ///< rad (a chain: its coordinate q and q_u)
  double d_star = 0.0;          ///< peak d* of the control point [C8.7.1.4] (m)
  double dc_energy = 0.0;       ///< energy demand/capacity (seed §3.2)
  double dc_displacement = 0.0; ///< d* / d_SLV [C8.7.1.2.1.9]
  bool overturned = false;
  bool ok() const {
    return termination == RockingTermination::completed || termination == RockingTermination::overturned;
  }
};

/// Everything the analyses need, built once.
struct FragilityStudy {
  std::string file;            ///< the case file
  std::string project;
  FragilityOptions options;
  std::string site_description;
  double VN = 50.0, VR = 50.0;  ///< nominal life and reference period (years)
  std::map<LimitState, SeismicAction> actions;  ///< the code's limit states at the site
  std::map<LimitState, double> action_pga;      ///< Se(0) = ag S of each (m/s^2)
  std::optional<HazardCurve> hazard;            ///< PGA hazard curve of the site
  // The mechanism (the governing candidate of the kinematic analysis).
  std::string mechanism;        ///< its label
  KinematicResult kinematic;    ///< its kinematic result (d_SLV, dk0, control point, ...)
  std::vector<CheckRow> checks; ///< the code's checks of the case (both editions)
  DynamicSpec dynamic;
  MechanismDynamics dynamics;                ///< rocking body or chain, base motion (as `assess run`)
  std::vector<std::string> restitution_labels;
  std::vector<bool> polarities;              ///< false = as recorded, true = reversed
  // Records and levels.
  std::vector<Record> records;               ///< unscaled ground records
  std::vector<std::string> record_files;
  /// At height: the unscaled floor motion of each record used by a stripe
  /// (dynamics.input; the filter is linear, so scaling and reversing commute
  /// with it); empty at ground level (the records themselves).
  std::vector<Record> floor_inputs;
  std::vector<Stripe> stripes;               ///< increasing im
  std::vector<std::string> selection_warnings;  ///< the catalogue filters' warnings (default windows, relaxed class)

  /// The motion at the mechanism's base of record i, unscaled: the ground
  /// record, or its floor motion at height.
  const Record& base_motion(std::size_t i) const { return floor_inputs.empty() ? records.at(i) : floor_inputs.at(i); }

  /// The only entry point to the dynamics: one analysis of the mechanism under
  /// the base motion `input` (base_motion) scaled by `scale`, polarity flipped
  /// if `reversed`, with restitution value `restitution`, through
  /// MechanismDynamics::analyse (rocking model or chain model). Thread-safe.
  MechanismResponse respond(const Record& input, double scale, bool reversed, std::size_t restitution) const;

  /// Number of restitution values.
  std::size_t restitutions() const { return restitution_labels.size(); }
  /// Analyses per (stripe, record) group: polarities x restitutions.
  std::uint64_t group_size() const { return polarities.size() * restitutions(); }
  /// Number of (stripe, record) groups.
  std::uint64_t groups() const;
  /// Number of analyses.
  std::uint64_t size() const { return groups() * group_size(); }
  /// The (stripe, position in the stripe) of group g.
  std::pair<std::size_t, std::size_t> group(std::uint64_t g) const;
};

/// Builds the study of a case with a "site" (grid or island: a hazard curve
/// is needed) and a "dynamic" section with ground records whose governing
/// mechanism the dynamics module handles (build_mechanism_dynamics: one body,
/// any 1-DOF chain, at ground level or at height with a "building").
/// @throws InputError naming the file, the JSON path and why (among them a
///   mechanism the dynamic model cannot represent, and "input": "floor").
FragilityStudy prepare_fragility(const CaseFile& kase, const FragilityOptions& options);

}  // namespace assess
