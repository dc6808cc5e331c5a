// ground_motion.hpp: the ground acceleration driving a rocking analysis,
// either a sampled record (piecewise linear between samples) or a given
// function of time (pulses, free vibration).
#pragma once

#include "assess/records/record.hpp"

#include <functional>
#include <limits>
#include <vector>

namespace assess {

/// Ground acceleration ug''(t) (m/s^2, positive outward) over [0, duration].
class GroundMotion {
 public:
  /// A record, scaled by `scale` and, if `reverse`, with flipped polarity
  /// (the record's positive direction becomes inward). Breakpoints at every sample.
  /// @param scale dimensionless factor, finite
  static GroundMotion from_record(const Record& record, double scale = 1.0, bool reverse = false);
  /// A function of time (m/s^2) on [0, duration_s], with the times (s) where
  /// it is not smooth. The integrator takes steps of at most max_step_s (s,
  /// default 0.01 s) so that a lift-off threshold crossed only briefly (while
  /// the body rests and its state does not limit the step) is not stepped over.
  static GroundMotion from_function(std::function<double(double)> acc_m_s2, double duration_s,
                                    std::vector<double> breakpoints_s = {}, double max_step_s = 0.01);
  /// No excitation for duration_s (free rocking).
  static GroundMotion none(double duration_s);

  /// ug''(t) (m/s^2); 0 outside [0, duration] (records and functions alike:
  /// the motion is the excitation on [0, duration], then free motion).
  double acc(double t) const {
    if (!samples_.empty()) {
      if (t < 0.0) return 0.0;
      const double x = t * inv_dt_;
      const long i = static_cast<long>(x);  // signed: a single conversion instruction
      if (static_cast<std::size_t>(i) + 1 >= samples_.size()) return t <= duration_ ? samples_.back() : 0.0;
      return samples_[i] + (x - double(i)) * (samples_[i + 1] - samples_[i]);
    }
    return fn_ && t <= duration_ ? fn_(t) : 0.0;
  }
  /// The range [lo, hi] of ug'' (m/s^2) over [t, +inf): the samples from the
  /// one at or before t to the last, and the zero after the end (records); for
  /// a function of time, [0, 0] from its end on and (-inf, +inf) before it
  /// (unknown). O(1): suffix extremes computed with the record (issue 21: the
  /// exact early end of an analysis whose body rests and cannot be lifted by
  /// what is left of the motion, docs/theory/rocking.md §8).
  void acc_range_from(double t, double& lo, double& hi) const;
  /// Next breakpoint strictly after t (s), +inf if none.
  double next_breakpoint(double t) const;

  /// ug'' on one sample interval as a linear function of the time from its
  /// start: ug''(t) = a0 + a1 (t - origin) for t in [origin, origin + dt]
  /// (m/s^2, m/s^3, s). The same straight line as acc() between two samples
  /// (zero past the last sample), so a right-hand side pays one multiply-add
  /// per evaluation instead of locating the sample.
  struct LinearPiece {
    double origin = 0.0;  ///< s: the sample time at the start of the interval
    double a0 = 0.0;      ///< m/s^2: ug'' at origin
    double a1 = 0.0;      ///< m/s^3: slope
    double end = 0.0;     ///< s: next_breakpoint(t) for the t asked, the same value to the bit
  };
  /// For a record: the piece of the interval that ends at next_breakpoint(t)
  /// (before the record, t < 0: the zero piece up to t = 0). None for a
  /// function of time, which has no such form. `end` saves the caller a
  /// separate next_breakpoint(t) (one index computation per sample interval).
  bool linear_piece(double t, LinearPiece& out) const;
  double duration() const { return duration_; }  ///< s
  /// Largest integration step that resolves the excitation (s): +inf for
  /// records (every sample is a breakpoint), max_step_s for functions.
  double max_step() const { return max_step_; }
  double pga() const;                             ///< max |ug''| over the samples (m/s^2); records only, else 0

 private:
  std::vector<double> samples_;  // m/s^2, already scaled
  std::vector<double> suffix_min_, suffix_max_;  // min/max of samples_[i..] and 0 (m/s^2)
  double dt_ = 0.0, inv_dt_ = 0.0;
  std::function<double(double)> fn_;
  std::vector<double> breakpoints_;
  double duration_ = 0.0;
  double max_step_ = std::numeric_limits<double>::infinity();
};

}  // namespace assess
