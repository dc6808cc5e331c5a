// tied_rocking.cpp: one-sided rocking with a tie rod (docs/theory/ties.md §6).
#include "assess/dynamics/tied_rocking.hpp"

#include "assess/support/error.hpp"

#include <algorithm>
#include <cmath>

namespace assess {

Eigen::Vector2d RockingTie::position(double th) const {
  const double c = std::cos(th), s = std::sin(th);
  // Outward rotation about the toe (clockwise in x-z): x' = x c + z s, z' = -x s + z c.
  return {point.x() * c + point.y() * s, -point.x() * s + point.y() * c};
}

double RockingTie::elongation(double th) const { return -direction.dot(position(th) - point); }

double RockingTie::delongation(double th) const {
  const Eigen::Vector2d p = position(th);
  return -direction.dot(Eigen::Vector2d(p.y(), -p.x()));
}

double RockingTie::generalised_force(double th, double T) const {
  const Eigen::Vector2d p = position(th);
  return T * direction.dot(Eigen::Vector2d(p.y(), -p.x()));
}

void RockingTie::validate() const {
  if (!point.allFinite()) throw InputError("tie on the rocking body: point: expected finite (x, z) in m");
  if (!(std::fabs(direction.norm() - 1.0) < 1e-9)) throw InputError("tie on the rocking body: direction: expected a unit vector");
  if (!(stiffness > 0.0) || !std::isfinite(stiffness)) throw InputError("tie on the rocking body: stiffness: expected > 0 N/m");
  if (!(capacity > 0.0) || !std::isfinite(capacity)) throw InputError("tie on the rocking body: capacity: expected > 0 N/m");
  if (!(pretension >= 0.0 && pretension <= capacity))
    throw InputError("tie on the rocking body: pretension: expected in [0, capacity] N/m");
}

namespace {

enum Mode { kRest = 0, kElastic = 1, kYield = 2 };

class TiedSystem : public HybridSystem {
 public:
  TiedSystem(const RockingModel& m, const RockingTie& t, const std::vector<double>& ug, double dt, double th_c,
             TiedRockingResult& out, bool history)
      : m_(m), t_(t), ug_(ug), dt_(dt), th_c_(th_c), out_(out), history_(history) {}

  std::size_t dimension() const override { return 3; }
  double ug(double t) const {
    const double x = t / dt_;
    if (!(x >= 0.0)) return ug_.front();
    const std::size_t i = static_cast<std::size_t>(x);
    if (i + 1 >= ug_.size()) return i < ug_.size() ? ug_.back() : 0.0;
    const double f = x - double(i);
    return ug_[i] + f * (ug_[i + 1] - ug_[i]);
  }
  double force(const double* y) const {
    return std::min(std::max(t_.pretension + t_.stiffness * (t_.elongation(y[0]) - y[2]), 0.0), t_.capacity);
  }
  bool rhs(double t, const double* y, int mode, double* f) const override {
    if (mode == kRest) {
      f[0] = f[1] = f[2] = 0.0;
      return true;
    }
    const double th = y[0];
    const bool partial = th > m_.theta_cr();
    const double T = mode == kYield ? t_.capacity : force(y);
    f[0] = y[1];
    f[1] = m_.angular_acceleration(th, +1, partial, ug(t)) + t_.generalised_force(th, T) / m_.body().I0;
    f[2] = mode == kYield ? t_.delongation(th) * y[1] : 0.0;
    return true;
  }
  std::size_t event_count(int mode) const override { return mode == kRest ? 1 : 3; }
  double event(std::size_t k, double t, const double* y, int mode) const override {
    if (mode == kRest)  // lift-off: s theta''(0) with the pretension's moment
      return m_.lift_margin(+1, ug(t)) + t_.generalised_force(0.0, t_.pretension) / m_.body().I0;
    if (k == 0) return y[0];               // impact at theta = 0 (falling)
    if (k == 1) return y[0] - th_c_;       // collapse (rising)
    if (mode == kElastic)                  // yield (rising)
      return t_.pretension + t_.stiffness * (t_.elongation(y[0]) - y[2]) - t_.capacity;
    return t_.delongation(y[0]) * y[1];    // unloading (falling)
  }
  EventDirection event_direction(std::size_t k, int mode) const override {
    if (mode == kRest) return EventDirection::rising;
    if (k == 0) return EventDirection::falling;
    if (k == 1) return EventDirection::rising;
    return mode == kElastic ? EventDirection::rising : EventDirection::falling;
  }
  EventAction on_event(std::size_t k, double, double* y, int& mode) override {
    if (mode == kRest) {
      mode = kElastic;
      return EventAction::proceed;
    }
    if (k == 0) {
      ++out_.impacts;
      y[0] = 0.0;
      y[1] = m_.impact(y[1]);
      if (!(y[1] > 1e-9)) {
        y[1] = 0.0;
        mode = kRest;
      } else {
        mode = kElastic;
      }
      return EventAction::proceed;
    }
    if (k == 1) {
      out_.overturned = true;
      return EventAction::stop;
    }
    if (mode == kElastic) {
      mode = kYield;
      out_.yielded = true;
    } else {
      mode = kElastic;
    }
    return EventAction::proceed;
  }
  void on_step(double, const double*, const double*, double t1, const double* y1, const double*, int mode) override {
    out_.theta_max = std::max(out_.theta_max, y1[0]);
    const double T = mode == kRest ? std::min(t_.pretension, t_.capacity) : mode == kYield ? t_.capacity : force(y1);
    out_.max_force = std::max(out_.max_force, T);
    out_.max_elongation = std::max(out_.max_elongation, t_.elongation(y1[0]));
    out_.plastic_elongation = y1[2];
    if (history_ && t1 >= next_sample_) {
      out_.t.push_back(t1);
      out_.theta.push_back(y1[0]);
      out_.force.push_back(T);
      next_sample_ = t1 + dt_;
    }
  }
  double next_breakpoint(double t) const override {
    const double k = std::floor(t / dt_ + 1e-9) + 1.0;
    return std::min(k * dt_, dt_ * double(ug_.size() - 1));
  }
  bool stationary(int mode) const override { return mode == kRest; }

 private:
  const RockingModel& m_;
  const RockingTie& t_;
  const std::vector<double>& ug_;
  double dt_, th_c_;
  TiedRockingResult& out_;
  bool history_;
  double next_sample_ = 0.0;
};

}  // namespace

TiedRockingResult analyse_tied_rocking(const RockingModel& model, const RockingTie& tie, const std::vector<double>& ug,
                                       double dt, double t_end, bool history, const HybridOdeOptions& options) {
  tie.validate();
  if (model.sidedness() != Sidedness::one_sided)
    throw InputError("tied rocking: the model must be one-sided (a façade against its transverse walls)");
  if (!(dt > 0.0) || ug.size() < 2) throw InputError("tied rocking: expected >= 2 samples and dt > 0 s");
  TiedRockingResult R;
  // Collapse: the first rotation beyond the peak at which the net restoring
  // moment with the tie at its capacity vanishes (scan, then bisection).
  auto net = [&](double th) {
    return model.restoring_moment(th, +1, th > model.theta_cr()) - model.body().M_ext -
           tie.generalised_force(th, tie.capacity);
  };
  double lo = 0.0, hi = 0.0;
  const double step = 1e-3;
  for (double th = step; th < 1.5707; th += step)
    if (net(th) <= 0.0 && th > model.theta_peak(+1)) {
      lo = th - step;
      hi = th;
      break;
    }
  if (hi == 0.0) hi = lo = 1.5707;
  for (int i = 0; i < 100 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (net(mid) > 0.0 ? lo : hi) = mid;
  }
  R.theta_collapse = hi;
  TiedSystem sys(model, tie, ug, dt, R.theta_collapse, R, history);
  double y[3] = {0.0, 0.0, 0.0};
  const double t1 = std::min(t_end, dt * double(ug.size() - 1));
  const HybridOdeResult h = integrate_hybrid(sys, 0.0, t1, y, kRest, options);
  R.termination = h.termination;
  R.t_end = h.t;
  R.plastic_elongation = y[2];
  R.plastic_energy = tie.capacity * R.plastic_elongation;
  return R;
}

}  // namespace assess
