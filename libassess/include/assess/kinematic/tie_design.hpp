// tie_design.hpp: the force a tie level must carry for each check of the
// mechanism to be satisfied (issue 23; docs/theory/ties.md §4), and the rod's
// elongation at a displacement demand.
#pragma once

#include "assess/kinematic/code_checks.hpp"
#include "assess/kinematic/kinematic_analysis.hpp"
#include "assess/kinematic/tie.hpp"

#include <string>
#include <vector>

namespace assess {

/// The force one tie level needs for one check of the mechanism to be
/// satisfied (D/C = 1), the other levels as given.
struct RequiredTieForce {
  std::string code, limit_state, kind, location;  ///< the check (CheckRow's fields)
  double level_force = 0.0;  ///< force of the whole level on the chain (N)
  double per_tie = 0.0;      ///< force of one tie (N): level_force / count
  double per_metre = 0.0;    ///< per metre of wall (N/m): per_tie / spacing
  bool reachable = true;     ///< false: no force up to 100 x the mechanism's weight satisfies it
                             ///< (the forces are then 0, never printed: "non raggiungibile")
  std::string reason;        ///< why it is not reachable
  double dc_without = 0.0;   ///< D/C of the check with this level at zero force (-)
};

/// For each check of `checks_input` (every row that run_code_checks gives for
/// the mechanism), the design strength of level `level` of `ties` at which
/// the check's D/C is 1: 0 if the check passes without the level. The level
/// keeps its stiffness and pretension; the strength is found by bracketing and
/// bisection to a relative 1e-7 (the linear checks are linear in it: their
/// closed form is in the tests). `spacing` (m) turns one tie into per metre.
std::vector<RequiredTieForce> required_tie_forces(const Chain& chain, const KinematicOptions& options,
                                                  const CheckInput& checks_input,
                                                  const std::vector<TieRestraint>& ties, std::size_t level,
                                                  double spacing);

/// Elongation (m) of each tie level when the equivalent displacement is d*
/// (m): the configuration of the chain at d_k = d* / (d*/d_k), found by
/// continuation from the undeformed one.
std::vector<double> tie_elongations_at(const Chain& chain, const KinematicResult& r,
                                       const std::vector<TieRestraint>& ties, double d_star);

}  // namespace assess

namespace assess {

/// What the design of ties searches (case file "design": {"ties": ...}):
/// tie levels given without rod and anchor (point, direction, free length,
/// masonry, layout, pretension), the steel grades allowed for the rods and
/// for the anchors, the anchors (plates, bars), how the rods' ends take the
/// nut, the smallest rod, and the lists of kinematic/tie_catalogue.hpp. Every
/// level gets the same rod and anchor [I]. Issue 37: the order of the search
/// and its rules are in docs/theory/ties.md §5.
struct TieDesignSpec {
  std::vector<Tie> levels;                  ///< rod and anchor are filled by the design (may be empty)
  std::vector<bool> pretension_given;       ///< per level: "pretension_kN" given (else E A alpha_T dT)
  std::vector<std::string> grades{"S275"};  ///< rod grades tried, in order
  /// Anchor grades tried, in order, for each anchor (issue 37: an input; default S275).
  std::vector<std::string> plate_grades{"S275"};
  /// Anchor types tried, in order: plates ("plate"), then bars ("bar", the
  /// paletto) when listed (issue 37; default plates only).
  std::vector<AnchorType> anchors{AnchorType::Plate};
  /// Threaded: each rod threaded at its ends (M d); Upset or Welded: the ends
  /// of the smallest ISO thread that satisfies the capacity design (a ductile
  /// rod), at most tie_catalogue::max_upset_ratio times the rod (issue 29).
  TieEnds ends = TieEnds::Threaded;
  double min_rod_diameter = 0.016;          ///< m (tie_catalogue::min_rod_diameter; "min_rod_diameter_mm")
};

}  // namespace assess
