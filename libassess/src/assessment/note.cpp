// note.cpp: the ids of the notes the assessment writes, with their number of
// arguments (the catalogue test: report/messages.cpp has each in both languages).
#include "assess/assessment/note.hpp"

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
  };
  return ids;
}

}  // namespace assess
