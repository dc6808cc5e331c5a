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
// Issue 29: a level that is not ductile breaks when T reaches T_y (its
// weakest component fails: the force is lost from then on and the wall,
// held by the levels left, goes on or collapses where their envelope
// vanishes); a ductile level yields, and breaks when its elongation reaches
// its ultimate (the rod's eps_ud L).
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
#include "assess/dynamics/rocking_analysis.hpp"
#include "assess/dynamics/rocking_model.hpp"
#include "assess/kinematic/tie.hpp"

#include <Eigen/Core>

#include <limits>
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
  /// Issue 29: a ductile tie yields at T_y and breaks at `ultimate_elongation`
  /// (m; infinity: never); a tie that is not ductile breaks when its force
  /// reaches T_y (its force is lost from then on, the wall goes on bare).
  bool ductile = true;
  double ultimate_elongation = std::numeric_limits<double>::infinity();
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

/// Outcome of one tied analysis integrated to a fixed end time (the
/// verification form of the tests). The scalars about the tie are those of
/// the first level; `levels` holds every level's.
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
};

/// Integrates the tied one-sided rocking under the ground acceleration ug
/// (m/s^2, positive outward, samples every dt s, linear in between) from rest
/// to t_end (s), without the early end of analysis_end.hpp (every impact up
/// to t_end is counted). The model must be one-sided. @throws InputError for
/// a two-sided model or a bad tie.
TiedRockingResult analyse_tied_rocking(const RockingModel& model, const RockingTie& tie, const std::vector<double>& ug,
                                       double dt, double t_end, const HybridOdeOptions& options = {});
/// Several tie levels (each with its own plastic elongation and yield state;
/// modes: rest, or rocking with the set of yielding levels).
TiedRockingResult analyse_tied_rocking(const RockingModel& model, const std::vector<RockingTie>& ties,
                                       const std::vector<double>& ug, double dt, double t_end,
                                       const HybridOdeOptions& options = {});

/// The same for a one-sided chain (dynamics/chain_dynamics.hpp) held by the
/// tie level `tie` (chain coordinates, the whole level on the chain: N, N/m):
///   M(q) q'' = [the chain's equation] + T d . dp/dq,
/// with the anchor's e(q) and dp/dq from the chain's exact configuration
/// tabulated at 2000 nodes over the chain's grid (cubic Hermite for e, linear
/// for de/dq); `e` is the coefficient of restitution at q = 0 (in [-1, 0]).
/// Forces and energies of the result are those of the level (N, J).
TiedRockingResult analyse_tied_chain(const ChainDynamics& chain, const TieRestraint& tie, double e,
                                     const std::vector<double>& ug, double dt, double t_end,
                                     const HybridOdeOptions& options = {});
TiedRockingResult analyse_tied_chain(const ChainDynamics& chain, const std::vector<TieRestraint>& ties, double e,
                                     const std::vector<double>& ug, double dt, double t_end,
                                     const HybridOdeOptions& options = {});

/// The restoring moment (force) of the tied wall with every level at its
/// strength (the rigid-plastic envelope of the elastic-perfectly-plastic
/// ties): the collapse rotation where it vanishes after its peak (rad), the
/// energy capacity up to there (seed §3.2 on the envelope: J/m for a body, J
/// for a chain), and the curve at n + 1 rotations evenly spaced on [0, collapse]
/// (rad; N m/m or N m).
struct TiedEnvelope {
  double theta_collapse = 0.0;
  double capacity = 0.0;
  std::vector<double> theta, restoring;
};
TiedEnvelope tied_envelope(const RockingModel& model, const std::vector<RockingTie>& ties, int n = 200);
TiedEnvelope tied_envelope(const ChainDynamics& chain, const std::vector<TieRestraint>& ties, int n = 200);

/// The tied analysis as every front end runs an analysis (issue 21's rule,
/// dynamics/analysis_end.hpp): the record scaled and reversed as in
/// `options`, integrated to its last sample, then free motion that ends when
/// the wall rests, or at an impact after which its energy is at most
/// free_energy_fraction of the least work from rest to the peak rotation
/// (a lower bound with the ties: the bare wall's work minus what a tie at its
/// strength could give back where it shortens, docs/theory/ties.md §6), or at
/// the cap options.tail_s. The result is a RockingResult: theta_u is the
/// collapse rotation with the ties at their strength; the energy measure
/// (seed §3.2) is taken on that rigid-plastic envelope of the tied wall's
/// restoring moment (demand: its work up to theta_max, or capacity + kinetic
/// energy at collapse; capacity: its work up to theta_u) [I]; `ties` holds
/// each level's outcome. options.overturn must be theta_u.
RockingResult analyse_tied(const RockingModel& model, const std::vector<RockingTie>& ties, const Record& record,
                           const RockingOptions& options);
RockingResult analyse_tied(const ChainDynamics& chain, const std::vector<TieRestraint>& ties, double e,
                           const Record& record, const RockingOptions& options);

}  // namespace assess
