// tie_report.hpp: text and JSON of the tie rods of a case (issues 23, 29):
// the stato di fatto and the stato di progetto, each level's rod, ends,
// anchor and layout, its strengths and ductility, the force each check of
// the mechanism needs, the checks of the tie, the mechanism in both states
// with zeta_E, the dynamic analyses of both states with each tie's outcome
// per analysis, the detailing; and the readings adopted (the certainty of
// each formula and constant, for the appendix). The relazione's section is in
// relazione_ties.cpp; its sentences are in the message catalogue (messages/ties.json).
#pragma once

#include "assess/assessment/tie_intervention.hpp"
#include "assess/report/messages.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace assess {

/// Terminal text (English with the Italian terms of the relazione).
std::string tie_text(const TieInterventionResult& t);
/// JSON: "designed", "intervention", "found", "regime", "levels_before",
/// "levels" (rod with its ends, anchor, layout, strengths in kN, ductility,
/// required forces in kN and kN/m, demands, checks), "before"/"after" (alpha0,
/// a0*, d0*, d_SLV ..., the plastic reserve apart, zeta_E, every check's D/C,
/// the capacity curve with each level's force and elongation), "dynamic"
/// (summaries, the runs of both states with each level's outcome), "readings";
/// SI except forces in kN and lengths of the rod and anchor in mm (named in
/// the keys). Never a non-finite number: null, with a reason where it matters.
nlohmann::json tie_json(const TieInterventionResult& t);

/// The tie levels of one state (`after`: the stato di progetto) grouped for a
/// one-line summary: the existing ties, then the new ones, each group by its
/// first level (a design gives every level the same rod and plate) and its
/// number of levels; a group without levels is left out.
struct TieGroup {
  bool existing = false;
  const Tie* first = nullptr;
  int levels = 0;
};
std::vector<TieGroup> tie_groups(const TieInterventionResult& t, bool after);

/// A reading adopted by the tie section (issue 29): the quantity, the value
/// or formula adopted, and its basis with its certainty ([V-T], [V-S], [R],
/// [I] as in docs/theory/ties.md). The signed body of the relazione carries
/// no tags; these are for an appendix "Ipotesi e letture adottate".
struct TieReading {
  std::string quantity, reading, basis;
};
std::vector<TieReading> tie_readings(const TieInterventionResult& t, Lang lang);

/// The title of the relazione's section on the ties; the section itself is
/// built as document blocks by the report layer (relazione_ties.cpp): the two
/// states, the ties drawn on the mechanism (labelled in kN per tie and per
/// level), each level's rod, ends, anchor and layout, the formulas with their
/// sources, the checks, the force each check needs, the two states side by
/// side, the dynamic analyses (per analysis: elastic, yielded, broken and
/// which component) and the detailing. No certainty tag: tie_readings().
std::string tie_section_title(Lang lang);

}  // namespace assess
