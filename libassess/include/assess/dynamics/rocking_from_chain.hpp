// rocking_from_chain.hpp: the rocking body of a one-block mechanism, built
// from the same kinematic chain as the code checks (issue: façade
// assessment), not re-entered by hand.
#pragma once

#include "assess/kinematic/chain.hpp"
#include "assess/dynamics/rocking_body.hpp"

#include <Eigen/Core>
#include <string>

namespace assess {

/// A rocking body per unit depth of wall, and where it came from.
struct ChainRockingBody {
  RockingBody body;              ///< per unit depth (N/m, kg m^2/m, N m/m)
  Eigen::Vector2d hinge{0, 0};   ///< the toe: the block's ground hinge (m, chain coordinates)
  double length = 1.0;           ///< out-of-plane length the chain's weights refer to (m)
  double total_weight = 0.0;     ///< W over the whole length (N)
  Eigen::Vector2d centroid{0, 0};  ///< of all the weights (m, chain coordinates)
  /// Horizontal displacement (m) of a material point p0 (chain coordinates) of
  /// the block rotated outward by theta (rad) about the hinge.
  double horizontal_displacement(const Eigen::Vector2d& p0, double theta) const;
};

/// Builds the body of a chain that rotates as ONE rigid body about a single
/// ground hinge (one block, or blocks welded together such as the slices of a
/// gable):
/// weight W = self weight + carried weights (bearing and seismic), centroid of
/// all of them, I0 = sum of the blocks' (I_c + m d^2) and the carried point
/// masses about the hinge, half base width b = half the extent of the block's
/// base at the hinge level, constant moment of the external forces and ties
/// about the hinge (virtual work of a rotation about it). Everything is
/// divided by the out-of-plane length of the block on the hinge (per unit
/// length of the base).
/// @throws InputError for a chain whose blocks move relative to each other
///   ("multi-block chains use the chain model", dynamics/chain_dynamics.hpp), no or
///   several ground hinges, a
///   carried weight whose mass and weight do not both act, or friction loads.
ChainRockingBody rocking_body_from_chain(const Chain& chain);

}  // namespace assess
