// code_checks.hpp: the checks of a local mechanism by NTC 2008 (Circ.
// 617/2009 C8A.4) and NTC 2018 (Circ. 2019 §C8.7.1.2.1.5-.8), at ground
// level and at height, linear (strength) and non-linear (displacement).
#pragma once

#include "assess/kinematic/check_index.hpp"
#include "assess/kinematic/floor_spectrum.hpp"
#include "assess/kinematic/outcome.hpp"
#include "assess/hazard/hazard.hpp"
#include "assess/kinematic/kinematic_analysis.hpp"
#include "assess/hazard/seismic_action.hpp"
#include "assess/hazard/spectrum.hpp"

#include <limits>
#include <map>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace assess {

enum class CodeEdition { NTC2008, NTC2018 };
std::string to_string(CodeEdition c);       ///< "NTC2008", "NTC2018"
CodeEdition parse_code_edition(const std::string& s);  ///< InputError otherwise

/// One check: demand, capacity (same unit), dc = demand / capacity, verdict
/// dc <= 1, and its safety index (check_index.hpp: the return period at which
/// this check reaches D/C = 1, zetaE = PGA_C / PGA_D), set by the assessment
/// that knows the site's hazard axis (run_kinematic_case).
struct CheckRow {
  std::string code;         ///< "NTC2008" | "NTC2018"
  std::string limit_state;  ///< "SLD" | "SLV" | "SLC"
  std::string kind;         ///< "strength" | "displacement"
  std::string location;     ///< "ground" | "height"
  std::string clause;       ///< clause and certainty tag
  std::string formula;      ///< the demand, in words ("ag S / q", "SDe(Ts)" ...)
  double demand = 0.0;
  double capacity = 0.0;
  std::string unit;         ///< "m/s2" | "m"
  double dc = 0.0;
  bool satisfied = false;
  /// The check's safety index (issue 41): defined for the kinematic rows of a
  /// site with its hazard; not for dynamic rows (index.note says why).
  CheckIndex index;
  /// The candidate mechanism the row belongs to (its label; "" for one).
  std::string candidate;
  /// True when the check cannot give a verdict (e.g. a dynamic check with
  /// fewer than 3 records, NTC 2018 §7.3.5): `satisfied` is then false and
  /// `note` says why. A report shows "no verdict", never "satisfied".
  bool no_verdict = false;
  /// Its verdict in three states (outcome.hpp).
  Outcome outcome() const { return outcome_of(satisfied, no_verdict); }
  NoteText note;                ///< remarks for the reader, as data ("overturned in 1 of 2 analyses" ...)
  /// Dynamic and energy rows (issue 28): the analyses behind the row, how
  /// many collapsed (the threshold d0 exceeded or the wall overturned,
  /// C8.7.1.2.1.9) and how many failed (integrator limits: not a result).
  /// Convention (docs/theory/facade.md §6.4): a row with a collapse has an
  /// unbounded demand, dc = +inf ("collasso in n su N"), and a row with a
  /// failed analysis has no trustworthy demand, dc = +inf as well; the
  /// figure over the analyses that neither collapsed nor failed is
  /// `dc_survivors` (NaN when none), shown apart and never as the verdict.
  int analyses = 0, collapsed = 0, failed = 0;
  double dc_survivors = std::numeric_limits<double>::quiet_NaN();
  /// Every input of the demand, so that it can be redone by hand (issue 24):
  /// name with its unit ("T1 (s)", "psi(Z) (-)", "gamma (-)", "N (storeys)",
  /// "Se(T1) (m/s2)", "a_Z (m/s2)", "q (-)", "xi (%)", "eta (-)", "T (s)", ...) and value.
  std::vector<std::pair<std::string, double>> inputs;
  /// Displacement checks: the secant period T (s) of the demand and the point
  /// (d*, a*) of the capacity curve that defines it (NTC 2008: ds* = 0.4 du*,
  /// as* [C8A.4.7]; NTC 2018: d_SLV or d_SLC and a(d) [C8.7.1.10-11]), and
  /// the damping of the demand spectrum xi (%). 0 for the other kinds.
  double secant_T = 0.0, secant_d = 0.0, secant_a = 0.0, xi_pct = 0.0;
  /// Checks at height (issue 28): what gives the floor demand, "" at ground:
  /// the branch of [C7.2.6] ("rising", "plateau", "falling"), "ground" when the
  /// ground spectrum's lower bound of [C7.2.5] governs, "plateau_bound" when the
  /// lower bound S_eZ(T1) (b T1)^2/4 pi^2 of [C8.7.1.12] does.
  std::string floor_branch;
};

/// The one verdict rule of a check (issue 28: one verdict everywhere): a
/// check is satisfied if and only if it can give a verdict and its D/C is a
/// finite number not above 1. Every rule that fails a check does so through
/// its D/C (a collapse, a failed analysis: dc = +inf), so that no row can
/// show a D/C <= 1 beside "not satisfied" or a D/C > 1 beside "satisfied".
bool check_satisfied(double dc, bool no_verdict);
/// Sets r.satisfied by check_satisfied(r.dc, r.no_verdict).
void decide(CheckRow& r);

/// What the checks need besides the analysis.
struct CheckInput {
  /// Hazard (ag in g, F0, TC* in s) per limit state; SLD and SLV for NTC
  /// 2008, SLD, SLV and SLC for NTC 2018.
  std::map<LimitState, HazardParams> hazard;
  SiteConditions site;
  /// Height Z (m) of the constraint centroid above the foundation; 0 = ground level.
  /// Z may exceed the building height H (a gable above the eaves when H is
  /// taken at the eaves): psi(Z) = Z/H > 1 is then used as given, the first
  /// mode extended linearly above H (docs/theory/facade.md §Z > H).
  double Z = 0.0;
  /// The building, required when Z > 0.
  std::optional<BuildingModel> building;
  double q = 2.0;                    ///< behaviour factor (code_rules::q_local_mechanism)
  double damping_SLV_pct = 8.0;      ///< xi of the mechanism at SLV (%)
  double damping_SLC_pct = 10.0;     ///< xi of the mechanism at SLC (%)
  std::vector<CodeEdition> codes{CodeEdition::NTC2008, CodeEdition::NTC2018};
  /// Include the SLD checks (damage limitation, not required for the safety
  /// of existing buildings, NTC 2018 §8.3): case key "check_SLD", default
  /// false in case files (issue 24); true here so the library computes every check.
  bool sld = true;
  void validate() const;             ///< InputError naming the missing item
};

/// Every check of the requested editions. The analysis must have activated
/// (alpha0 > 0) and, for the displacement checks, a complete curve; otherwise
/// only the strength checks are returned.
std::vector<CheckRow> run_code_checks(const KinematicResult& r, const CheckInput& in);

/// The displacement demand (m) of the non-linear check of `code` at limit
/// state `ls` (SLV; SLC for NTC 2018) as a function of the secant period T
/// (s), with the checks' own rule at in.Z: NTC 2008 SDe(T) at 5 % [C8A.4.11]
/// or SDe(T1) psi gamma (T/T1)^2 / sqrt((1 - T/T1)^2 + 0.02 T/T1) at height
/// [C8A.4.12]; NTC 2018 SDe(T, xi) [3.2.10] or S_eZ(T, xi) T^2/4pi^2 at
/// height [C8.7.1.12], xi the mechanism damping of `ls`. The curve of the ADRS
/// plot: each check's demand is this function at its own secant period.
double displacement_demand(const CheckInput& in, CodeEdition code, LimitState ls, double T);

}  // namespace assess
