// tie_intervention.hpp: the tie rods of a case (issue 23): the mechanism
// before and after the ties, side by side, with the checks of every tie
// level, the force each check of the mechanism needs, and zeta_E before and
// after; with "design": {"ties": ...}, the smallest commercial rod and plate
// (kinematic/tie_catalogue.hpp) that make every check pass.
// docs/theory/ties.md §5.
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/kinematic/tie_checks.hpp"
#include "assess/kinematic/tie_design.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// One tie level after the intervention.
struct TieLevelResult {
  Tie tie;
  TieResistance resistance;
  double count = 0.0;  ///< ties on the governing candidate's chain (-)
  /// Per check of the governing candidate (NTC 2018, else the first code):
  /// the force this level needs, the other levels as given.
  std::vector<RequiredTieForce> required;
  double N_Ed = 0.0;   ///< demand on one tie: the largest required force per tie (N)
  std::optional<double> elongation_demand;  ///< rod elongation at the largest displacement demand (m)
  std::vector<TieCheckRow> checks;
  bool satisfied = false;
};

struct TieInterventionResult {
  bool designed = false;      ///< from "design" (else the case's "ties" are assessed)
  bool found = false;         ///< design: a rod and plate of the lists satisfy every check
  std::string message;        ///< why no design was found
  int tried = 0;              ///< design: combinations analysed
  CaseFile case_before, case_after;  ///< the case without / with the ties (after: the designed ones)
  KinematicCaseResult before, after;
  std::vector<TieLevelResult> levels;
  /// zeta_E = PGA capacity / PGA demand (NTC 2018 rows of the adopted
  /// procedure, SLV and SLC, every candidate; the smallest) (-); NaN without NTC 2018.
  double zetaE_before = 0.0, zetaE_after = 0.0;
  bool passes_before = false, passes_after = false;  ///< every kinematic check satisfied
};

/// True when the case has ties or a design of ties.
bool has_ties(const CaseFile& c);

/// The intervention of the case (has_ties(c) must hold). Needs a site for
/// the checks; throws InputError otherwise.
TieInterventionResult run_tie_intervention(const CaseFile& c);

/// zeta_E of a kinematic result for the adopted `method` (see above).
double zeta_E(const KinematicCaseResult& r, const std::string& method);

}  // namespace assess
