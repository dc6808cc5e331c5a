// hybrid_ode.cpp: event-driven integration of hybrid systems with GSL
// gsl_odeiv2 steppers and step-size control (gsl_odeiv2_step_apply +
// gsl_odeiv2_control_hadjust; the evolve loop is written out here so that the
// end derivative of an accepted step is reused as the start derivative of the
// next, first-same-as-last, and the step start is at hand for event location).
//
// Notation:
//   t_prev, y0, f0  start of the current step: time (s), state, dy/dt
//   t, y, ftry      end of the step (ftry becomes f, the next start derivative)
//   g_start, g_end  event functions at the start and at the end of the step
//   hh              trial step size while locating an event from (t_prev, y0)
//   y1, f1          end of a step in which an event fired (for the interpolant)
//   best_h, yb      earliest fired end of an event so far, its state
//   yk              state of the last re-step that fell on the fired side
//
// Step: gsl_odeiv2_step_apply to the next breakpoint (a record sample) or the
// control's proposal if shorter; the control (and its pow()) is consulted
// only when the error estimate binds, so on a record with a tolerance the
// samples already satisfy, every step is one step_apply per sample.
//
// Right-hand side: the system's kernel (HybridSystem::rhs_kernel), a plain
// function called by GSL directly with the time measured from the kernel's
// origin, or, without a kernel, an adapter to the virtual rhs().
//
// Event location: a step across which some g_k changes sign in its direction
// is re-taken from its saved start with gsl_odeiv2_step_apply. The first
// re-step size is the root of g_k on the system's dense output
// (HybridSystem::interpolate); from each real value g_k(hh) a Newton step with
// the dense output's slope estimates the root r. A re-step on the fired side
// with hh - r in [0, event_time_tol / 2] is accepted: Newton's estimate from
// a point that close is exact far below event_time_tol (the error is the
// slope's relative error times hh - r, plus a curvature term of order
// (hh - r)^2), so the event time is known to within event_time_tol as with a
// bracket. Otherwise the next re-step aims at r + event_time_tol / 4 (the
// fired side); after two Newton re-steps an Illinois/bisection search
// (bracket_root.hpp) narrows the bracket below event_time_tol. The state at
// the accepted fired re-step is handed to the system's jump map, then the
// stepper is reset (GSL manual: step_reset "should be used whenever the next
// use of s will not be a continuation of a previous step"). Re-stepping is
// valid for one-step Runge-Kutta methods only, which is why only explicit RK
// steppers are offered (research notes rocking.md §3.1).
#include "assess/dynamics/hybrid_ode.hpp"

#include "assess/support/error.hpp"
#include "support/bracket_root.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <mutex>
#include <optional>
#include <vector>

namespace assess {
namespace {

struct StepDeleter {
  void operator()(gsl_odeiv2_step* p) const { gsl_odeiv2_step_free(p); }
};
struct ControlDeleter {
  void operator()(gsl_odeiv2_control* p) const { gsl_odeiv2_control_free(p); }
};

/// The generic path: GSL calls the system's virtual rhs() through this adapter.
struct Adapter {
  HybridSystem* sys;
  int mode;
  double origin;  // s: GSL's time is t - origin, as for a kernel
};

int gsl_rhs(double t, const double y[], double dydt[], void* params) {
  auto* a = static_cast<Adapter*>(params);
  return a->sys->rhs(t + a->origin, y, a->mode, dydt) ? GSL_SUCCESS : GSL_EBADFUNC;
}

const gsl_odeiv2_step_type* step_type(OdeStepper s) {
  switch (s) {
    case OdeStepper::rkck: return gsl_odeiv2_step_rkck;
    case OdeStepper::rkf45: return gsl_odeiv2_step_rkf45;
    case OdeStepper::rk8pd: break;
  }
  return gsl_odeiv2_step_rk8pd;
}

/// Right-hand-side evaluations of one gsl_odeiv2_step_apply given dy/dt at the
/// start (GSL's rk8pd has 13 stages, rkck and rkf45 6; the first is dydt_in),
/// plus one for dydt_out if asked.
long evaluations_per_step(OdeStepper s, bool dydt_out) {
  const long stages = s == OdeStepper::rk8pd ? 13 : 6;
  return stages - 1 + (dydt_out ? 1 : 0);
}

/// dst[0 .. n) = src[0 .. n). The common case n = 2 (a second-order
/// equation) without a call to memmove, which std::copy of a run-time length
/// becomes and which costs more than the copy itself.
inline void copy_state(const double* src, std::size_t n, double* dst) {
  if (n == 2) {
    dst[0] = src[0], dst[1] = src[1];
    return;
  }
  std::copy(src, src + n, dst);
}

bool fired(EventDirection d, double g_start, double g_end) {
  return d == EventDirection::falling ? (g_start >= 0.0 && g_end < 0.0) : (g_start <= 0.0 && g_end > 0.0);
}

std::once_flag gsl_handler_once;

/// One integration (the state of integrate_hybrid), split into its steps:
/// run() is the loop over breakpoint intervals; each pass either advances a
/// stationary mode (advance_at_rest) or takes one adaptive step (take_step);
/// a step across which an event fired is cut back to the event
/// (locate_events, locate_one) and the jump applied (fire).
class Integration {
 public:
  Integration(HybridSystem& sys, double t0, double t_end, double* y, int mode, const HybridOdeOptions& o)
      : sys_(sys), opt_(o), n_(sys.dimension()), t_(t0), t_end_(t_end), y_(y), mode_(mode),
        step_(gsl_odeiv2_step_alloc(step_type(o.stepper), n_)),
        control_(gsl_odeiv2_control_y_new(o.abs_tol, o.rel_tol)),
        adapter_{&sys, mode, 0.0},
        gsys_{gsl_rhs, nullptr, n_, &adapter_},
        y0_(n_), f0_(n_), f_(n_), ytry_(n_), ftry_(n_), yerr_(n_), y1_(n_), f1_(n_), yb_(n_), yk_(n_),
        yh_(n_) {
    if (!step_ || !control_) throw std::bad_alloc();
  }

  HybridOdeResult run() {
    h_ = std::min(opt_.h_initial, std::max(t_end_ - t_, 0.0));
    if (!restart()) return finish(HybridTermination::integrator_error, "right-hand side failed at the start");
    if (sys_.finished(t_, y_, mode_)) return finish(HybridTermination::finished, "");
    // The next breakpoint after t stays valid while t has not reached it (t never decreases).
    double next_bp = -std::numeric_limits<double>::infinity();
    while (t_ < t_end_) {
      if (!(t_ < next_bp)) {
        use_kernel();  // a kernel may bring the breakpoint with it (RhsKernel::end)
        next_bp = std::isnan(kernel_end_) ? sys_.next_breakpoint(t_) : kernel_end_;
      }
      double t_bp = std::min(next_bp, t_end_);
      if (!(t_bp > t_)) t_bp = t_end_;
      if (t_bp - t_ <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(t_))) {
        t_ = t_bp;  // a sliver left by an event at a breakpoint: nothing to integrate
        continue;
      }
      std::optional<HybridOdeResult> end = stationary_ ? advance_at_rest(t_bp) : take_step(t_bp);
      if (end) return *end;
    }
    return finish(HybridTermination::completed, "");
  }

 private:
  HybridOdeResult finish(HybridTermination term, std::string msg) {
    res_.termination = term;
    res_.message = std::move(msg);
    res_.t = t_;
    res_.mode = mode_;
    return res_;
  }

  /// GSL's right-hand side from here to the next breakpoint in this mode:
  /// the system's kernel if it has one, else the adapter to rhs().
  void use_kernel() {
    const RhsKernel k = sys_.rhs_kernel(mode_, t_);
    kernel_end_ = k.end;
    if (k.fn) {
      gsys_.function = k.fn;
      gsys_.params = k.ctx;
      origin_ = k.origin;
    } else {
      adapter_.mode = mode_;
      gsys_.function = gsl_rhs;
      gsys_.params = &adapter_;
      origin_ = adapter_.origin = 0.0;
    }
  }

  bool eval_rhs(double t, const double* y, double* f) {
    ++res_.rhs_evaluations;
    return gsys_.function(t - origin_, y, f, gsys_.params) == GSL_SUCCESS;
  }

  /// One GSL step of size h from (t, y) in place; counts its evaluations.
  int apply(double t, double h, double* y, const double* dydt_in, double* dydt_out) {
    res_.rhs_evaluations += evaluations_per_step(opt_.stepper, dydt_out != nullptr);
    return gsl_odeiv2_step_apply(step_.get(), t - origin_, h, y, yerr_.data(), dydt_in, dydt_out, &gsys_);
  }

  void eval_events(double t, const double* y, std::vector<double>& g) {  // g sized by restart()
    if (!g.empty()) sys_.events(t, y, mode_, g.data());
  }

  /// After a jump (and at the start): the mode's events, kernel, fresh
  /// derivative and event values.
  bool restart() {
    gsl_odeiv2_step_reset(step_.get());
    dirs_.resize(sys_.event_count(mode_));
    for (std::size_t k = 0; k < dirs_.size(); ++k) dirs_[k] = sys_.event_direction(k, mode_);
    g_start_.resize(dirs_.size());
    g_end_.resize(dirs_.size());
    stationary_ = sys_.stationary(mode_);
    use_kernel();
    eval_events(t_, y_, g_start_);
    return eval_rhs(t_, y_, f_.data()) && std::all_of(f_.begin(), f_.end(), [](double v) { return std::isfinite(v); });
  }

  /// Applies the located event k at (t, y): the jump, then a stop or a limit
  /// ends the integration (the result is returned), else a fresh start.
  std::optional<HybridOdeResult> fire(std::size_t k) {
    ++res_.events;
    const EventAction action = sys_.on_event(k, t_, y_, mode_);
    if (action == EventAction::stop) return finish(HybridTermination::stopped_by_event, "stopped by an event");
    if (res_.events >= opt_.max_events)
      return finish(HybridTermination::event_limit, "event limit reached: " + std::to_string(res_.events) +
                                                        " events by t = " + std::to_string(t_) + " s");
    if (!restart())
      return finish(HybridTermination::integrator_error,
                    "right-hand side failed after an event at t = " + std::to_string(t_) + " s");
    if (sys_.finished(t_, y_, mode_)) return finish(HybridTermination::finished, "");
    return std::nullopt;
  }

  /// A stationary mode: the state does not move. Advance to the breakpoint
  /// (at most h_max), and locate an event in time if one fires on the way.
  std::optional<HybridOdeResult> advance_at_rest(double t_bp) {
    const double t_prev = t_;
    const double t_next = std::min(t_bp, t_prev + opt_.h_max);
    copy_state(y_, n_, y0_.data());
    eval_events(t_next, y_, g_end_);
    std::size_t k_hit = g_end_.size();
    double best = t_next;
    for (std::size_t k = 0; k < g_end_.size(); ++k) {
      const EventDirection dir = dirs_[k];
      if (!fired(dir, g_start_[k], g_end_[k])) continue;
      auto g_of_t = [&](double tt) { return sys_.event(k, tt, y0_.data(), mode_); };
      const double g_b = best == t_next ? g_end_[k] : g_of_t(best);
      if (!fired(dir, g_start_[k], g_b)) continue;
      const auto br = detail::shrink_bracket(g_of_t, {t_prev, g_start_[k], best, g_b}, opt_.event_time_tol);
      if (fired(dir, g_start_[k], br.fb) && br.b <= best) best = br.b, k_hit = k;
    }
    t_ = best;
    sys_.on_step(t_prev, y0_.data(), f_.data(), t_, y_, f_.data(), mode_);
    if (k_hit == g_end_.size()) {
      g_start_.swap(g_end_);
      if (sys_.finished(t_, y_, mode_)) return finish(HybridTermination::finished, "");
      return std::nullopt;
    }
    return fire(k_hit);
  }

  /// One adaptive step from (t, y) never across t_bp; then either the
  /// step is accepted as is, or an event that fired in it is located.
  std::optional<HybridOdeResult> take_step(double t_bp) {
    copy_state(y_, n_, y0_.data());
    copy_state(f_.data(), n_, f0_.data());
    const double t_prev = t_;
    double h_try = std::min(h_, opt_.h_max);
    bool final_step = false;
    for (;;) {
      if (res_.steps + res_.rejected_steps >= opt_.max_steps)
        return finish(HybridTermination::step_limit, "step limit reached");
      final_step = h_try >= t_bp - t_prev;
      if (final_step) h_try = t_bp - t_prev;
      copy_state(y0_.data(), n_, ytry_.data());
      const int status = apply(t_prev, h_try, ytry_.data(), f0_.data(), ftry_.data());
      if (status != GSL_SUCCESS)
        return finish(HybridTermination::integrator_error, std::string("GSL gsl_odeiv2_step_apply at t = ") +
                                                               std::to_string(t_prev) + " s: " + gsl_strerror(status));
      if (!finite_end())
        return finish(HybridTermination::integrator_error,
                      "non-finite state or derivative after the step from t = " + std::to_string(t_prev) + " s");
      if (accept(final_step, h_try)) break;
      if (!(h_try > 16.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(t_prev))))
        return finish(HybridTermination::integrator_error,
                      "step size underflow at t = " + std::to_string(t_prev) + " s");
    }
    ++res_.steps;
    t_ = final_step ? t_bp : t_prev + h_try;
    copy_state(ytry_.data(), n_, y_);

    eval_events(t_, y_, g_end_);
    std::size_t k_hit = 0;
    while (k_hit < g_end_.size() && !fired(dirs_[k_hit], g_start_[k_hit], g_end_[k_hit])) ++k_hit;
    if (k_hit == g_end_.size()) {
      sys_.on_step(t_prev, y0_.data(), f0_.data(), t_, y_, ftry_.data(), mode_);
      g_start_.swap(g_end_);
      f_.swap(ftry_);
      return std::nullopt;
    }
    return locate_events(t_prev, k_hit);
  }

  bool finite_end() const {
    for (std::size_t i = 0; i < n_; ++i)
      if (!(std::isfinite(ytry_[i]) && std::isfinite(ftry_[i]))) return false;
    return true;
  }

  /// The error control on a step of h_try: true to accept; false with
  /// h_try set to the smaller retry. A step cut at a breakpoint whose error
  /// ratio is within GSL's acceptance (D_i = abs_tol + rel_tol |y_i|,
  /// max |yerr_i|/D_i <= 1.1, the rule of gsl_odeiv2_control_y_new) keeps the
  /// current proposal h, so the control (and its pow()) is only consulted when
  /// it can change something.
  bool accept(bool final_step, double& h_try) {
    double h_new = h_try;
    int adj = GSL_ODEIV_HADJ_NIL;
    double ratio = 0.0;
    for (std::size_t i = 0; i < n_; ++i)
      ratio = std::max(ratio, std::fabs(yerr_[i]) / (opt_.abs_tol + opt_.rel_tol * std::fabs(ytry_[i])));
    if (!(final_step && ratio <= 1.1))
      adj = gsl_odeiv2_control_hadjust(control_.get(), step_.get(), ytry_.data(), yerr_.data(), ftry_.data(), &h_new);
    if (adj == GSL_ODEIV_HADJ_DEC) {
      ++res_.rejected_steps;
      h_try = h_new;
      return false;
    }
    h_ = final_step ? std::max(h_, h_new) : h_new;  // a step cut at a breakpoint keeps the proposal
    return true;
  }

  /// The step from (t_prev, y0, f0) to (t, y, ftry) fired event k_hit (and
  /// maybe later ones): cut it back to the earliest located event, report
  /// the shortened step and apply the jump.
  std::optional<HybridOdeResult> locate_events(double t_prev, std::size_t k_hit) {
    // The end of the step (y, ftry) stays in y1, f1 for the dense output.
    copy_state(y_, n_, y1_.data());
    f1_.swap(ftry_);
    const double h_step = t_ - t_prev;
    step_failed_ = false;
    double best_h = h_step;                         // earliest fired end so far
    copy_state(y1_.data(), n_, yb_.data());  // the state there
    for (std::size_t k = k_hit; k < g_end_.size(); ++k) {
      if (!fired(dirs_[k], g_start_[k], g_end_[k])) continue;
      if (locate_one(k, t_prev, h_step, best_h)) k_hit = k;
    }
    if (step_failed_) {
      t_ = t_prev;
      copy_state(y0_.data(), n_, y_);
      return finish(HybridTermination::integrator_error, "GSL step failed while locating an event");
    }
    // The state at the fired end, from a real GSL step, with its derivative
    // (the same evaluation as GSL's dydt_out) for on_step.
    t_ = t_prev + best_h;
    copy_state(yb_.data(), n_, y_);
    if (best_h == h_step) {
      ftry_.swap(f1_);
    } else if (!eval_rhs(t_, y_, ftry_.data())) {
      return finish(HybridTermination::integrator_error, "right-hand side failed while locating an event");
    }
    sys_.on_step(t_prev, y0_.data(), f0_.data(), t_, y_, ftry_.data(), mode_);
    return fire(k_hit);
  }

  /// Locates event k in the step of length h_step from t_prev if it fires
  /// before best_h; then updates best_h and its state yb and returns true.
  bool locate_one(std::size_t k, double t_prev, double h_step, double& best_h) {
    const EventDirection dir = dirs_[k];
    const double tol = opt_.event_time_tol;
    auto is_fired = [&](double g) { return fired(dir, g_start_[k], g); };
    auto g_of_h = [&](double hh) {  // g_k after a real GSL step hh from (t_prev, y0)
      copy_state(y0_.data(), n_, ytry_.data());
      ++res_.event_steps;
      if (apply(t_prev, hh, ytry_.data(), f0_.data(), nullptr) != GSL_SUCCESS) step_failed_ = true;
      const double g = sys_.event(k, t_prev + hh, ytry_.data(), mode_);
      if (is_fired(g)) copy_state(ytry_.data(), n_, yk_.data());  // a new fired end
      return g;
    };
    auto g_dense = [&](double hh) {  // g_k on the dense output of the step
      sys_.interpolate(t_prev, y0_.data(), f0_.data(), t_prev + h_step, y1_.data(), f1_.data(), mode_,
                       hh / h_step, yh_.data());
      return sys_.event(k, t_prev + hh, yh_.data(), mode_);
    };
    const double g_b = best_h == h_step ? g_end_[k] : g_of_h(best_h);
    if (!is_fired(g_b)) return false;  // fires only after an earlier event
    detail::Bracket br{0.0, g_start_[k], best_h, g_b};
    bool fired_last = false;  // the last real re-step fell on the fired side (its state is in yk)
    auto narrow = [&](double hh) {  // a real step to hh inside the bracket narrows it; g or NaN
      if (!(hh > br.a && hh < br.b)) return std::numeric_limits<double>::quiet_NaN();
      const double g = g_of_h(hh);
      fired_last = is_fired(g);
      if (fired_last) br.b = hh, br.fb = g; else br.a = hh, br.fa = g;
      return g;
    };
    bool located = false;
    const double gd_b = g_dense(br.b);
    if (is_fired(gd_b)) {
      // Guess: the root of the dense output; then up to two Newton re-steps.
      double c = detail::shrink_bracket(g_dense, {0.0, g_start_[k], br.b, gd_b}, 1e-3 * tol).b;
      for (int newton = 0; newton < 2 && !located; ++newton) {
        const double g = narrow(c);
        if (!std::isfinite(g)) break;  // the guess fell outside the bracket
        const double d = 1e-6 * h_step;
        const double slope = (g_dense(c + d) - g_dense(c - d)) / (2.0 * d);
        const bool slope_ok = dir == EventDirection::falling ? slope < 0.0 : slope > 0.0;
        if (!slope_ok) break;
        const double r = c - g / slope;  // Newton's root estimate
        if (fired_last && c - r >= 0.0 && c - r <= 0.5 * tol) located = true;
        c = r + 0.25 * tol;  // next: just past the root, on the fired side
      }
    }
    if (!located) br = detail::shrink_bracket(g_of_h, br, tol);
    if (step_failed_ || !is_fired(br.fb) || br.b > best_h) return false;
    // br.b is the last fired re-step whenever it moved (its state is in yk).
    if (br.b < best_h) copy_state(yk_.data(), n_, yb_.data());
    best_h = br.b;
    return true;
  }

  HybridSystem& sys_;
  const HybridOdeOptions& opt_;
  const std::size_t n_;
  double t_, t_end_;
  double* y_;
  int mode_;
  double h_ = 0.0;  // the control's step proposal (s)
  std::unique_ptr<gsl_odeiv2_step, StepDeleter> step_;
  std::unique_ptr<gsl_odeiv2_control, ControlDeleter> control_;
  Adapter adapter_;
  gsl_odeiv2_system gsys_;
  double origin_ = 0.0;  // s: GSL's time is t - origin
  double kernel_end_ = std::numeric_limits<double>::quiet_NaN();  // s: RhsKernel::end of the last kernel
  HybridOdeResult res_;
  bool step_failed_ = false;
  bool stationary_ = false;  // sys.stationary(mode), read once per mode
  // y0/f0: start of the step; f: dy/dt at y (first same as last: the end
  // derivative of an accepted step is the start derivative of the next).
  std::vector<double> y0_, f0_, f_, ytry_, ftry_, yerr_;
  std::vector<double> y1_, f1_, yb_, yk_, yh_;  // event location
  std::vector<double> g_start_, g_end_;
  std::vector<EventDirection> dirs_;  // directions of the events of the current mode
};

}  // namespace

void HybridSystem::events(double t, const double* y, int mode, double* g) const {
  const std::size_t n = event_count(mode);
  for (std::size_t k = 0; k < n; ++k) g[k] = event(k, t, y, mode);
}

/// Cubic Hermite interpolant of a step of length h at s in [0, 1] from the
/// values and derivatives at both ends, per component.
void HybridSystem::interpolate(double t0, const double* y0, const double* f0, double t1, const double* y1,
                               const double* f1, int /*mode*/, double s, double* out) const {
  const double h = t1 - t0;
  const double s2 = s * s, s3 = s2 * s;
  const double c_y0 = 2 * s3 - 3 * s2 + 1, c_f0 = (s3 - 2 * s2 + s) * h, c_y1 = 3 * s2 - 2 * s3, c_f1 = (s3 - s2) * h;
  for (std::size_t i = 0, n = dimension(); i < n; ++i)
    out[i] = c_y0 * y0[i] + c_f0 * f0[i] + c_y1 * y1[i] + c_f1 * f1[i];
}

void HybridOdeOptions::validate() const {
  auto positive = [](double v, const char* field) {
    if (!(std::isfinite(v) && v > 0.0)) throw InputError(std::string(field) + " must be a positive number");
  };
  positive(rel_tol, "relative tolerance rel_tol");
  positive(abs_tol, "absolute tolerance abs_tol");
  positive(event_time_tol, "event time tolerance event_time_tol (s)");
  positive(h_initial, "initial step h_initial (s)");
  if (!(h_max > 0.0)) throw InputError("largest step h_max must be positive (s)");
  if (max_steps <= 0) throw InputError("max_steps must be positive");
  if (max_events <= 0) throw InputError("max_events must be positive");
}

std::optional<OdeStepper> parse_stepper(const std::string& name) {
  if (name == "rk8pd") return OdeStepper::rk8pd;
  if (name == "rkck") return OdeStepper::rkck;
  if (name == "rkf45") return OdeStepper::rkf45;
  return std::nullopt;
}

const char* to_string(HybridTermination t) {
  switch (t) {
    case HybridTermination::completed: return "completed";
    case HybridTermination::finished: return "finished";
    case HybridTermination::stopped_by_event: return "stopped_by_event";
    case HybridTermination::step_limit: return "step_limit";
    case HybridTermination::event_limit: return "event_limit";
    case HybridTermination::integrator_error: return "integrator_error";
  }
  return "unknown";
}

HybridOdeResult integrate_hybrid(HybridSystem& sys, double t0, double t_end, double* y, int mode,
                                 const HybridOdeOptions& options) {
  std::call_once(gsl_handler_once, [] { gsl_set_error_handler_off(); });
  options.validate();
  if (!(std::isfinite(t0) && std::isfinite(t_end) && t_end >= t0))
    throw InputError("integration interval must be finite with t_end >= t0 (s)");
  return Integration(sys, t0, t_end, y, mode, options).run();
}

}  // namespace assess
