// chain_analysis.hpp: time-history analysis of a 1-DOF chain (ChainDynamics)
// under a ground or floor motion, by the generic hybrid integrator, with the
// results of the rocking analysis (the chain's coordinate q in place of theta).
//
// One-sided: the chain moves outward only (q >= 0) and impacts at q = 0, where
// the generalised velocity jumps: q'+ = e q'-, e in [-1, 0] (seed convention:
// negative = rebound; e = 0 stops the chain). Two-sided (mirror-symmetric
// chains only, ChainDynamics::symmetric): q < 0 is the mirror image of the
// outward mechanism and the chain goes through q = 0 with q'+ = e q'-, e in
// [0, 1]. Since M(q) is continuous at q = 0 the kinetic energy after the
// impact is e^2 times the energy before (docs/theory/chain-dynamics.md §3).
#pragma once

#include "assess/dynamics/chain_dynamics.hpp"
#include "assess/dynamics/rocking_analysis.hpp"
#include "assess/records/ground_motion.hpp"

namespace assess {

/// Analysis of the chain under `motion` with restitution e (one-sided [-1, 0],
/// two-sided [0, 1]), from an initial state (q, rad; q', rad/s; one-sided
/// q >= 0). The result uses RockingResult's fields with theta = q: theta_max =
/// peak |q| and its side, theta_u = q_u, theta_cr = q_cr,
/// energy demand and capacity from the work of the net restoring force (J,
/// whole chain, not per unit length), d_max = 0 (the caller computes the
/// control displacement with ChainDynamics::horizontal_displacement), alpha = 0.
/// Options: overturn must be theta_u (q reaches q_u); scale and reverse are not applied.
/// @throws InputError for e outside its range, a half_pi criterion, a
///   negative initial q (one-sided), two-sided motion of a chain that is not symmetric
RockingResult analyse_chain(const ChainDynamics& model, const GroundMotion& motion, const RockingOptions& options,
                            double e, const RockingInitialState& initial = {},
                            Sidedness sidedness = Sidedness::one_sided);

/// The same under a record, scaled and polarity-flipped as in options.
RockingResult analyse_chain(const ChainDynamics& model, const Record& record, const RockingOptions& options,
                            double e, Sidedness sidedness = Sidedness::one_sided);

}  // namespace assess
