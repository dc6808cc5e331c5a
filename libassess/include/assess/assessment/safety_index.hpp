// safety_index.hpp: the safety index of a mechanism per code edition and
// approach (issue 41; docs/theory/building.md §4): the lowest index of its
// checks (kinematic/check_index.hpp) over every candidate, limit state and
// location of the approach, beside the approach's verdict. No physics here:
// each check carries its own index, computed once by run_kinematic_case; this
// is their summary, below 1 exactly where the approach's verdict fails.
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/assessment/verdict.hpp"

#include <limits>
#include <string>
#include <vector>

namespace assess {

/// The safety index of one mechanism for one (code, approach). PGA means ag on
/// rock (g), the quantity of the hazard grid.
struct SafetyIndex {
  std::string code;      ///< "NTC2018" | "NTC2008"
  std::string approach;  ///< "strength" | "displacement" | "dynamic"
  bool has_checks = false;  ///< the approach has checks for this mechanism
  /// The approach's verdict (verdict.hpp MethodVerdict): its largest D/C, counts and three states.
  double dc = std::numeric_limits<double>::quiet_NaN();
  bool satisfied = false;
  bool undecided = false;  ///< no check fails, some give no verdict: no verdict
  int checks = 0, failing = 0, no_verdict = 0;
  Outcome outcome() const { return summary_outcome(checks, failing, no_verdict); }
  /// zetaE defined: the approach has a check with an index (strength and
  /// displacement; the dynamic approach has none: `note` says why).
  bool defined = false;
  NoteText note;
  std::string limit_state, location, candidate;  ///< the check whose index is the lowest
  /// That check's index (check_index.hpp): zeta, PGA_C, PGA_D, TR_C, TR_D,
  /// their ratio, whether extrapolated, bounded, non-monotonic.
  CheckIndex index;
  /// The candidate whose D/C is the approach's (its governing row, issue 28):
  /// its label, alpha0 (-) and a0* (m/s^2), printed beside that D/C.
  std::string dc_candidate;
  double dc_alpha0 = std::numeric_limits<double>::quiet_NaN();
  double dc_a0_star = std::numeric_limits<double>::quiet_NaN();
};

/// The check with the lowest index of (code, kind) over every candidate of
/// `k` (nullptr when none has one): the approach's index.
const CheckRow* lowest_index_check(const KinematicCaseResult& k, const std::string& code, const std::string& kind);

/// The safety indices of a mechanism: per code present in `v` (NTC 2018
/// first), strength, displacement and dynamic, from its checks' own indices
/// and its verdict `v` (every candidate's kinematic rows and the dynamic rows).
std::vector<SafetyIndex> safety_indices(const KinematicCaseResult& k, const Verdict& v);

}  // namespace assess
