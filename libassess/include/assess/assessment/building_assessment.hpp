// building_assessment.hpp: the assessment of a building (issue 22): every
// mechanism of the building case run through assess_facade (the code path of
// a single run), in parallel across mechanisms, then per mechanism and
// approach the PGA capacity, its return period and the safety index
// zetaE = PGA_C / PGA_D (and TR_C / TR_D) of both code editions, the governing
// mechanism of the building per approach and the mechanisms that pass and
// fail (docs/theory/building.md).
#pragma once

#include "assess/assessment/building_case.hpp"
#include "assess/assessment/facade_assessment.hpp"
#include "assess/assessment/tie_intervention.hpp"

#include <limits>
#include <optional>
#include <string>
#include <vector>

namespace assess {

struct BuildingMechanismResult {
  /// The mechanism's assessment as assess_ties left it (given ties decide its
  /// dynamic rows; a design leaves it as is), the code path of `assess run`.
  FacadeAssessment a;
  /// Issue 23: the tie rods of the mechanism ("ties" or "design" in its wall or
  /// entry): assess_ties of its assessment; empty when it has none.
  std::optional<TieInterventionResult> ties;
  /// The mechanism's zetaE of its adopted method's approach (NTC 2018; zeta_E of
  /// tie_intervention.hpp: strength rows for "linear", displacement rows
  /// otherwise) before and after its ties (docs/theory/building.md §8); equal
  /// without ties; NaN without NTC 2018 rows.
  double zeta_before = std::numeric_limits<double>::quiet_NaN();
  double zeta_after = std::numeric_limits<double>::quiet_NaN();
  /// Every kinematic check of every candidate satisfied (both editions), before
  /// and after its ties (after: every check of the ties too; TieInterventionResult).
  bool passes_before = false, passes_after = false;
  /// The index of (code, approach) of its assessment (a.indices), or nullptr.
  const SafetyIndex* index(const std::string& code, const std::string& approach) const;
};

/// The governing mechanism of the building for one (code, approach): the lowest
/// zetaE (strength, displacement), the largest D/C (dynamic: no zetaE).
struct BuildingGoverning {
  std::string code, approach;
  int mechanism = -1;  ///< index in BuildingCase::mechanisms; -1 if no mechanism has the approach
  double zeta = std::numeric_limits<double>::quiet_NaN();
  double dc = std::numeric_limits<double>::quiet_NaN();
  int satisfied = 0, failing = 0, no_verdict = 0;  ///< mechanisms passing, failing, without a verdict
  int assessed = 0;                                ///< mechanisms with checks of the approach
};

/// The building's safety index before and after the tie rods of its mechanisms
/// (docs/theory/building.md §8): the smallest mechanism zetaE (the weakest local
/// mechanism governs the building, Circ. 2019 C8.7.1), NaN when no mechanism has one.
struct BuildingTieIndex {
  bool any_ties = false;  ///< some mechanism has "ties" or "design"
  double zeta_before = std::numeric_limits<double>::quiet_NaN();
  double zeta_after = std::numeric_limits<double>::quiet_NaN();
  int mechanism_before = -1, mechanism_after = -1;  ///< index in BuildingCase::mechanisms (the smallest; ties: the first)
  int passing_before = 0, passing_after = 0;        ///< mechanisms with passes_before / passes_after
};

/// The building's verdict (issue 28: one verdict, computed once, read by
/// every writer): each mechanism by its adopted method under NTC 2018 (its
/// Verdict::conclusion()); the building satisfies the check when every
/// mechanism does. Its index zetaE,edificio is the smallest zetaE of the
/// mechanisms' adopted approaches (the weakest local mechanism governs,
/// Circ. 2019 C8.7.1; docs/theory/building.md §8); mechanisms adopting the
/// dynamic method have none (NaN when no mechanism has one).
struct BuildingVerdict {
  bool satisfied = false;
  int mechanisms = 0;               ///< mechanisms of the building
  std::vector<int> failing;         ///< indices of the mechanisms that do not satisfy it
  std::vector<int> undecided;       ///< indices of those without a verdict (or without a check by their method)
  double zeta = std::numeric_limits<double>::quiet_NaN();
  int zeta_mechanism = -1;          ///< index of the mechanism that gives zeta
  double max_dc = 0.0;              ///< the largest adopted D/C over the mechanisms (+inf: a collapse)
  int dc_mechanism = -1;
  /// Not satisfied if a mechanism fails, else no verdict if one has none (`undecided` says which), else satisfied.
  Outcome outcome() const { return summary_outcome(mechanisms, int(failing.size()), int(undecided.size())); }
};

struct BuildingAssessment {
  BuildingCase building;  ///< as run (a shared selection that fell back is marked)
  std::vector<BuildingMechanismResult> results;  ///< one per mechanism, in the file's order
  std::vector<BuildingGoverning> governing;      ///< per code, then approach
  std::vector<std::string> codes;                ///< the codes present, NTC2018 first
  BuildingTieIndex tie_index;                    ///< before/after the tie rods (issue 23)
  BuildingVerdict verdict;                       ///< the building's verdict (issue 28)
  std::string site_description;
  double VR = 0.0;
  double TR_SLV = 0.0;  ///< years
  double ag_SLV_g = 0.0;
  /// Warnings of the building (paths in the building file), mechanism by mechanism.
  std::vector<std::string> warnings;
  const BuildingGoverning* governing_of(const std::string& code, const std::string& approach) const;
};

/// Runs every mechanism (assess_facade on its expanded case, then assess_ties,
/// in parallel across mechanisms, results in the file's order). Errors name the
/// building file and the path in it. @throws InputError
BuildingAssessment assess_building(BuildingCase building, const FacadeOptions& options = {});

/// The governing mechanism of the building for `approach` ("strength" or
/// "displacement") by the kinematic checks alone (no dynamic analysis): the
/// lowest NTC 2018 zetaE (else NTC 2008); ties: the first. The index in
/// b.mechanisms. Used by `assess fragility BUILDING.json` without --mechanism.
std::size_t governing_mechanism_kinematic(const BuildingCase& b, const std::string& approach);

/// The building's verdict from its mechanisms' (assess_building stores it in BuildingAssessment::verdict).
BuildingVerdict building_verdict(const BuildingAssessment& b);

}  // namespace assess
