// tied_rocking.hpp: one-sided rocking of a wall held back by a tie rod
// (issue 23): the rocking model's equation of motion (rigid Housner block or
// smooth block on a Winkler bed, dynamics/rocking_model.hpp) plus the tie as a
// one-sided (tension-only), elastic-perfectly-plastic restraint at its point,
// with its plastic elongation as a state:
//
//   I0 theta'' = I0 f_model(theta, theta', ug) + Q_tie,  Q_tie = T d . dp/dtheta
//   e(theta) = -d . (p(theta) - p0)           elongation of the rod (m)
//   T = min(max(P0 + k (e - e_p), 0), T_y)    force per unit depth of wall (N/m)
//   e_p' = e' while yielding (T = T_y and e' > 0), else 0
//
// p(theta) is the anchor point rotated by theta about the outer toe; d the
// unit direction of the pull on the wall. Modes: rest, rocking with the rod
// elastic (or slack), rocking with the rod yielding; events: lift-off,
// impact at theta = 0 (theta' <- e theta'), yield, unloading, collapse.
// The integrator is dynamics/hybrid_ode (GSL stays there).
// docs/theory/ties.md §6.
#pragma once

#include "assess/dynamics/chain_dynamics.hpp"
#include "assess/dynamics/hybrid_ode.hpp"
#include "assess/dynamics/rocking_model.hpp"
#include "assess/kinematic/tie.hpp"

#include <Eigen/Core>

#include <vector>

namespace assess {

/// A tie on a rocking body, per unit depth of wall. Coordinates relative to
/// the outer toe: x outward (the body lies at x < 0), z up (m).
struct RockingTie {
  Eigen::Vector2d point{0.0, 0.0};       ///< anchor (m)
  Eigen::Vector2d direction{-1.0, 0.0};  ///< pull on the wall (unit)
  double stiffness = 0.0;   ///< k (N/m per m of wall), > 0
  double capacity = 0.0;    ///< T_y (N/m), > 0
  double pretension = 0.0;  ///< P0 (N/m), 0 <= P0 <= T_y
  /// Position of the anchor after a rotation theta about the toe (m).
  Eigen::Vector2d position(double theta) const;
  /// Elongation e(theta) (m) and de/dtheta (m/rad).
  double elongation(double theta) const;
  double delongation(double theta) const;
  /// Generalised force of a tie force T (N/m) on theta (N m/m): T d . dp/dtheta
  /// (negative: it restrains the outward rotation).
  double generalised_force(double theta, double T) const;
  void validate() const;  ///< InputError naming the field
};

/// One tie level's outcome.
struct TiedLevelResult {
  double max_force = 0.0;           ///< largest force (N/m for a body, N for a chain)
  double max_elongation = 0.0;      ///< largest elongation e (m)
  bool yielded = false;
  double plastic_elongation = 0.0;  ///< e_p at the end (m)
  double plastic_energy = 0.0;      ///< T_y e_p (J/m for a body, J for a chain)
};

/// Outcome of one tied analysis. The scalars about the tie are those of the
/// first level; `levels` holds every level's.
struct TiedRockingResult {
  HybridTermination termination = HybridTermination::completed;
  double theta_max = 0.0;         ///< largest rotation (rad)
  double theta_collapse = 0.0;    ///< rotation at which the net restoring moment with the tie yielded vanishes (rad)
  bool overturned = false;        ///< theta reached theta_collapse
  double t_end = 0.0;             ///< s
  long impacts = 0;
  double max_force = 0.0;         ///< largest tie force (N/m)
  double max_elongation = 0.0;    ///< largest elongation e (m)
  bool yielded = false;
  double plastic_elongation = 0.0;  ///< e_p at the end (m): the permanent set of the rod
  double plastic_energy = 0.0;      ///< T_y e_p (J/m): energy dissipated by the rod
  std::vector<TiedLevelResult> levels;
  /// Samples at the record's steps (when asked): t (s), theta (rad), T of the first level (N/m).
  std::vector<double> t, theta, force;
};

/// Integrates the tied one-sided rocking under the ground acceleration ug
/// (m/s^2, positive outward, samples every dt s, linear in between) from rest
/// to t_end (s). The model must be one-sided. @throws InputError for a
/// two-sided model or a bad tie.
TiedRockingResult analyse_tied_rocking(const RockingModel& model, const RockingTie& tie, const std::vector<double>& ug,
                                       double dt, double t_end, bool history = false,
                                       const HybridOdeOptions& options = {});
/// Several tie levels (each with its own plastic elongation and yield state;
/// modes: rest, or rocking with the set of yielding levels).
TiedRockingResult analyse_tied_rocking(const RockingModel& model, const std::vector<RockingTie>& ties,
                                       const std::vector<double>& ug, double dt, double t_end, bool history = false,
                                       const HybridOdeOptions& options = {});

/// The same for a one-sided chain (dynamics/chain_dynamics.hpp) held by the
/// tie level `tie` (chain coordinates, the whole level on the chain: N, N/m):
///   M(q) q'' = [the chain's equation] + T d . dp/dq,
/// with the anchor's e(q) and dp/dq from the chain's exact configuration
/// tabulated at 2000 nodes over the chain's grid (cubic Hermite for e, linear
/// for de/dq); `e` is the coefficient of restitution at q = 0 (in [-1, 0]).
/// Forces and energies of the result are those of the level (N, J).
TiedRockingResult analyse_tied_chain(const ChainDynamics& chain, const TieRestraint& tie, double e,
                                     const std::vector<double>& ug, double dt, double t_end, bool history = false,
                                     const HybridOdeOptions& options = {});
TiedRockingResult analyse_tied_chain(const ChainDynamics& chain, const std::vector<TieRestraint>& ties, double e,
                                     const std::vector<double>& ug, double dt, double t_end, bool history = false,
                                     const HybridOdeOptions& options = {});

}  // namespace assess
