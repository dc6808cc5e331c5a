// note.cpp: the ids of the notes the library writes, with their number of
// arguments (the catalogue test: report/messages.cpp has each in both languages).
#include "assess/support/note.hpp"

namespace assess {

const std::vector<std::pair<std::string, std::size_t>>& note_ids() {
  static const std::vector<std::pair<std::string, std::size_t>> ids{
      // Why the selection's period range is what it is (facade_assessment.cpp range_note).
      {"range.union", 6},
      {"range.given", 2},
      {"range.default", 6},
      {"range.raised", 1},
      {"range.cut", 1},
      {"range.beyond_one", 3},
      {"range.beyond_two", 5},
      // How the candidates analysed dynamically share their selection (shared_range).
      {"shared.one_selection", 4},
      {"shared.each_own", 4},
      // One step of the selection's site-class ladder (selected_records).
      {"step.any_class", 0},
      {"step.classes", 1},
      {"step.outcome", 2},
      {"step.no_selection", 1},
      // The caveats of a record used (flag_records, record-selection.md §2.8).
      {"flag.not_in_library", 0},
      {"flag.near_fault", 1},
      {"flag.class_not_site", 2},
      {"flag.class_not_asked", 2},
      {"flag.class_vs30", 3},
      {"flag.misfit", 3},
      {"flag.scale_raised", 3},
      {"flag.scale_listed", 2},
      // Why a check has no safety index, or only a bound (kinematic/check_index.cpp,
      // assessment/safety_index.cpp).
      {"index.no_dynamic", 0},
      {"index.no_finite_dc", 0},
      {"index.hazard_outside", 0},
      {"index.bound_below", 0},
      {"index.bound_above", 0},
      {"index.no_check", 0},
      // A dynamic check's row (assessment/facade_assessment.cpp dynamic_row, energy_row):
      // its collapses, the records' rule (NTC 2018 §7.3.5), compatibility, failed analyses.
      {"check.d0_exceeded", 3},
      {"check.d0_exceeded_tied", 4},
      {"check.d0_never", 0},
      {"check.records_one", 0},
      {"check.records", 1},
      {"check.rule_mean", 0},
      {"check.rule_worst", 0},
      {"check.rule_few_collapse", 0},
      {"check.rule_few", 0},
      {"check.not_compatible", 0},
      {"check.failed", 2},
      {"check.overturned", 2},
      // The dynamic model of a mechanism, or why there is none (assessment/mechanism_dynamics.cpp).
      {"dyn.body", 0},
      {"dyn.thrust_one", 1},
      {"dyn.thrust_two", 1},
      {"dyn.chain_one", 3},
      {"dyn.chain_two", 3},
      {"dyn.body_held_one", 0},
      {"dyn.body_held", 1},
      {"dyn.chain_held_one", 0},
      {"dyn.chain_held", 1},
      {"dyn.floor_given", 1},
      {"dyn.floor_filter", 4},
      {"dyn.na_tied_two_sided", 0},
      {"dyn.na_plan", 0},
      {"dyn.na_friction", 0},
      {"dyn.na_chain", 1},
      // The tie intervention's dynamic analysis (assessment/tie_intervention.cpp run_tie_dynamics).
      {"tie.dyn_none", 0},
      {"tie.dyn_no_block", 0},
      {"tie.dyn_repeated", 0},
      {"tie.dyn_existing", 0},
      // Why a building's shared record selection fell back (facade_assessment.cpp
      // shared_selection_problem, building_case.cpp).
      {"sel.no_compatible", 1},
      {"sel.band_left", 0},
      {"sel.fell_back", 2},
      // The records' mean spectrum against the SLV spectrum (facade_assessment.cpp, NTC 2018 §3.2.3.6).
      {"compat.within", 7},
      {"compat.outside", 7},
  };
  return ids;
}

}  // namespace assess
