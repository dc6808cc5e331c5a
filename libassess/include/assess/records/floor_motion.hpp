// floor_motion.hpp: the acceleration of a floor at height Z of a building
// from a ground motion, filtered by the building's first mode (the model
// behind the floor spectra of Circ. 2019 §C7.2.3, [C7.2.5]-[C7.2.10]):
//
//   a_Z(t) = ug''(t) + gamma psi(Z) ur''(t)
//
// with ur'' the relative acceleration of a linear oscillator of period T1 and
// damping ratio xi under ug'' (ur'' + 2 xi w ur' + w^2 ur = -ug'', w = 2 pi / T1),
// gamma = 3N/(2N+1) and psi(Z) = Z/H for a linear first mode (the caller gives
// the product gamma psi; kinematic/code_rules.hpp holds both).
// The oscillator is integrated exactly for the record's piecewise-linear
// acceleration (state-transition matrix of the oscillator augmented with the
// linear excitation, computed once per time step by the matrix exponential).
#pragma once

#include "assess/records/record.hpp"

namespace assess {

/// The first-mode filter of a building.
struct FloorFilter {
  double T1 = 0.0;         ///< first-mode period (s), > 0
  double xi = 0.05;        ///< damping ratio of the first mode (-, 0.05 = 5 %), in [0, 1)
  double gamma_psi = 0.0;  ///< participation x mode shape at Z (-), >= 0
  void validate() const;   ///< throws InputError naming the field and its unit
};

/// The relative acceleration ur''(t_i) (m/s^2) of the oscillator (T1, xi) at
/// the record's samples, starting at rest.
std::vector<double> oscillator_relative_acceleration(const Record& ground, double T1_s, double xi);

/// The floor motion a_Z(t_i) = ug''(t_i) + gamma psi ur''(t_i) as a record
/// with the same time step (named "<name> @Z"; metadata copied).
Record floor_motion(const Record& ground, const FloorFilter& filter);

}  // namespace assess
