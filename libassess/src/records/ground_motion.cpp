// ground_motion.cpp: piecewise-linear records and functional excitations.
//
// Notation: ug''(t) ground acceleration (m/s^2, positive outward, seed Eq. 1);
//   samples_[i] = f * acc[i] at t_i = i dt, f = scale (negated if reversed);
//   between samples ug'' is linear, so every t_i is a breakpoint (a kink) the
//   integrator must not step across (research notes rocking.md §3.1).
#include "assess/records/ground_motion.hpp"

#include "assess/support/error.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace assess {

GroundMotion GroundMotion::from_record(const Record& record, double scale, bool reverse) {
  if (!(record.dt > 0.0 && std::isfinite(record.dt)))
    throw InputError("record '" + record.name + "': time step must be positive (s)");
  if (record.acc.size() < 2) throw InputError("record '" + record.name + "' has fewer than 2 samples");
  if (!std::isfinite(scale)) throw InputError("scale factor must be finite");
  GroundMotion g;
  const double f = reverse ? -scale : scale;
  g.samples_.reserve(record.acc.size());
  for (double a : record.acc) g.samples_.push_back(f * a);
  g.dt_ = record.dt;
  g.inv_dt_ = 1.0 / record.dt;
  g.duration_ = record.duration();
  // Suffix extremes, the zero after the record included.
  const std::size_t n = g.samples_.size();
  g.suffix_min_.resize(n);
  g.suffix_max_.resize(n);
  double lo = 0.0, hi = 0.0;
  for (std::size_t i = n; i-- > 0;) {
    lo = std::min(lo, g.samples_[i]);
    hi = std::max(hi, g.samples_[i]);
    g.suffix_min_[i] = lo;
    g.suffix_max_[i] = hi;
  }
  return g;
}

void GroundMotion::acc_range_from(double t, double& lo, double& hi) const {
  if (!samples_.empty()) {
    // ug'' on [t_i, t_i+1] lies between samples i and i+1: from sample
    // i = floor(t / dt) on, one sample earlier against the rounding of t / dt.
    const double x = t < 0.0 ? 0.0 : std::max(0.0, std::floor(t * inv_dt_) - 1.0);
    if (x >= double(samples_.size())) {
      lo = hi = 0.0;
      return;
    }
    const auto i = static_cast<std::size_t>(x);
    lo = suffix_min_[i];
    hi = suffix_max_[i];
    return;
  }
  if (!fn_ || t > duration_) {
    lo = hi = 0.0;
    return;
  }
  lo = -std::numeric_limits<double>::infinity();
  hi = std::numeric_limits<double>::infinity();
}

GroundMotion GroundMotion::from_function(std::function<double(double)> acc_m_s2, double duration_s,
                                         std::vector<double> breakpoints_s, double max_step_s) {
  if (!(duration_s >= 0.0 && std::isfinite(duration_s)))
    throw InputError("excitation duration must be finite and >= 0 (s)");
  if (!(max_step_s > 0.0)) throw InputError("maximum step of an excitation function must be positive (s)");
  GroundMotion g;
  g.max_step_ = max_step_s;
  g.fn_ = std::move(acc_m_s2);
  g.duration_ = duration_s;
  std::sort(breakpoints_s.begin(), breakpoints_s.end());
  g.breakpoints_ = std::move(breakpoints_s);
  return g;
}

GroundMotion GroundMotion::none(double duration_s) {
  return from_function([](double) { return 0.0; }, duration_s);
}

double GroundMotion::next_breakpoint(double t) const {
  if (!samples_.empty()) {
    // index of the first sample strictly after t (robust to t a rounded sample time)
    if (t < 0.0) return 0.0;
    double i = static_cast<double>(static_cast<long>(t * inv_dt_)) + 1.0;  // floor for t >= 0
    if (i * dt_ <= t) i += 1.0;
    return i * dt_;
  }
  const auto it = std::upper_bound(breakpoints_.begin(), breakpoints_.end(), t);
  return it == breakpoints_.end() ? std::numeric_limits<double>::infinity() : *it;
}

bool GroundMotion::linear_piece(double t, LinearPiece& out) const {
  if (samples_.empty()) return false;
  if (t < 0.0) {  // acc() is zero before the record starts; next_breakpoint(t) = 0
    out = {t, 0.0, 0.0, 0.0};
    return true;
  }
  // The interval [t_k, t_k+1] whose end is next_breakpoint(t): the same index
  // rule, so piece and breakpoint never disagree on a rounded sample time.
  long j = static_cast<long>(t * inv_dt_) + 1;  // floor + 1 for t >= 0
  if (double(j) * dt_ <= t) ++j;
  const auto k = static_cast<std::size_t>(j - 1);
  out.origin = double(k) * dt_;
  out.end = double(j) * dt_;  // next_breakpoint(t): the same i (as a double) times dt_
  if (k + 1 >= samples_.size()) {  // past the last sample: acc() is zero (the tail)
    out.a0 = out.a1 = 0.0;
    return true;
  }
  out.a0 = samples_[k];
  out.a1 = (samples_[k + 1] - samples_[k]) * inv_dt_;
  return true;
}

double GroundMotion::pga() const {
  double m = 0.0;
  for (double a : samples_) m = std::max(m, std::fabs(a));
  return m;
}

}  // namespace assess
