// record.hpp: a ground-motion record (accelerogram) sampled at a constant
// time step, in SI units.
#pragma once

#include <string>
#include <vector>

namespace assess {

/// An accelerogram: acc[i] is the ground acceleration (m/s^2) at t = i*dt,
/// positive in the direction of the record's component (see metadata).
/// The excitation between samples is linear (piecewise-linear record).
struct Record {
  std::string name;       ///< file stem or given name
  std::string source;     ///< file path it was read from, if any
  std::string event;      ///< event description from the header, if any
  std::string station;    ///< station, if any
  std::string component;  ///< component / azimuth (e.g. "270", "WE"), if any
  std::string format;     ///< "PEER AT2", "ESM ASCII", "ITACA ASCII", "GEM cor.acc", "plain"
  double dt = 0.0;        ///< time step (s), > 0
  std::vector<double> acc;  ///< accelerations (m/s^2)

  std::size_t size() const { return acc.size(); }
  double duration() const { return acc.empty() ? 0.0 : dt * double(acc.size() - 1); }  ///< s
  /// Peak ground acceleration max|acc| (m/s^2).
  double pga() const;
  /// Time of the peak (s).
  double t_pga() const;
  /// A copy scaled by `factor` (and, if `reverse`, with flipped polarity).
  Record scaled(double factor, bool reverse = false) const;
  /// Ground acceleration at time t (m/s^2), linear between samples, 0 outside.
  double at(double t) const;
};

}  // namespace assess
