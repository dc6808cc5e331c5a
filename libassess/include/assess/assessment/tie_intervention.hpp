// tie_intervention.hpp: the tie rods of a case (issues 23, 29, 37): the stato
// di fatto (the wall with its existing ties, their checks) and the stato di
// progetto (with the new ties, given or designed, and the changes to the
// existing ties that fail) side by side, with the checks of every tie level
// (capacity design: ductile or elastic), the force each check of the
// mechanism needs, zeta_E of each state and the dynamic analyses of both, each
// tie's outcome per analysis (elastic, yielded, broken and which component).
// With "design": {"ties": ...}, the first commercial rod and anchor
// (kinematic/tie_catalogue.hpp) of the documented order, ductile ones first,
// that make every check pass, every existing tie's included, changing an
// existing tie that fails by the least change (a new anchor, a new rod, its
// removal). The same search runs over the mechanisms of a wall together
// (issue 37: a wall's ties act on every mechanism they cross).
// docs/theory/ties.md §5, §6.
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/assessment/facade_assessment.hpp"
#include "assess/kinematic/tie_checks.hpp"
#include "assess/kinematic/tie_design.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// One tie level in one dynamic analysis (per tie: N, m).
struct TieLevelRun {
  std::string name;
  double max_force = 0.0;         ///< largest force of one tie (N)
  double max_elongation = 0.0;    ///< m
  bool yielded = false;           ///< a ductile level yielded (snervata)
  double plastic_elongation = 0.0;  ///< m
  bool broken = false;            ///< the level broke (rottura)
  std::string component;          ///< how: "thread", "punching", ... (not ductile) or "elongation" (ductile)
  double t_broken = 0.0;          ///< s
};

/// One analysis of a state (issue 23, 29): the run of the façade's model with
/// the same record, polarity and restitution, with that state's tie levels.
struct TieDynamicRun {
  std::size_t run = 0;            ///< index of the analysis (restitution, record, polarity order of FacadeAssessment::runs)
  std::size_t record = 0;         ///< index in FacadeAssessment::records
  bool reversed = false;
  double e = 0.0;                 ///< restitution coefficient
  double theta_max = 0.0;         ///< rad
  double theta_collapse = 0.0;    ///< rad
  bool overturned = false;
  bool yielded = false;           ///< a ductile level yielded
  bool broken = false;            ///< a level broke
  double max_force = 0.0;         ///< per tie, the largest over the levels (N)
  double plastic_elongation = 0.0;  ///< the largest over the levels (m)
  double plastic_energy = 0.0;    ///< one tie of each level, summed (J)
  double max_elongation = 0.0;    ///< the largest over the levels (m)
  double d_star = 0.0;            ///< peak d* (m)
  bool collapse = false;          ///< overturned, a level broken, or d_control >= d_k0 of the mechanism
  bool failed = false;            ///< the integration did not complete
  std::vector<TieLevelRun> levels;
};

/// The dynamic check (Circ. 2019 C8.7.1.2.1.9) before and after, per restitution value.
struct TieDynamicSummary {
  double e = 0.0;
  int records = 0;
  std::string rule;              ///< "mean" (N >= 7), "most unfavourable" (3..6), "none"
  int overturned_before = 0, overturned_after = 0;
  double d_demand_before = 0.0, d_demand_after = 0.0;  ///< m
  double d_SLV_before = 0.0, d_SLV_after = 0.0;        ///< m
  bool collapse_before = false, collapse_after = false;
  bool satisfied_before = false, satisfied_after = false;
  int yielded_before = 0, yielded_after = 0;   ///< analyses in which a ductile level yielded (snervata)
  int broken_before = 0, broken_after = 0;     ///< analyses in which a level broke (rottura)
  double max_plastic_elongation = 0.0;  ///< after (m)
};

struct TieDynamicResult {
  bool applies = false;
  NoteText note;                 ///< why not, or what was done (as data)
  std::vector<TieDynamicRun> runs_before;  ///< the stato di fatto's analyses (with its existing ties), if tied
  std::vector<TieDynamicRun> runs;         ///< the stato di progetto's
  std::vector<TieDynamicSummary> summaries;
};

/// One tie level in one state.
struct TieLevelResult {
  Tie tie;
  TieResistance resistance;
  double count = 0.0;  ///< ties on the governing candidate's chain (-): count x length / wall length
  /// Per check of the governing candidate (every code): the force this
  /// level needs, the other levels as given.
  std::vector<RequiredTieForce> required;
  TieDemand demand;    ///< what it develops: the checks' force, at the displacement demand, in the dynamics
  std::vector<TieCheckRow> checks;
  bool satisfied = false;
  int dynamic_runs = 0, dynamic_yielded = 0, dynamic_broken = 0;  ///< its outcome over the analyses
};

/// A change the design makes to an existing tie level that fails (issue 37),
/// in the order of the least change: "anchor" (a new anchor on its rod), "rod"
/// (a new rod and anchor through the same holes), "removed".
struct TieChange {
  std::string level;    ///< the existing level's name
  std::string kind;     ///< "anchor" | "rod" | "removed"
  Tie before;           ///< the level as it is
  std::optional<Tie> after;  ///< as changed (none when removed)
};

/// One combination the design analysed (issues 29, 37), in the order tried.
struct TieTrial {
  double diameter = 0.0;       ///< rod (m; 0: no level to design)
  std::string grade;
  double thread = 0.0;         ///< nominal diameter of the ends' thread (m)
  AnchorType anchor = AnchorType::Plate;
  double plate = 0.0, plate_t = 0.0;  ///< plate side and thickness, or bar length and diameter (m)
  std::string plate_grade;
  double T_Rd = 0.0;           ///< per tie, the weakest design level (N)
  std::string governing;       ///< its weakest component
  bool ductile = false;
  std::string changes;         ///< the changes to existing ties tried with it ("" none)
  /// "mechanism" (a check of a mechanism), "tie" (a check of a tie),
  /// "existing" (a check of an existing tie, the rest satisfied), "broken" (a
  /// tie broke in a dynamic analysis: `component`), "dynamic" (the dynamic
  /// check), "accepted".
  std::string outcome;
  std::string component;
  std::string mechanism;       ///< in a wall: the mechanism that failed first ("" for a single case)
};

struct TieInterventionResult {
  bool designed = false;      ///< from "design" (else the case's "ties" are assessed)
  bool intervention = false;  ///< new ties (given or designed) exist: a stato di progetto
  bool found = false;         ///< design: a rod and plate of the lists satisfy every check
  std::string message;        ///< why no design was found
  int tried = 0;              ///< design: combinations analysed
  std::vector<TieTrial> trials;  ///< design: each combination and why it was rejected or accepted
  /// Issue 37: the changes made to existing ties that fail (design only).
  std::vector<TieChange> changes;
  /// Issue 37: the existing ties that fail in the stato di progetto without a
  /// design to change them (names), or with a design that found none.
  std::vector<std::string> failing_existing;
  /// Issue 37: the mechanisms designed together (a wall's: their ids or
  /// names, as the caller gave them; empty for a single case).
  std::vector<std::string> wall_members;
  /// The stato di fatto (the case as read: its existing ties) and the stato
  /// di progetto (with the new ties; the same case without an intervention).
  CaseFile case_before, case_after;
  KinematicCaseResult before, after;
  std::vector<TieLevelResult> levels_before;  ///< the existing ties, in the stato di fatto
  std::vector<TieLevelResult> levels;         ///< every tie of the stato di progetto (existing first)
  /// zeta_E = PGA capacity / PGA demand (NTC 2018 rows of the adopted
  /// procedure, SLV and SLC, every candidate; the smallest) (-); NaN without NTC 2018.
  double zetaE_before = 0.0, zetaE_after = 0.0;
  /// Every kinematic check satisfied and every check of the state's ties.
  bool passes_before = false, passes_after = false;
  /// The dynamic analyses of both states (filled by run_tie_dynamics when
  /// the case has a "dynamic" section; applies = false otherwise).
  TieDynamicResult dynamics;
  /// Design: "ductile" (every level ductile) or "elastic" (a level is not
  /// ductile: it stays elastic in every analysis); "" otherwise.
  std::string regime;
};

/// Every kinematic check of every candidate satisfied (with a verdict): the
/// reading of passes_before / passes_after.
bool every_kinematic_check_satisfied(const KinematicCaseResult& r);

/// True when the case has ties (existing or new) or a design of ties.
bool has_ties(const CaseFile& c);

/// The two states of the case (has_ties(c) must hold) from the kinematic
/// analyses alone. Needs a site for the checks; throws InputError otherwise.
TieInterventionResult run_tie_intervention(const CaseFile& c);

/// The same with the dynamic analyses of `a` (its case is `c`): the design
/// accepts a tie only if no level breaks in any analysis and the dynamic
/// check is satisfied; the elastic ties' checks take the largest dynamic force.
TieInterventionResult run_tie_intervention(const CaseFile& c, const FacadeAssessment& a);

/// The dynamic analyses of both states of `t` (docs/theory/ties.md §6): the
/// façade's analyses are the stato di fatto (its existing ties hold it); the
/// stato di progetto is the same model, records, polarities and candidate with
/// every tie of the intervention. applies = false, with `note`, when the
/// façade has no dynamic analysis or the tied model cannot represent it.
TieDynamicResult run_tie_dynamics(const FacadeAssessment& a, const TieInterventionResult& t);

/// The tie step of an assessment, as `assess run` and the building case do it:
/// nothing when the case has no ties (has_ties false); otherwise
/// run_tie_intervention(a.kase, a).
std::optional<TieInterventionResult> assess_ties(const FacadeAssessment& a);

/// Issue 37: the ties of a wall, which act on every mechanism of the wall
/// whose moving blocks they cross: one design for all of them (levels and
/// existing ties matched by name across the mechanisms), accepted when every
/// mechanism passes. `members` are the assessments of the wall's mechanisms
/// with ties (their cases hold the wall's levels that cross them), `names`
/// their labels; one result per member, in order.
std::vector<TieInterventionResult> assess_wall_ties(const std::vector<const FacadeAssessment*>& members,
                                                    const std::vector<std::string>& names);

/// zeta_E of a kinematic result for the adopted `method` (see above).
double zeta_E(const KinematicCaseResult& r, const std::string& method);

/// Issue 37: the text of a change ("new plate 300 x 300 x 20 mm S275", ...).
std::string describe_change(const TieChange& c);

}  // namespace assess
