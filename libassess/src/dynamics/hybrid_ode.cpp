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
//   best_h, yb      earliest fired end of an event bracket so far, its state
//   yk              state of the last re-step that fell on the fired side
//
// Event location: a step across which some g_k changes sign in its direction
// is re-taken from its saved start with gsl_odeiv2_step_apply and step sizes
// hh that narrow a bracket on hh until it is narrower than event_time_tol.
// The first hh are guesses from the cubic Hermite interpolant of the step:
// its root, a Newton step from there with the real g_k and the interpolant's
// slope, then the two ends of a bracket narrower than event_time_tol around
// it, each checked by a real re-step; an Illinois/bisection search
// (bracket_root.hpp) finishes, or does all the work when a guess misses. The
// state at the fired end of the bracket, kept from its re-step, is handed to
// the system's jump map, then the stepper is reset (GSL manual: step_reset
// "should be used whenever the next use of s will not be a continuation of a
// previous step"). Re-stepping is valid for one-step Runge-Kutta methods
// only, which is why only explicit RK steppers are offered (research notes
// rocking.md §3.1).
#include "assess/dynamics/hybrid_ode.hpp"

#include "assess/support/error.hpp"
#include "support/bracket_root.hpp"

#include <gsl/gsl_errno.h>
#include <gsl/gsl_odeiv2.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <optional>
#include <mutex>
#include <vector>

namespace assess {
namespace {

struct StepDeleter {
  void operator()(gsl_odeiv2_step* p) const { gsl_odeiv2_step_free(p); }
};
struct ControlDeleter {
  void operator()(gsl_odeiv2_control* p) const { gsl_odeiv2_control_free(p); }
};

struct Adapter {
  HybridSystem* sys;
  int mode;
  long* rhs_count;
};

int gsl_rhs(double t, const double y[], double dydt[], void* params) {
  auto* a = static_cast<Adapter*>(params);
  ++*a->rhs_count;
  return a->sys->rhs(t, y, a->mode, dydt) ? GSL_SUCCESS : GSL_EBADFUNC;
}

const gsl_odeiv2_step_type* step_type(OdeStepper s) {
  switch (s) {
    case OdeStepper::rkck: return gsl_odeiv2_step_rkck;
    case OdeStepper::rkf45: return gsl_odeiv2_step_rkf45;
    case OdeStepper::rk8pd: break;
  }
  return gsl_odeiv2_step_rk8pd;
}

bool fired(EventDirection d, double g_start, double g_end) {
  return d == EventDirection::falling ? (g_start >= 0.0 && g_end < 0.0) : (g_start <= 0.0 && g_end > 0.0);
}

/// Cubic Hermite interpolant of a step of length h at s in [0, 1] from the
/// values and derivatives at both ends, per component: out = H(s).
void hermite(double h, double s, const double* y0, const double* f0, const double* y1, const double* f1,
             double* out, std::size_t n) {
  const double s2 = s * s, s3 = s2 * s;
  const double c_y0 = 2 * s3 - 3 * s2 + 1, c_f0 = (s3 - 2 * s2 + s) * h, c_y1 = 3 * s2 - 2 * s3, c_f1 = (s3 - s2) * h;
  for (std::size_t i = 0; i < n; ++i) out[i] = c_y0 * y0[i] + c_f0 * f0[i] + c_y1 * y1[i] + c_f1 * f1[i];
}

std::once_flag gsl_handler_once;

}  // namespace

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

  HybridOdeResult res;
  const std::size_t n = sys.dimension();
  std::unique_ptr<gsl_odeiv2_step, StepDeleter> step(gsl_odeiv2_step_alloc(step_type(options.stepper), n));
  std::unique_ptr<gsl_odeiv2_control, ControlDeleter> control(
      gsl_odeiv2_control_y_new(options.abs_tol, options.rel_tol));
  if (!step || !control) throw std::bad_alloc();

  Adapter adapter{&sys, mode, &res.rhs_evaluations};
  gsl_odeiv2_system gsys{gsl_rhs, nullptr, n, &adapter};

  // y0/f0: start of the step; f: dy/dt at y (first same as last: the end
  // derivative of an accepted step is the start derivative of the next).
  std::vector<double> y0(n), f0(n), f(n), ytry(n), ftry(n), yerr(n);
  std::vector<double> y1(n), f1(n), yb(n), yk(n), yh(n);  // event location
  std::vector<double> g_start, g_end;
  std::vector<EventDirection> dirs;  // directions of the events of the current mode
  auto eval_events = [&](double tt, const double* yy, std::vector<double>& g) {
    g.resize(dirs.size());
    for (std::size_t k = 0; k < g.size(); ++k) g[k] = sys.event(k, tt, yy, mode);
  };
  double t = t0;
  auto finish = [&](HybridTermination term, std::string msg) {
    res.termination = term;
    res.message = std::move(msg);
    res.t = t;
    res.mode = mode;
    return res;
  };
  auto restart = [&]() {  // after a jump: the mode's events, fresh derivative and event values
    gsl_odeiv2_step_reset(step.get());
    dirs.resize(sys.event_count(mode));
    for (std::size_t k = 0; k < dirs.size(); ++k) dirs[k] = sys.event_direction(k, mode);
    eval_events(t, y, g_start);
    return gsl_rhs(t, y, f.data(), &adapter) == GSL_SUCCESS;
  };

  // Applies the located event k at (t, y): the jump, then a stop or a limit
  // ends the integration (the result is returned), else a fresh start.
  auto fire = [&](std::size_t k) -> std::optional<HybridOdeResult> {
    ++res.events;
    const EventAction action = sys.on_event(k, t, y, mode);
    adapter.mode = mode;
    if (action == EventAction::stop) return finish(HybridTermination::stopped_by_event, "stopped by an event");
    if (res.events >= options.max_events)
      return finish(HybridTermination::event_limit, "event limit reached (accumulation of events?)");
    if (!restart())
      return finish(HybridTermination::integrator_error,
                    "right-hand side failed after an event at t = " + std::to_string(t) + " s");
    return std::nullopt;
  };

  double h = std::min(options.h_initial, std::max(t_end - t0, 0.0));
  if (!restart()) return finish(HybridTermination::integrator_error, "right-hand side failed at the start");

  // The next breakpoint after t stays valid while t has not reached it (t never decreases).
  double next_bp = -std::numeric_limits<double>::infinity();
  while (t < t_end) {
    if (!(t < next_bp)) next_bp = sys.next_breakpoint(t);
    double t_bp = std::min(next_bp, t_end);
    if (!(t_bp > t)) t_bp = t_end;
    if (t_bp - t <= 4.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(t))) {
      t = t_bp;  // a sliver left by an event at a breakpoint: nothing to integrate
      continue;
    }
    if (sys.stationary(mode)) {
      // The state does not move: advance to the breakpoint (at most h_max),
      // and locate an event in time if one fires on the way.
      const double t_prev = t;
      const double t_next = std::min(t_bp, t_prev + options.h_max);
      std::copy(y, y + n, y0.begin());
      eval_events(t_next, y, g_end);
      std::size_t k_hit = g_end.size();
      double best = t_next;
      for (std::size_t k = 0; k < g_end.size(); ++k) {
        const EventDirection dir = dirs[k];
        if (!fired(dir, g_start[k], g_end[k])) continue;
        auto g_of_t = [&](double tt) { return sys.event(k, tt, y0.data(), mode); };
        const double g_b = best == t_next ? g_end[k] : g_of_t(best);
        if (!fired(dir, g_start[k], g_b)) continue;
        const auto br = detail::shrink_bracket(g_of_t, {t_prev, g_start[k], best, g_b}, options.event_time_tol);
        if (fired(dir, g_start[k], br.fb) && br.b <= best) best = br.b, k_hit = k;
      }
      t = best;
      sys.on_step(t_prev, y0.data(), f.data(), t, y, f.data(), mode);
      if (k_hit == g_end.size()) {
        g_start.swap(g_end);
        continue;
      }
      if (auto end = fire(k_hit)) return *end;
      continue;
    }
    // One adaptive step (gsl_odeiv2_step_apply + gsl_odeiv2_control_hadjust),
    // never across the breakpoint t_bp.
    std::copy(y, y + n, y0.begin());
    std::copy(f.begin(), f.end(), f0.begin());
    const double t_prev = t;
    double h_try = std::min(h, options.h_max);
    bool final_step = false;
    for (;;) {
      if (res.steps + res.rejected_steps >= options.max_steps)
        return finish(HybridTermination::step_limit, "step limit reached");
      final_step = h_try >= t_bp - t_prev;
      if (final_step) h_try = t_bp - t_prev;
      std::copy(y0.begin(), y0.end(), ytry.begin());
      const int status = gsl_odeiv2_step_apply(step.get(), t_prev, h_try, ytry.data(), yerr.data(), f0.data(),
                                               ftry.data(), &gsys);
      if (status != GSL_SUCCESS)
        return finish(HybridTermination::integrator_error, std::string("GSL gsl_odeiv2_step_apply at t = ") +
                                                               std::to_string(t_prev) + " s: " + gsl_strerror(status));
      // A step cut at a breakpoint whose error ratio is within GSL's acceptance
      // (D_i = abs_tol + rel_tol |y_i|, max |yerr_i|/D_i <= 1.1, the rule of
      // gsl_odeiv2_control_y_new) keeps the current proposal h, so the control
      // (and its pow()) is only consulted when it can change something.
      double h_new = h_try;
      int adj = GSL_ODEIV_HADJ_NIL;
      double ratio = 0.0;
      for (std::size_t i = 0; i < n; ++i)
        ratio = std::max(ratio, std::fabs(yerr[i]) / (options.abs_tol + options.rel_tol * std::fabs(ytry[i])));
      if (!(final_step && ratio <= 1.1))
        adj = gsl_odeiv2_control_hadjust(control.get(), step.get(), ytry.data(), yerr.data(), ftry.data(), &h_new);
      if (adj == GSL_ODEIV_HADJ_DEC) {
        ++res.rejected_steps;
        if (!(h_new > 16.0 * std::numeric_limits<double>::epsilon() * std::max(1.0, std::fabs(t_prev))))
          return finish(HybridTermination::integrator_error,
                        "step size underflow at t = " + std::to_string(t_prev) + " s");
        h_try = h_new;
        continue;
      }
      h = final_step ? std::max(h, h_new) : h_new;  // a step cut at a breakpoint keeps the proposal
      break;
    }
    ++res.steps;
    t = final_step ? t_bp : t_prev + h_try;
    std::copy(ytry.begin(), ytry.end(), y);

    eval_events(t, y, g_end);
    std::size_t k_hit = g_end.size();
    for (std::size_t k = 0; k < g_end.size(); ++k)
      if (fired(dirs[k], g_start[k], g_end[k])) {
        k_hit = k;
        break;
      }
    if (k_hit == g_end.size()) {
      sys.on_step(t_prev, y0.data(), f0.data(), t, y, ftry.data(), mode);
      g_start.swap(g_end);
      f.swap(ftry);
      continue;
    }

    // Locate the earliest of the fired events by re-stepping from (t_prev, y0).
    // The end of the step (y, ftry) stays in y1, f1 for the dense interpolant.
    std::copy(y, y + n, y1.begin());
    f1.swap(ftry);
    const double h_step = t - t_prev;
    bool step_failed = false;
    double best_h = h_step;                       // earliest fired end so far
    std::copy(y1.begin(), y1.end(), yb.begin());  // the state there
    for (std::size_t k = k_hit; k < g_end.size(); ++k) {
      const EventDirection dir = dirs[k];
      if (!fired(dir, g_start[k], g_end[k])) continue;
      auto g_of_h = [&](double hh) {  // g_k after a real GSL step hh from (t_prev, y0)
        std::copy(y0.begin(), y0.end(), ytry.begin());
        ++res.event_steps;
        if (gsl_odeiv2_step_apply(step.get(), t_prev, hh, ytry.data(), yerr.data(), f0.data(), nullptr, &gsys) !=
            GSL_SUCCESS)
          step_failed = true;
        const double g = sys.event(k, t_prev + hh, ytry.data(), mode);
        if (fired(dir, g_start[k], g)) std::copy(ytry.begin(), ytry.end(), yk.begin());  // a new bracket end b
        return g;
      };
      auto g_dense = [&](double hh) {  // g_k on the cubic Hermite interpolant of the step
        hermite(h_step, hh / h_step, y0.data(), f0.data(), y1.data(), f1.data(), yh.data(), n);
        return sys.event(k, t_prev + hh, yh.data(), mode);
      };
      const double g_b = best_h == h_step ? g_end[k] : g_of_h(best_h);
      if (!fired(dir, g_start[k], g_b)) continue;  // fires only after an earlier event
      detail::Bracket br{0.0, g_start[k], best_h, g_b};
      auto narrow = [&](double hh) {  // a real step to hh inside the bracket narrows it
        if (!(hh > br.a && hh < br.b)) return;
        const double g = g_of_h(hh);
        if (fired(dir, g_start[k], g)) br.b = hh, br.fb = g; else br.a = hh, br.fa = g;
      };
      // Guesses from the dense output, each checked by a real step: the root
      // c1 of the interpolant; a Newton step from c1 with the real g_k(c1)
      // and the interpolant's slope (central difference over 2e-6 of the
      // step); then both ends of a bracket 0.8 event_time_tol wide around it.
      // The bracketing search finishes, or does all the work when a guess misses.
      const double gd_b = g_dense(br.b);
      if (fired(dir, g_start[k], gd_b)) {
        const double c1 =
            detail::shrink_bracket(g_dense, {0.0, g_start[k], br.b, gd_b}, 1e-3 * options.event_time_tol).b;
        narrow(c1);
        if (c1 == br.a || c1 == br.b) {
          const double d = 1e-6 * h_step;
          const double slope = (g_dense(c1 + d) - g_dense(c1 - d)) / (2.0 * d);
          const double c2 = c1 - (c1 == br.a ? br.fa : br.fb) / slope;
          narrow(c2 - 0.4 * options.event_time_tol);
          narrow(c2 + 0.4 * options.event_time_tol);
        }
      }
      br = detail::shrink_bracket(g_of_h, br, options.event_time_tol);
      if (!step_failed && fired(dir, g_start[k], br.fb) && br.b <= best_h) {
        if (br.b < best_h) std::copy(yk.begin(), yk.end(), yb.begin());  // br.b was the last fired re-step
        best_h = br.b;
        k_hit = k;
      }
    }
    if (step_failed) {
      t = t_prev;
      std::copy(y0.begin(), y0.end(), y);
      return finish(HybridTermination::integrator_error, "GSL step failed while locating an event");
    }
    // The state at the fired end of the bracket, from a real GSL step, with
    // its derivative (the same evaluation as GSL's dydt_out) for on_step.
    t = t_prev + best_h;
    std::copy(yb.begin(), yb.end(), y);
    if (best_h == h_step) {
      ftry.swap(f1);
    } else if (gsl_rhs(t, y, ftry.data(), &adapter) != GSL_SUCCESS) {
      return finish(HybridTermination::integrator_error, "right-hand side failed while locating an event");
    }
    sys.on_step(t_prev, y0.data(), f0.data(), t, y, ftry.data(), mode);

    if (auto end = fire(k_hit)) return *end;
  }
  return finish(HybridTermination::completed, "");
}

}  // namespace assess
