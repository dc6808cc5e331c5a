// tied_rocking.cpp: one-sided rocking of a body or a chain held by tie rods
// (docs/theory/ties.md §6).
#include "assess/dynamics/tied_rocking.hpp"

#include "assess/support/error.hpp"
#include "dynamics/integration_run.hpp"
#include "dynamics/quintic.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>
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
  bool brittle = false;  // not ductile: breaks when its force reaches cap (issue 29)
  double e_u = std::numeric_limits<double>::infinity();  // ductile: breaks at this elongation (m)
  std::function<double(double)> e, de;
};

// The body the ties hold: the rocking model (per unit depth) or a chain (whole
// level): acceleration without the ties, generalised inertia, lift-off margin
// without the ties (rad/s^2, affine in ug''), impact, and the net restoring
// moment (force) without the ties (N m/m or N m).
struct Body {
  std::function<double(double, double, double)> acc;  // (q, q', ug)
  std::function<double(double)> inertia;
  std::function<double(double)> lift;
  std::function<double(double)> impact;
  std::function<double(double)> restoring;
};

// Works of two restoring curves from rest to q, tabulated on [0, q_c]
// (trapezoids on n intervals; N m/m or N m):
//  - cap: the tied wall with every level at its strength, the rigid-plastic
//    envelope whose zero after the peak is q_c (the energy measure);
//  - lb: a lower bound of the work of the true restoring force whatever the
//    rods' state: the bare wall's, less T_y |de/dq| where a rod shortens as q
//    grows (there a rod can push the wall out, by at most its strength);
//    where rods lengthen they only resist (docs/theory/ties.md §6).
struct Works {
  double h = 0.0;
  std::vector<double> cap, lb;
  static double at(const std::vector<double>& w, double h, double q) {
    if (!(q > 0.0)) return 0.0;
    const double x = q / h;
    const std::size_t i = std::min(static_cast<std::size_t>(x), w.size() - 2);
    return w[i] + (x - double(i)) * (w[i + 1] - w[i]);
  }
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

// How an integration runs: with the end rule of analysis_end.hpp (front
// ends) or to a fixed end time (verification); the rest velocity (rad/s).
struct Settings {
  bool end_rule = false;
  double rest_velocity = 1e-9;
  bool history = false;
};

// The collapse coordinate of the body held by the intact levels (`broken[i]`
// true: level i lost), given the last coordinate of its tables.
using CollapseOf = std::function<double(const std::vector<char>& broken)>;

class TiedSystem : public HybridSystem {
 public:
  TiedSystem(const Body& b, const std::vector<Level>& lv, const GroundMotion& motion, double q_c, const Works& works,
             const Settings& set, RockingResult& out, CollapseOf collapse_of)
      : b_(b), lv_(lv), motion_(motion), q_c_(q_c), works_(works), set_(set), out_(out),
        collapse_of_(std::move(collapse_of)), broken_(lv.size(), 0) {
    out_.ties.assign(lv_.size(), TiedLevelResult{});
  }

  std::size_t dimension() const override { return 2 + lv_.size(); }
  static bool yielding(int mode, std::size_t i) { return mode >= 0 && ((mode >> i) & 1); }
  double force(std::size_t i, const double* y, int mode) const {
    const Level& L = lv_[i];
    if (broken_[i]) return 0.0;
    if (mode == kRest) return std::min(L.P0, L.cap);
    if (yielding(mode, i)) return L.cap;
    return std::min(std::max(L.P0 + L.k * (L.e(y[0]) - y[2 + i]), 0.0), L.cap);
  }
  // Lift-off margin at rest (rad/s^2) under ug'', with the pretensions' generalised force.
  double lift_margin(double ug) const {
    double Q = 0.0;
    for (std::size_t i = 0; i < lv_.size(); ++i)
      if (!broken_[i]) Q -= std::min(lv_[i].P0, lv_[i].cap) * lv_[i].de(0.0);
    return b_.lift(ug) + Q / b_.inertia(0.0);
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
    f[1] = b_.acc(th, y[1], motion_.acc(t)) + Q / b_.inertia(th);
    return std::isfinite(f[1]);
  }
  // Events: impact, collapse, then per level its strength (yield of a ductile
  // level, rupture of one that is not) or unloading, then per level the
  // rupture of a ductile rod at its ultimate elongation. A broken level's
  // events are constants that never cross.
  std::size_t event_count(int mode) const override { return mode == kRest ? 1 : 2 + 2 * lv_.size(); }
  double event(std::size_t k, double t, const double* y, int mode) const override {
    if (mode == kRest) return lift_margin(motion_.acc(t));
    if (k == 0) return y[0];          // impact at q = 0 (falling)
    if (k == 1) return y[0] - q_c_;   // collapse (rising)
    const std::size_t n = lv_.size();
    if (k >= 2 + n) {                 // rupture by elongation (rising)
      const std::size_t i = k - 2 - n;
      const Level& L = lv_[i];
      if (broken_[i] || L.brittle || !std::isfinite(L.e_u)) return -1.0;
      return L.e(y[0]) - L.e_u;
    }
    const std::size_t i = k - 2;
    if (broken_[i]) return 1.0;
    const Level& L = lv_[i];
    if (!yielding(mode, i)) return L.P0 + L.k * (L.e(y[0]) - y[2 + i]) - L.cap;  // strength (rising)
    return L.de(y[0]) * y[1];                                                   // unloading (falling)
  }
  EventDirection event_direction(std::size_t k, int mode) const override {
    if (mode == kRest) return EventDirection::rising;
    if (k == 0) return EventDirection::falling;
    if (k == 1) return EventDirection::rising;
    if (k >= 2 + lv_.size()) return EventDirection::rising;
    return yielding(mode, k - 2) ? EventDirection::falling : EventDirection::rising;
  }
  EventAction on_event(std::size_t k, double t, double* y, int& mode) override {
    if (mode == kRest) {
      mode = 0;
      push_history(t, y);
      return EventAction::proceed;
    }
    if (k == 0) {
      push_history(t, y);
      ++out_.impacts;
      y[0] = 0.0;
      y[1] = b_.impact(y[1]);
      mode = 0;  // at q = 0 every rod is back below its yield force
      if (!(y[1] > set_.rest_velocity)) {
        // Too slow to rise again by itself: at rest, unless the excitation lifts it now.
        y[1] = 0.0;
        if (!(lift_margin(motion_.acc(t)) > 0.0)) mode = kRest;
      } else if (set_.end_rule) {
        // Free motion: can the energy left reach the peak again (analysis_end.hpp)?
        const double energy = 0.5 * b_.inertia(0.0) * y[1] * y[1];
        if (detail::energy_decayed(motion_, t, energy, Works::at(works_.lb, works_.h, out_.theta_max))) {
          decayed_ = true;
          why_ = AnalysisEnd::energy_decayed;
        }
      }
      push_history(t, y);
      return EventAction::proceed;
    }
    if (k == 1) return overturn(t, y);
    if (k >= 2 + lv_.size()) {  // a ductile rod at its ultimate elongation
      const std::size_t i = k - 2 - lv_.size();
      mode &= ~(1 << i);
      return break_level(i, t, y, true);
    }
    // A strength or unloading event; the state just past it also decides the
    // other levels, whose event functions may cross zero at the same instant
    // (every yielding rod unloads when theta' changes sign).
    const std::size_t i = k - 2;
    const bool unloading = yielding(mode, i);
    std::vector<std::size_t> breaking;
    for (std::size_t j = 0; j < lv_.size(); ++j) {
      const Level& L = lv_[j];
      if (broken_[j]) continue;
      if (unloading && yielding(mode, j) && (j == i || L.de(y[0]) * y[1] <= 0.0)) mode &= ~(1 << j);
      if (!unloading && !yielding(mode, j) && (j == i || L.P0 + L.k * (L.e(y[0]) - y[2 + j]) >= L.cap)) {
        if (L.brittle) {
          breaking.push_back(j);  // not ductile: its weakest component fails (issue 29)
        } else {
          mode |= (1 << j);
          out_.ties[j].yielded = true;
        }
      }
    }
    for (std::size_t j : breaking) {
      out_.ties[j].max_force = std::max(out_.ties[j].max_force, lv_[j].cap);
      if (break_level(j, t, y, false) == EventAction::stop) return EventAction::stop;
    }
    return EventAction::proceed;
  }
  void on_step(double t0, const double* y0, const double* f0, double t1, const double* y1, const double* f1,
               int mode) override {
    consider_peak(t1, y1[0]);
    double tp, qp;  // the peak inside the step (quintic Hermite of q, as the untied analyses)
    if (mode != kRest && detail::extremum_in_step(t0, y0, f0, t1, y1, f1, tp, qp)) consider_peak(tp, qp);
    for (std::size_t i = 0; i < lv_.size(); ++i) {
      TiedLevelResult& r = out_.ties[i];
      if (broken_[i]) continue;  // its outcome is that of the instant it broke
      r.max_force = std::max(r.max_force, force(i, y1, mode));
      r.max_elongation = std::max(r.max_elongation, lv_[i].e(y1[0]));
      r.plastic_elongation = y1[2 + i];
    }
    push_history(t1, y1);
  }
  double next_breakpoint(double t) const override { return motion_.next_breakpoint(t); }
  double collapse() const { return q_c_; }
  bool stationary(int mode) const override { return mode == kRest; }
  // The end rule (analysis_end.hpp): at rest for good, or the energy after an
  // impact in the free motion cannot reach the peak again.
  bool finished(double t, const double*, int mode) override {
    if (!set_.end_rule) return false;
    if (mode == kRest) {
      auto lifts = [this](double ug) { return lift_margin(ug) > 0.0; };
      return detail::rests_for_good(motion_, t, lifts, why_);
    }
    return decayed_;
  }
  AnalysisEnd why() const { return why_; }

 private:
  // Level i breaks at t: its force is lost from then on; the wall held by the
  // levels left collapses where their envelope vanishes, at once if it is
  // already beyond that rotation.
  EventAction break_level(std::size_t i, double t, double* y, bool by_elongation) {
    broken_[i] = 1;
    TiedLevelResult& r = out_.ties[i];
    r.broken = true;
    r.broken_by_elongation = by_elongation;
    r.t_broken = t;
    r.max_elongation = std::max(r.max_elongation, lv_[i].e(y[0]));
    q_c_ = collapse_of_(broken_);
    if (y[0] >= q_c_) return overturn(t, y);
    return EventAction::proceed;
  }
  // The wall overturns at t: recorded, the analysis stops.
  EventAction overturn(double t, const double* y) {
    out_.overturned = true;
    out_.t_overturn = t;
    out_.kinetic_energy_overturn = 0.5 * b_.inertia(y[0]) * y[1] * y[1];
    consider_peak(t, y[0]);
    push_history(t, y);
    return EventAction::stop;
  }
  void consider_peak(double t, double q) {
    if (q > out_.theta_max) {
      out_.theta_max = q;
      out_.t_theta_max = t;
    }
  }
  void push_history(double t, const double* y) {
    if (!set_.history) return;
    out_.history.t.push_back(t);
    out_.history.theta.push_back(y[0]);
    out_.history.omega.push_back(y[1]);
  }

  Body b_;
  const std::vector<Level>& lv_;
  const GroundMotion& motion_;
  double q_c_;
  const Works& works_;
  Settings set_;
  RockingResult& out_;
  CollapseOf collapse_of_;
  std::vector<char> broken_;
  bool decayed_ = false;
  AnalysisEnd why_ = AnalysisEnd::free_motion_cap;
};

// Net restoring force with every level at its capacity (the levels not
// broken, when `broken` is given).
double envelope(const Body& body, const std::vector<Level>& lv, double q, const std::vector<char>* broken = nullptr) {
  double r = body.restoring(q);
  for (std::size_t i = 0; i < lv.size(); ++i)
    if (!broken || !(*broken)[i]) r += lv[i].cap * lv[i].de(q);
  return r;
}

// Collapse coordinate: the first zero, after the peak, of the net restoring
// force with every level at its capacity; `q_end` if there is none before it.
double collapse_coordinate(const Body& body, const std::vector<Level>& lv, double q_end,
                           const std::vector<char>* broken = nullptr) {
  auto net = [&](double q) { return envelope(body, lv, q, broken); };
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

Works works_of(const Body& body, const std::vector<Level>& lv, double q_c) {
  const int n = 4000;
  Works w;
  w.h = q_c / n;
  w.cap.assign(n + 1, 0.0);
  w.lb.assign(n + 1, 0.0);
  auto lb = [&](double q) {
    double r = body.restoring(q);
    for (const Level& L : lv) r -= L.cap * std::max(0.0, -L.de(q));
    return r;
  };
  double c0 = envelope(body, lv, 0.0), l0 = lb(0.0);
  for (int k = 1; k <= n; ++k) {
    const double q = k * w.h, c1 = envelope(body, lv, q), l1 = lb(q);
    w.cap[k] = w.cap[k - 1] + 0.5 * w.h * (c0 + c1);
    w.lb[k] = w.lb[k - 1] + 0.5 * w.h * (l0 + l1);
    c0 = c1;
    l0 = l1;
  }
  return w;
}

void check_levels(const std::vector<Level>& lv) {
  if (lv.empty() || lv.size() > 16) throw InputError("tied rocking: expected 1 to 16 tie levels");
}

// The collapse coordinate of the levels left intact, on [0, q_end].
CollapseOf collapse_of(const Body& body, const std::vector<Level>& lv, double q_end) {
  return [&body, &lv, q_end](const std::vector<char>& broken) { return collapse_coordinate(body, lv, q_end, &broken); };
}

// Verification form: from rest to t_end under ug, no early end.
TiedRockingResult integrate_fixed(const Body& body, const std::vector<Level>& lv, double q_c, double q_end,
                                  const std::vector<double>& ug, double dt, double t_end,
                                  const HybridOdeOptions& options) {
  if (!(dt > 0.0) || ug.size() < 2) throw InputError("tied rocking: expected >= 2 samples and dt > 0 s");
  check_levels(lv);
  Record rec;
  rec.dt = dt;
  rec.acc = ug;
  const GroundMotion motion = GroundMotion::from_record(rec);
  const Works works = works_of(body, lv, q_c);
  RockingResult r;
  TiedSystem sys(body, lv, motion, q_c, works, Settings{}, r, collapse_of(body, lv, q_end));
  std::vector<double> y(2 + lv.size(), 0.0);
  const double t1 = std::min(t_end, rec.duration());
  const HybridOdeResult h = integrate_hybrid(sys, 0.0, t1, y.data(), kRest, options);
  TiedRockingResult R;
  R.termination = h.termination;
  R.t_end = h.t;
  R.theta_max = r.theta_max;
  R.theta_collapse = q_c;
  R.overturned = r.overturned;
  R.impacts = r.impacts;
  R.levels = r.ties;
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

// Front-end form: the record as in `options`, to its last sample, then free
// motion with the end rule; the result as the untied analyses give theirs.
RockingResult integrate_record(const Body& body, const std::vector<Level>& lv, double q_c, double q_end,
                               const Record& record, const RockingOptions& options, double restitution) {
  options.validate();
  if (options.overturn != OverturnCriterion::theta_u)
    throw InputError("tied rocking: overturn_at: a tied wall collapses where its net restoring moment with the ties "
                     "at their strength vanishes; \"half_pi\" is not available with ties");
  check_levels(lv);
  const GroundMotion motion = GroundMotion::from_record(record, options.scale, options.reverse);
  const Works works = works_of(body, lv, q_c);
  RockingResult r;
  Settings set;
  set.end_rule = true;
  set.rest_velocity = options.rest_velocity;
  set.history = options.record_history;
  TiedSystem sys(body, lv, motion, q_c, works, set, r, collapse_of(body, lv, q_end));
  std::vector<double> y(2 + lv.size(), 0.0);
  HybridOdeOptions ho = detail::hybrid_options(options, motion);
  const HybridOdeResult h = integrate_hybrid(sys, 0.0, motion.duration() + options.tail_s, y.data(), kRest, ho);
  detail::take_integration(h, r);
  for (std::size_t i = 0; i < lv.size(); ++i) {
    r.ties[i].plastic_elongation = y[2 + i];
    r.ties[i].plastic_energy = lv[i].cap * y[2 + i];
  }
  r.theta_u = q_c;
  r.theta_max_side = +1;
  r.restitution = restitution;
  r.motion_duration = motion.duration();
  r.capacity = Works::at(works.cap, works.h, q_c);
  r.energy_demand = r.overturned ? r.capacity + r.kinetic_energy_overturn
                                 : Works::at(works.cap, works.h, std::min(r.theta_max, q_c));
  r.dc = r.capacity > 0.0 ? r.energy_demand / r.capacity : std::numeric_limits<double>::infinity();
  const double q_stop = std::max(q_c, sys.collapse());  // a broken level moves the collapse rotation
  if (succeeded(r) && !(std::isfinite(r.theta_max) && std::isfinite(r.dc) && r.theta_max <= q_stop * (1.0 + 1e-9))) {
    r.termination = RockingTermination::integrator_error;
    r.message = "the tied analysis gave a peak rotation or an energy that cannot be true";
  }
  r.end = detail::analysis_end(r, h, sys.why());
  return r;
}

// The rocking model with its ties: the body, the levels and the collapse rotation.
struct Tied {
  Body body;
  std::vector<Level> levels;
  double q_c = 0.0;
  double q_end = 0.0;  // the last coordinate of the tables (the collapse search's range)
};

Tied tied_body(const RockingModel& model, const std::vector<RockingTie>& ties) {
  if (model.sidedness() != Sidedness::one_sided)
    throw InputError("tied rocking: the model must be one-sided (a façade against its transverse walls)");
  Tied T;
  for (const RockingTie& t : ties) {
    t.validate();
    Level L;
    L.k = t.stiffness;
    L.cap = t.capacity;
    L.P0 = t.pretension;
    L.brittle = !t.ductile;
    L.e_u = t.ultimate_elongation;
    L.e = [t](double q) { return t.elongation(q); };
    L.de = [t](double q) { return t.delongation(q); };
    T.levels.push_back(L);
  }
  check_levels(T.levels);
  Body& b = T.body;
  b.acc = [&model](double q, double, double u) { return model.angular_acceleration(q, +1, q > model.theta_cr(), u); };
  const double I0 = model.body().I0;
  b.inertia = [I0](double) { return I0; };
  b.lift = [&model](double u) { return model.lift_margin(+1, u); };
  b.impact = [&model](double w) { return model.impact(w); };
  b.restoring = [&model](double q) {
    return model.restoring_moment(q, +1, q > model.theta_cr()) - model.body().M_ext;
  };
  T.q_end = 1.5707;
  T.q_c = collapse_coordinate(b, T.levels, T.q_end);
  return T;
}

Tied tied_chain(const ChainDynamics& chain, const std::vector<TieRestraint>& ties, double e) {
  if (!(e >= -1.0 && e <= 0.0)) throw InputError("tied chain: one-sided restitution must be in [-1, 0]");
  const double q_end = chain.grid_step() * double(chain.grid_intervals());
  const int n = 2000;
  Tied T;
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
    L.brittle = !tie.ductile;
    L.e_u = tie.ultimate_elongation;
    L.e = [tab](double q) { return tab->elong(q); };
    L.de = [tab](double q) { return tab->delong(q); };
    T.levels.push_back(L);
  }
  check_levels(T.levels);
  Body& b = T.body;
  b.acc = [&chain](double q, double qd, double u) { return chain.acceleration(q, qd, q > chain.q_cr(), u, +1); };
  b.inertia = [&chain](double q) { return chain.mass(q); };
  b.lift = [&chain](double u) { return chain.rest_force(u, +1) / chain.mass(0.0); };
  b.impact = [e](double w) { return e * w; };
  b.restoring = [&chain](double q) { return chain.net_restoring(q); };
  // The chain's tables end a little beyond its bare q_u: beyond them the
  // tied chain is stopped (counted as overturned), docs/theory/ties.md §6.
  T.q_end = q_end;
  T.q_c = collapse_coordinate(b, T.levels, q_end);
  return T;
}

TiedEnvelope envelope_of(const Tied& T, int n) {
  TiedEnvelope E;
  E.theta_collapse = T.q_c;
  E.capacity = Works::at(works_of(T.body, T.levels, T.q_c).cap, T.q_c / 4000, T.q_c);
  for (int k = 0; k <= n; ++k) {
    const double q = T.q_c * k / n;
    E.theta.push_back(q);
    E.restoring.push_back(envelope(T.body, T.levels, q));
  }
  return E;
}

}  // namespace

TiedEnvelope tied_envelope(const RockingModel& model, const std::vector<RockingTie>& ties, int n) {
  return envelope_of(tied_body(model, ties), n);
}

TiedEnvelope tied_envelope(const ChainDynamics& chain, const std::vector<TieRestraint>& ties, int n) {
  return envelope_of(tied_chain(chain, ties, 0.0), n);
}

TiedRockingResult analyse_tied_rocking(const RockingModel& model, const RockingTie& tie, const std::vector<double>& ug,
                                       double dt, double t_end, const HybridOdeOptions& options) {
  return analyse_tied_rocking(model, std::vector<RockingTie>{tie}, ug, dt, t_end, options);
}

TiedRockingResult analyse_tied_rocking(const RockingModel& model, const std::vector<RockingTie>& ties,
                                       const std::vector<double>& ug, double dt, double t_end,
                                       const HybridOdeOptions& options) {
  const Tied T = tied_body(model, ties);
  return integrate_fixed(T.body, T.levels, T.q_c, T.q_end, ug, dt, t_end, options);
}

TiedRockingResult analyse_tied_chain(const ChainDynamics& chain, const TieRestraint& tie, double e,
                                     const std::vector<double>& ug, double dt, double t_end,
                                     const HybridOdeOptions& options) {
  return analyse_tied_chain(chain, std::vector<TieRestraint>{tie}, e, ug, dt, t_end, options);
}

TiedRockingResult analyse_tied_chain(const ChainDynamics& chain, const std::vector<TieRestraint>& ties, double e,
                                     const std::vector<double>& ug, double dt, double t_end,
                                     const HybridOdeOptions& options) {
  const Tied T = tied_chain(chain, ties, e);
  return integrate_fixed(T.body, T.levels, T.q_c, T.q_end, ug, dt, t_end, options);
}

RockingResult analyse_tied(const RockingModel& model, const std::vector<RockingTie>& ties, const Record& record,
                           const RockingOptions& options) {
  const Tied T = tied_body(model, ties);
  RockingResult r = integrate_record(T.body, T.levels, T.q_c, T.q_end, record, options,
                                     model.restitution());
  r.alpha = model.body().alpha;
  if (!model.foundation().is_rigid()) r.theta_cr = model.theta_cr();
  return r;
}

RockingResult analyse_tied(const ChainDynamics& chain, const std::vector<TieRestraint>& ties, double e,
                           const Record& record, const RockingOptions& options) {
  const Tied T = tied_chain(chain, ties, e);
  return integrate_record(T.body, T.levels, T.q_c, T.q_end, record, options, e);
}

}  // namespace assess
