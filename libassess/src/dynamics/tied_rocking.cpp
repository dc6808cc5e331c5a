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

// The body the tie holds: the rocking model (per unit depth) or a chain (whole
// level). Each gives the acceleration without the tie, the generalised inertia,
// the lift-off margin without the tie, the impact, and the tie's geometry.
struct RockingAdapter {
  const RockingModel& m;
  const RockingTie& t;
  double acc(double q, double /*qd*/, double ug) const { return m.angular_acceleration(q, +1, q > m.theta_cr(), ug); }
  double inertia(double /*q*/) const { return m.body().I0; }
  double lift(double ug) const { return m.lift_margin(+1, ug); }
  double impact(double w) const { return m.impact(w); }
  double elong(double q) const { return t.elongation(q); }
  double delong(double q) const { return t.delongation(q); }
  double gforce(double q, double T) const { return t.generalised_force(q, T); }
  double k() const { return t.stiffness; }
  double cap() const { return t.capacity; }
  double P0() const { return t.pretension; }
};

struct ChainTieTable {
  double h = 0.0;
  std::vector<double> e, de;  // at q_k = k h
  double eval(const std::vector<double>& v, double q, double& f, std::size_t& i) const {
    const double x = std::min(std::max(q / h, 0.0), double(e.size() - 1) - 1e-9);
    i = static_cast<std::size_t>(x);
    f = x - double(i);
    return v[i];
  }
  double elong(double q) const {
    double f;
    std::size_t i;
    eval(e, q, f, i);
    // Cubic Hermite with the exact slopes de/dq at the nodes.
    const double h00 = (1 + 2 * f) * (1 - f) * (1 - f), h10 = f * (1 - f) * (1 - f), h01 = f * f * (3 - 2 * f),
                 h11 = f * f * (f - 1);
    return h00 * e[i] + h10 * h * de[i] + h01 * e[i + 1] + h11 * h * de[i + 1];
  }
  double delong(double q) const {
    double f;
    std::size_t i;
    eval(de, q, f, i);
    return de[i] + f * (de[i + 1] - de[i]);
  }
};

struct ChainAdapter {
  const ChainDynamics& c;
  const TieRestraint& t;
  const ChainTieTable& tab;
  double e;
  double acc(double q, double qd, double ug) const { return c.acceleration(q, qd, q > c.q_cr(), ug, +1); }
  double inertia(double q) const { return c.mass(q); }
  double lift(double ug) const { return c.rest_force(ug, +1) / c.mass(0.0); }
  double impact(double w) const { return e * w; }
  double elong(double q) const { return tab.elong(q); }
  double delong(double q) const { return tab.delong(q); }
  // Generalised force T d . dp/dq = -T de/dq.
  double gforce(double q, double T) const { return -T * tab.delong(q); }
  double k() const { return t.stiffness; }
  double cap() const { return t.capacity; }
  double P0() const { return std::min(t.pretension, t.capacity); }
};

template <class Body>
class TiedSystem : public HybridSystem {
 public:
  TiedSystem(const Body& b, const std::vector<double>& ug, double dt, double th_c, TiedRockingResult& out, bool history)
      : b_(b), ug_(ug), dt_(dt), th_c_(th_c), out_(out), history_(history) {}

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
    return std::min(std::max(b_.P0() + b_.k() * (b_.elong(y[0]) - y[2]), 0.0), b_.cap());
  }
  bool rhs(double t, const double* y, int mode, double* f) const override {
    if (mode == kRest) {
      f[0] = f[1] = f[2] = 0.0;
      return true;
    }
    const double th = y[0];
    const double T = mode == kYield ? b_.cap() : force(y);
    f[0] = y[1];
    f[1] = b_.acc(th, y[1], ug(t)) + b_.gforce(th, T) / b_.inertia(th);
    f[2] = mode == kYield ? b_.delong(th) * y[1] : 0.0;
    return true;
  }
  std::size_t event_count(int mode) const override { return mode == kRest ? 1 : 3; }
  double event(std::size_t k, double t, const double* y, int mode) const override {
    if (mode == kRest)  // lift-off: s theta''(0) with the pretension's moment
      return b_.lift(ug(t)) + b_.gforce(0.0, b_.P0()) / b_.inertia(0.0);
    if (k == 0) return y[0];               // impact at theta = 0 (falling)
    if (k == 1) return y[0] - th_c_;       // collapse (rising)
    if (mode == kElastic)                  // yield (rising)
      return b_.P0() + b_.k() * (b_.elong(y[0]) - y[2]) - b_.cap();
    return b_.delong(y[0]) * y[1];         // unloading (falling)
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
      y[1] = b_.impact(y[1]);
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
    const double T = mode == kRest ? std::min(b_.P0(), b_.cap()) : mode == kYield ? b_.cap() : force(y1);
    out_.max_force = std::max(out_.max_force, T);
    out_.max_elongation = std::max(out_.max_elongation, b_.elong(y1[0]));
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
  Body b_;
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
  TiedSystem<RockingAdapter> sys(RockingAdapter{model, tie}, ug, dt, R.theta_collapse, R, history);
  double y[3] = {0.0, 0.0, 0.0};
  const double t1 = std::min(t_end, dt * double(ug.size() - 1));
  const HybridOdeResult h = integrate_hybrid(sys, 0.0, t1, y, kRest, options);
  R.termination = h.termination;
  R.t_end = h.t;
  R.plastic_elongation = y[2];
  R.plastic_energy = tie.capacity * R.plastic_elongation;
  return R;
}

TiedRockingResult analyse_tied_chain(const ChainDynamics& chain, const TieRestraint& tie, double e,
                                     const std::vector<double>& ug, double dt, double t_end, bool history,
                                     const HybridOdeOptions& options) {
  if (!(tie.stiffness > 0.0) || !(tie.capacity > 0.0)) throw InputError("tied chain: the tie needs k > 0 N/m and T_Rd > 0 N");
  if (!(e >= -1.0 && e <= 0.0)) throw InputError("tied chain: one-sided restitution must be in [-1, 0]");
  if (!(dt > 0.0) || ug.size() < 2) throw InputError("tied chain: expected >= 2 samples and dt > 0 s");
  if (tie.block < 0 || tie.block >= static_cast<int>(chain.chain().blocks().size()))
    throw InputError("tied chain: the tie holds no block of the chain");
  // The anchor's elongation and its slope on the chain's grid.
  ChainTieTable tab;
  const double q_end = chain.grid_step() * double(chain.grid_intervals());
  const int n = 2000;
  tab.h = q_end / n;
  for (int k = 0; k <= n; ++k) {
    const ChainState st = chain.exact(k * tab.h);
    const Eigen::Vector2d p = chain.chain().position(tie.block, tie.point, st.Q);
    const Eigen::Vector2d dp = chain.chain().position_jacobian(tie.block, tie.point, st.Q) * st.dQ;
    tab.e.push_back(-tie.direction.dot(p - tie.point));
    tab.de.push_back(-tie.direction.dot(dp));
  }
  const ChainAdapter body{chain, tie, tab, e};
  TiedRockingResult R;
  // Collapse: the first zero of the net restoring force with the tie at T_Rd after its peak.
  auto net = [&](double q) { return chain.net_restoring(q) - body.gforce(q, tie.capacity); };
  double q_peak = 0.0, best = -1e300;
  for (int k = 1; k < n; ++k)
    if (net(k * tab.h) > best) best = net(k * tab.h), q_peak = k * tab.h;
  double lo = q_end, hi = q_end;
  for (int k = 1; k <= n; ++k)
    if (k * tab.h > q_peak && net(k * tab.h) <= 0.0) {
      lo = (k - 1) * tab.h;
      hi = k * tab.h;
      break;
    }
  for (int i = 0; i < 100 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (net(mid) > 0.0 ? lo : hi) = mid;
  }
  R.theta_collapse = hi;
  TiedSystem<ChainAdapter> sys(body, ug, dt, R.theta_collapse, R, history);
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
