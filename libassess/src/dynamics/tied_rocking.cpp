// tied_rocking.cpp: one-sided rocking of a body or a chain held by tie rods
// (docs/theory/ties.md §6).
#include "assess/dynamics/tied_rocking.hpp"

#include "assess/support/error.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <memory>

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

// A tie level as the system sees it: its law and its geometry e(q), de/dq
// (the generalised force of a force T is -T de/dq, since e = -d . (p - p0)).
struct Level {
  double k = 0.0, cap = 0.0, P0 = 0.0;
  std::function<double(double)> e, de;
};

// The body the ties hold: the rocking model (per unit depth) or a chain (whole
// level): acceleration without the ties, generalised inertia, lift-off margin
// without the ties (rad/s^2), impact.
struct Body {
  std::function<double(double, double, double)> acc;  // (q, q', ug)
  std::function<double(double)> inertia;
  std::function<double(double)> lift;
  std::function<double(double)> impact;
};

// A tabulated e(q), de/dq of a chain's anchor: cubic Hermite for e with the
// exact slopes, linear for de/dq.
struct ChainTieTable {
  double h = 0.0;
  std::vector<double> e, de;  // at q_k = k h
  std::size_t locate(double q, double& f) const {
    // A trial stage may stray (even to NaN): held on the table, no conversion of NaN to an index.
    double x = q / h;
    if (!(x > 0.0)) x = 0.0;
    x = std::min(x, double(e.size() - 1) - 1e-9);
    const std::size_t i = static_cast<std::size_t>(x);
    f = x - double(i);
    return i;
  }
  double elong(double q) const {
    double f;
    const std::size_t i = locate(q, f);
    const double h00 = (1 + 2 * f) * (1 - f) * (1 - f), h10 = f * (1 - f) * (1 - f), h01 = f * f * (3 - 2 * f),
                 h11 = f * f * (f - 1);
    return h00 * e[i] + h10 * h * de[i] + h01 * e[i + 1] + h11 * h * de[i + 1];
  }
  double delong(double q) const {
    double f;
    const std::size_t i = locate(q, f);
    return de[i] + f * (de[i + 1] - de[i]);
  }
};

// Modes: -1 rest; m >= 0 rocking with bit i of m set when level i yields.
constexpr int kRest = -1;

class TiedSystem : public HybridSystem {
 public:
  TiedSystem(const Body& b, const std::vector<Level>& lv, const std::vector<double>& ug, double dt, double th_c,
             TiedRockingResult& out, bool history)
      : b_(b), lv_(lv), ug_(ug), dt_(dt), th_c_(th_c), out_(out), history_(history) {
    out_.levels.assign(lv_.size(), TiedLevelResult{});
  }

  std::size_t dimension() const override { return 2 + lv_.size(); }
  double ug(double t) const {
    const double x = t / dt_;
    if (!(x >= 0.0)) return ug_.front();
    const std::size_t i = static_cast<std::size_t>(x);
    if (i + 1 >= ug_.size()) return i < ug_.size() ? ug_.back() : 0.0;
    const double f = x - double(i);
    return ug_[i] + f * (ug_[i + 1] - ug_[i]);
  }
  static bool yielding(int mode, std::size_t i) { return mode >= 0 && ((mode >> i) & 1); }
  double force(std::size_t i, const double* y, int mode) const {
    const Level& L = lv_[i];
    if (mode == kRest) return std::min(L.P0, L.cap);
    if (yielding(mode, i)) return L.cap;
    return std::min(std::max(L.P0 + L.k * (L.e(y[0]) - y[2 + i]), 0.0), L.cap);
  }
  bool rhs(double t, const double* y, int mode, double* f) const override {
    if (mode == kRest) {
      std::fill(f, f + dimension(), 0.0);
      return true;
    }
    const double th = y[0];
    double Q = 0.0;
    for (std::size_t i = 0; i < lv_.size(); ++i) {
      const double de = lv_[i].de(th);
      Q -= force(i, y, mode) * de;
      f[2 + i] = yielding(mode, i) ? de * y[1] : 0.0;
    }
    f[0] = y[1];
    f[1] = b_.acc(th, y[1], ug(t)) + Q / b_.inertia(th);
    return true;
  }
  std::size_t event_count(int mode) const override { return mode == kRest ? 1 : 2 + lv_.size(); }
  double event(std::size_t k, double t, const double* y, int mode) const override {
    if (mode == kRest) {  // lift-off with the pretensions' generalised force
      double Q = 0.0;
      for (const Level& L : lv_) Q -= std::min(L.P0, L.cap) * L.de(0.0);
      return b_.lift(ug(t)) + Q / b_.inertia(0.0);
    }
    if (k == 0) return y[0];          // impact at q = 0 (falling)
    if (k == 1) return y[0] - th_c_;  // collapse (rising)
    const std::size_t i = k - 2;
    const Level& L = lv_[i];
    if (!yielding(mode, i)) return L.P0 + L.k * (L.e(y[0]) - y[2 + i]) - L.cap;  // yield (rising)
    return L.de(y[0]) * y[1];                                                   // unloading (falling)
  }
  EventDirection event_direction(std::size_t k, int mode) const override {
    if (mode == kRest) return EventDirection::rising;
    if (k == 0) return EventDirection::falling;
    if (k == 1) return EventDirection::rising;
    return yielding(mode, k - 2) ? EventDirection::falling : EventDirection::rising;
  }
  EventAction on_event(std::size_t k, double, double* y, int& mode) override {
    if (mode == kRest) {
      mode = 0;
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
        mode = 0;  // at q = 0 every rod is back below its yield force
      }
      return EventAction::proceed;
    }
    if (k == 1) {
      out_.overturned = true;
      return EventAction::stop;
    }
    // A yield or unloading event; the state just past it also decides the
    // other levels, whose event functions may cross zero at the same instant
    // (every yielding rod unloads when theta' changes sign).
    const std::size_t i = k - 2;
    const bool unloading = yielding(mode, i);
    for (std::size_t j = 0; j < lv_.size(); ++j) {
      const Level& L = lv_[j];
      if (unloading && yielding(mode, j) && (j == i || L.de(y[0]) * y[1] <= 0.0)) mode &= ~(1 << j);
      if (!unloading && !yielding(mode, j) && (j == i || L.P0 + L.k * (L.e(y[0]) - y[2 + j]) >= L.cap)) {
        mode |= (1 << j);
        out_.levels[j].yielded = true;
      }
    }
    return EventAction::proceed;
  }
  void on_step(double, const double*, const double*, double t1, const double* y1, const double*, int mode) override {
    out_.theta_max = std::max(out_.theta_max, y1[0]);
    for (std::size_t i = 0; i < lv_.size(); ++i) {
      TiedLevelResult& r = out_.levels[i];
      r.max_force = std::max(r.max_force, force(i, y1, mode));
      r.max_elongation = std::max(r.max_elongation, lv_[i].e(y1[0]));
      r.plastic_elongation = y1[2 + i];
    }
    if (history_ && t1 >= next_sample_) {
      out_.t.push_back(t1);
      out_.theta.push_back(y1[0]);
      out_.force.push_back(lv_.empty() ? 0.0 : force(0, y1, mode));
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
  const std::vector<Level>& lv_;
  const std::vector<double>& ug_;
  double dt_, th_c_;
  TiedRockingResult& out_;
  bool history_;
  double next_sample_ = 0.0;
};

// Collapse coordinate: the first zero, after the peak, of the net restoring
// force with every level at its capacity; `q_end` if there is none before it.
double collapse_coordinate(const std::function<double(double)>& restoring, const std::vector<Level>& lv, double q_end) {
  auto net = [&](double q) {
    double r = restoring(q);
    for (const Level& L : lv) r += L.cap * L.de(q);
    return r;
  };
  const int n = 4000;
  const double h = q_end / n;
  double q_peak = 0.0, best = -1e300;
  for (int k = 1; k < n; ++k)
    if (net(k * h) > best) best = net(k * h), q_peak = k * h;
  double lo = q_end, hi = q_end;
  for (int k = 1; k <= n; ++k)
    if (k * h > q_peak && net(k * h) <= 0.0) {
      lo = (k - 1) * h;
      hi = k * h;
      break;
    }
  for (int i = 0; i < 100 && hi - lo > 1e-14; ++i) {
    const double mid = 0.5 * (lo + hi);
    (net(mid) > 0.0 ? lo : hi) = mid;
  }
  return hi;
}

TiedRockingResult integrate(const Body& body, const std::vector<Level>& lv, double q_c, const std::vector<double>& ug,
                            double dt, double t_end, bool history, const HybridOdeOptions& options) {
  if (!(dt > 0.0) || ug.size() < 2) throw InputError("tied rocking: expected >= 2 samples and dt > 0 s");
  if (lv.empty() || lv.size() > 16) throw InputError("tied rocking: expected 1 to 16 tie levels");
  TiedRockingResult R;
  R.theta_collapse = q_c;
  TiedSystem sys(body, lv, ug, dt, q_c, R, history);
  std::vector<double> y(2 + lv.size(), 0.0);
  const double t1 = std::min(t_end, dt * double(ug.size() - 1));
  const HybridOdeResult h = integrate_hybrid(sys, 0.0, t1, y.data(), kRest, options);
  R.termination = h.termination;
  R.t_end = h.t;
  for (std::size_t i = 0; i < lv.size(); ++i) {
    R.levels[i].plastic_elongation = y[2 + i];
    R.levels[i].plastic_energy = lv[i].cap * y[2 + i];
  }
  const TiedLevelResult& f = R.levels.front();
  R.max_force = f.max_force;
  R.max_elongation = f.max_elongation;
  R.plastic_elongation = f.plastic_elongation;
  R.plastic_energy = f.plastic_energy;
  for (const TiedLevelResult& l : R.levels) R.yielded = R.yielded || l.yielded;
  return R;
}

}  // namespace

TiedRockingResult analyse_tied_rocking(const RockingModel& model, const RockingTie& tie, const std::vector<double>& ug,
                                       double dt, double t_end, bool history, const HybridOdeOptions& options) {
  return analyse_tied_rocking(model, std::vector<RockingTie>{tie}, ug, dt, t_end, history, options);
}

TiedRockingResult analyse_tied_rocking(const RockingModel& model, const std::vector<RockingTie>& ties,
                                       const std::vector<double>& ug, double dt, double t_end, bool history,
                                       const HybridOdeOptions& options) {
  if (model.sidedness() != Sidedness::one_sided)
    throw InputError("tied rocking: the model must be one-sided (a façade against its transverse walls)");
  std::vector<Level> lv;
  for (const RockingTie& t : ties) {
    t.validate();
    Level L;
    L.k = t.stiffness;
    L.cap = t.capacity;
    L.P0 = t.pretension;
    L.e = [t](double q) { return t.elongation(q); };
    L.de = [t](double q) { return t.delongation(q); };
    lv.push_back(L);
  }
  Body b;
  b.acc = [&model](double q, double, double u) { return model.angular_acceleration(q, +1, q > model.theta_cr(), u); };
  const double I0 = model.body().I0;
  b.inertia = [I0](double) { return I0; };
  b.lift = [&model](double u) { return model.lift_margin(+1, u); };
  b.impact = [&model](double w) { return model.impact(w); };
  auto restoring = [&model](double q) {
    return model.restoring_moment(q, +1, q > model.theta_cr()) - model.body().M_ext;
  };
  const double q_c = collapse_coordinate(restoring, lv, 1.5707);
  return integrate(b, lv, q_c, ug, dt, t_end, history, options);
}

TiedRockingResult analyse_tied_chain(const ChainDynamics& chain, const TieRestraint& tie, double e,
                                     const std::vector<double>& ug, double dt, double t_end, bool history,
                                     const HybridOdeOptions& options) {
  return analyse_tied_chain(chain, std::vector<TieRestraint>{tie}, e, ug, dt, t_end, history, options);
}

TiedRockingResult analyse_tied_chain(const ChainDynamics& chain, const std::vector<TieRestraint>& ties, double e,
                                     const std::vector<double>& ug, double dt, double t_end, bool history,
                                     const HybridOdeOptions& options) {
  if (!(e >= -1.0 && e <= 0.0)) throw InputError("tied chain: one-sided restitution must be in [-1, 0]");
  const double q_end = chain.grid_step() * double(chain.grid_intervals());
  const int n = 2000;
  std::vector<Level> lv;
  for (const TieRestraint& tie : ties) {
    if (!(tie.stiffness > 0.0) || !(tie.capacity > 0.0))
      throw InputError("tied chain: a tie needs k > 0 N/m and T_Rd > 0 N");
    if (tie.block < 0 || tie.block >= static_cast<int>(chain.chain().blocks().size()))
      throw InputError("tied chain: a tie holds no block of the chain");
    // The anchor's elongation and its slope from the chain's exact configuration.
    auto tab = std::make_shared<ChainTieTable>();
    tab->h = q_end / n;
    for (int k = 0; k <= n; ++k) {
      const ChainState st = chain.exact(k * tab->h);
      const Eigen::Vector2d p = chain.chain().position(tie.block, tie.point, st.Q);
      const Eigen::Vector2d dp = chain.chain().position_jacobian(tie.block, tie.point, st.Q) * st.dQ;
      tab->e.push_back(-tie.direction.dot(p - tie.point));
      tab->de.push_back(-tie.direction.dot(dp));
    }
    Level L;
    L.k = tie.stiffness;
    L.cap = tie.capacity;
    L.P0 = std::min(tie.pretension, tie.capacity);
    L.e = [tab](double q) { return tab->elong(q); };
    L.de = [tab](double q) { return tab->delong(q); };
    lv.push_back(L);
  }
  Body b;
  b.acc = [&chain](double q, double qd, double u) { return chain.acceleration(q, qd, q > chain.q_cr(), u, +1); };
  b.inertia = [&chain](double q) { return chain.mass(q); };
  b.lift = [&chain](double u) { return chain.rest_force(u, +1) / chain.mass(0.0); };
  b.impact = [e](double w) { return e * w; };
  // The chain's tables end a little beyond its bare q_u: beyond them the
  // tied chain is stopped (counted as overturned), docs/theory/ties.md §6.
  const double q_c = collapse_coordinate([&chain](double q) { return chain.net_restoring(q); }, lv, q_end);
  return integrate(b, lv, q_c, ug, dt, t_end, history, options);
}

}  // namespace assess
