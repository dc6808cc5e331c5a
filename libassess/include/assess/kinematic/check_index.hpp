// check_index.hpp: the safety index of one code check (issue 41;
// docs/theory/building.md §4): the return period TR_C at which that same
// check, the function that gives its D/C, reaches D/C = 1 with the site's
// whole hazard at TR_C (ag, F0 and TC* of Allegato A at TR_C, S at that ag),
// PGA_C = ag(TR_C) and PGA_D = ag(TR_D) on rock, zetaE = PGA_C / PGA_D and
// TR_C / TR_D. By construction zetaE < 1 exactly where D/C > 1.
#pragma once

#include "assess/hazard/hazard.hpp"
#include "assess/support/note.hpp"

#include <functional>
#include <limits>
#include <string>

namespace assess {

struct KinematicResult;
struct CheckInput;
struct CheckRow;

/// The safety index of one check.
struct CheckIndex {
  /// An index exists (a kinematic check with a finite D/C); otherwise `note` says why.
  bool defined = false;
  NoteText note;
  double TR_demand = std::numeric_limits<double>::quiet_NaN();    ///< TR_D: the limit state's TR as the check used it (years)
  double TR_capacity = std::numeric_limits<double>::quiet_NaN();  ///< TR_C (years); NaN without a return-period axis
  double ag_demand_g = std::numeric_limits<double>::quiet_NaN();  ///< PGA_D = ag(TR_D) on rock (g)
  double ag_capacity_g = std::numeric_limits<double>::quiet_NaN();  ///< PGA_C = ag(TR_C) on rock (g)
  double zeta = std::numeric_limits<double>::quiet_NaN();         ///< zetaE = PGA_C / PGA_D (-)
  double TR_ratio = std::numeric_limits<double>::quiet_NaN();     ///< TR_C / TR_D (-)
  /// TR_C outside the hazard data's 30-2475 years: ag extrapolated by the end
  /// segment's power law, F0 and TC* held at the end values (Site::hazard_extrapolated).
  bool extrapolated = false;
  /// The crossing lies beyond the searched range [check_index_tr_min,
  /// check_index_tr_max] (or, without a TR axis, the ag range): TR_C and
  /// PGA_C are then that bound ("< 1 year", "> 1e6 years"), a bound on the index.
  int bound = 0;  ///< -1 below the range, +1 above it, 0 a crossing found
  /// D/C is not monotonic in TR: it also reaches 1 on the other side of TR_D
  /// (a satisfied check that fails at a lower return period, or a failing
  /// check that is satisfied again between TR_C and TR_D). The index keeps the
  /// crossing on the side that agrees with the check at TR_D; `other_crossing_TR`
  /// (years) is the lowest crossing on the other side.
  bool non_monotonic = false;
  double other_crossing_TR = std::numeric_limits<double>::quiet_NaN();
  /// The site's hazard is given per limit state (no return-period axis): ag is
  /// varied alone with F0 and TC* of the limit state (the only spectral shape
  /// given) and TR_C is not defined.
  bool shape_held = false;
};

/// Why a dynamic check has no index (the same words in every output).
inline Note no_dynamic_index() { return {"index.no_dynamic", {}}; }

/// The searched range of return periods (years), beyond the data by the
/// extrapolation of Site::hazard_extrapolated; a crossing beyond it is a bound.
inline constexpr double check_index_tr_min = 1.0;
inline constexpr double check_index_tr_max = 1.0e6;
/// Without a return-period axis (hazard given per limit state): the ag range (g).
inline constexpr double check_index_ag_min_g = 1.0e-4;
inline constexpr double check_index_ag_max_g = 20.0;

/// The site's hazard along the return-period axis (years -> ag, F0, TC*): the
/// site's Site::hazard_extrapolated; empty when the hazard is given per limit state.
using HazardAxis = std::function<HazardParams(double tr_years)>;

/// The index of `row`, a check of `in.codes` computed by run_code_checks(r, in)
/// with in.Z of its candidate: the same function is re-run with the hazard of
/// the row's limit state replaced by axis(TR) (or, without an axis, its ag
/// varied alone), every other input unchanged. Dynamic and energy rows and a
/// row without a finite D/C have none (`note` says why).
CheckIndex check_index(const KinematicResult& r, const CheckInput& in, const CheckRow& row, const HazardAxis& axis);

}  // namespace assess
