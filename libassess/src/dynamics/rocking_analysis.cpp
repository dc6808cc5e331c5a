// rocking_analysis.cpp: the rocking wall as a hybrid system (state theta,
// theta'; mode = pivot side and contact branch) integrated by
// integrate_hybrid, and the results of the seed paper (§3.2, Fig. 3).
//
// Notation (seed paper Eq. 1, research notes rocking.md §1):
//   y[0] = theta (rad), y[1] = omega = theta' (rad/s)
//   mode 0: at rest on the base; mode s*1: rocking on pivot s (rigid, or smooth
//   in full contact |theta| <= theta_cr); mode s*2: smooth, partial contact.
//   e: restitution (velocity ratio) applied at theta = 0 (rocking.md §1.2-1.3)
//   Events per mode (all "falling" unless stated):
//     rest:     lift about s = +1 (and -1 if two-sided): s theta''(0) rising through 0,
//               from RockingModel::lift_margin (static moment from the geometry:
//               exactly 0 for a centred smooth block at ug'' = 0, so a rising
//               crossing is seen from t = 0; angular_acceleration(0, ...) left
//               +1.1e-16 there and the block never left rest, docs/theory/rocking.md)
//     rocking:  impact s theta = 0; ultimate rotation theta_u - s theta;
//               pi/2 - s theta (half_pi criterion); branch switch at theta_cr.
#include "assess/dynamics/rocking_analysis.hpp"

#include "assess/dynamics/analysis_limits.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"
#include "dynamics/integration_run.hpp"
#include "dynamics/quintic.hpp"
#include "support/bracket_root.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace assess {
namespace {

enum class Ev { lift_out, lift_in, impact, theta_u, half_pi, branch };

class RockingSystem final : public HybridSystem {
 public:
  RockingSystem(const RockingModel& model, const GroundMotion& motion, const RockingOptions& opt)
      : model_(model), motion_(motion), opt_(opt), smooth_(!model.foundation().is_rigid()),
        two_sided_(model.sidedness() == Sidedness::two_sided) {
    for (int m = -2; m <= 2; ++m) {
      n_events_[m + 2] = list_events(m, kinds_[m + 2]);
      if (m != 0)
        for (std::size_t k = 0; k < n_events_[m + 2]; ++k) linear_event(kinds_[m + 2][k], m, ev_a_[m + 2][k], ev_b_[m + 2][k]);
    }
  }

  std::size_t dimension() const override { return 2; }

  // The right-hand side, seed Eq. 1: theta' = omega, omega' = theta''(theta, ug).
  // Each contact branch extends smoothly past theta_cr (the branch event cuts
  // the step there), so a step that crosses theta_cr has a smooth right-hand
  // side and its error estimate does not reject it; the full-contact formula
  // for partial-branch stages below theta_cr was measured instead (bench_rocking:
  // 106 rejected steps, 71 more steps, theta_max 4x further from the rk8pd
  // 1e-12 run) and not kept.
  bool rhs(double t, const double* y, int mode, double* dydt) const override {
    if (mode == 0) {
      dydt[0] = dydt[1] = 0.0;
      return true;
    }
    dydt[0] = y[1];
    dydt[1] = model_.angular_acceleration(y[0], mode > 0 ? 1 : -1, std::abs(mode) == 2, motion_.acc(t));
    return std::isfinite(dydt[1]);
  }

  // The same right-hand side as a kernel per pivot side S and contact
  // branch, with the record's ug'' on the current sample interval as
  // a0 + a1 tau (GroundMotion::linear_piece): one multiply-add for ug'' and
  // no virtual call per stage. A function of time (pulses) has no such form:
  // rhs() then serves.
  RhsKernel rhs_kernel(int mode, double t) override {
    GroundMotion::LinearPiece piece;
    if (mode == 0 || !motion_.linear_piece(t, piece)) return {};
    kernel_.u0 = piece.a0;
    kernel_.u1 = piece.a1;
    RhsKernel k;
    k.fn = mode == 1 ? &kernel<+1, false> : mode == -1 ? &kernel<-1, false>
         : mode == 2 ? &kernel<+1, true> : &kernel<-1, true>;
    k.ctx = &kernel_;
    k.origin = piece.origin;
    k.end = piece.end;  // = motion_.next_breakpoint(t), so the integrator need not ask
    return k;
  }

  void events(double t, const double* y, int mode, double* g) const override {
    if (mode == 0) {  // at rest: lift-off about +1 (and -1), with ug''(t) looked up once
      const double ug = motion_.acc(t);
      g[0] = model_.lift_margin(+1, ug);
      if (two_sided_) g[1] = model_.lift_margin(-1, ug);
      return;
    }
    for (std::size_t k = 0, n = n_events_[mode + 2]; k < n; ++k) g[k] = ev_a_[mode + 2][k] + ev_b_[mode + 2][k] * y[0];
  }

  // Dense output for event location: theta by the quintic Hermite interpolant
  // of theta, theta' = omega and theta'' = omega' at both ends, omega by its
  // derivative (so omega matches both ends too). At rest: the base's cubic.
  void interpolate(double t0, const double* y0, const double* f0, double t1, const double* y1, const double* f1,
                   int mode, double s, double* y) const override {
    if (mode == 0) return HybridSystem::interpolate(t0, y0, f0, t1, y1, f1, mode, s, y);
    const detail::Quintic q{y0[0], f0[0], f0[1], y1[0], f1[0], f1[1], t1 - t0};
    y[0] = q.value(s);
    y[1] = q.slope(s) / (t1 - t0);
  }

  std::size_t event_count(int mode) const override { return n_events_[mode + 2]; }
  EventDirection event_direction(std::size_t k, int mode) const override {
    const Ev e = event_kind(k, mode);
    return (e == Ev::lift_out || e == Ev::lift_in) ? EventDirection::rising : EventDirection::falling;
  }

  // In a rocking mode every event function is linear in theta, g = a + b theta
  // (coefficients per mode from linear_event, the same values to the bit as the
  // expressions written there); at rest the lift-off events depend on ug''(t).
  double event(std::size_t k, double t, const double* y, int mode) const override {
    if (mode != 0) return ev_a_[mode + 2][k] + ev_b_[mode + 2][k] * y[0];
    return model_.lift_margin(event_kind(k, mode) == Ev::lift_out ? +1 : -1, motion_.acc(t));
  }

  // The jump map: one named step per kind of event (lift-off, impact,
  // ultimate rotation, branch switch); the state after a lift-off or an impact
  // goes to the history.
  EventAction on_event(std::size_t k, double t, double* y, int& mode) override {
    switch (event_kind(k, mode)) {
      case Ev::lift_out: lift_off(+1, y, mode); break;
      case Ev::lift_in: lift_off(-1, y, mode); break;
      case Ev::impact: impact(t, y, mode); break;
      case Ev::theta_u: return reach_theta_u(t, y);
      case Ev::half_pi: return overturn(t);
      case Ev::branch: switch_branch(mode); return EventAction::proceed;
    }
    push_history(t, y);
    return EventAction::proceed;
  }

  void on_step(double t0, const double* y0, const double* f0, double t1, const double* y1, const double* f1,
               int) override {
    consider_peak(t0, y0[0]);
    consider_peak(t1, y1[0]);
    double tp, qp;  // theta' changes sign: an extremum inside the step
    if (detail::extremum_in_step(t0, y0, f0, t1, y1, f1, tp, qp)) consider_peak(tp, qp);
    push_history(t1, y1);
  }

  double next_breakpoint(double t) const override { return motion_.next_breakpoint(t); }
  bool stationary(int mode) const override { return mode == 0; }  // at rest on the base

  // The end rule (analysis_end.hpp): at rest for good, or the energy after
  // an impact in the free motion cannot reach the peak again.
  bool finished(double t, const double*, int mode) override {
    if (mode == 0) {
      auto lifts = [this](double ug) { return model_.lifts(+1, ug) || (two_sided_ && model_.lifts(-1, ug)); };
      return detail::rests_for_good(motion_, t, lifts, why_);
    }
    return decayed_;
  }
  AnalysisEnd why() const { return why_; }

  void push_history(double t, const double* y) {
    if (!opt_.record_history) return;
    res_.history.t.push_back(t);
    res_.history.theta.push_back(y[0]);
    res_.history.omega.push_back(y[1]);
  }

  RockingResult& result() { return res_; }
  long impacts() const { return impacts_; }
  double ke_theta_u() const { return ke_theta_u_; }

 private:
  // Events active in a mode, in a fixed order; returns their number and, if
  // out != nullptr, writes the kinds.
  std::size_t list_events(int mode, Ev* out) const {
    std::size_t n = 0;
    auto add = [&](Ev e) {
      if (out) out[n] = e;
      ++n;
    };
    if (mode == 0) {
      add(Ev::lift_out);
      if (two_sided_) add(Ev::lift_in);
      return n;
    }
    add(Ev::impact);
    add(Ev::theta_u);
    if (opt_.overturn == OverturnCriterion::half_pi) add(Ev::half_pi);
    if (smooth_) add(Ev::branch);
    return n;
  }
  Ev event_kind(std::size_t k, int mode) const { return kinds_[mode + 2][k]; }

  // Event function of kind e in rocking mode m (pivot s) as a + b theta:
  //   impact s theta; ultimate rotation theta_u(s) - s theta; pi/2 - s theta;
  //   branch switch theta_cr - s theta (full contact) or s theta - theta_cr (partial).
  void linear_event(Ev e, int mode, double& a, double& b) const {
    const double s = mode >= 0 ? 1.0 : -1.0;
    switch (e) {
      case Ev::impact: a = 0.0, b = s; return;
      case Ev::theta_u: a = model_.theta_u(int(s)), b = -s; return;
      case Ev::half_pi: a = 0.5 * units::pi, b = -s; return;
      case Ev::branch:
        if (std::abs(mode) == 1) a = model_.theta_cr(), b = -s;
        else a = -model_.theta_cr(), b = s;
        return;
      case Ev::lift_out:
      case Ev::lift_in: break;
    }
    a = 1.0, b = 0.0;
  }

  struct KernelData {
    const RockingModel* model;
    double u0 = 0.0, u1 = 0.0;  // ug'' = u0 + u1 tau (m/s^2, m/s^3)
  };
  template <int S, bool Partial>
  static int kernel(double tau, const double* y, double* dydt, void* ctx) {
    const auto* d = static_cast<const KernelData*>(ctx);
    dydt[0] = y[1];
    dydt[1] = d->model->angular_acceleration(y[0], S, Partial, d->u0 + d->u1 * tau);
    return 0;
  }

  void consider_peak(double t, double theta) {
    if (std::fabs(theta) > res_.theta_max) {
      res_.theta_max = std::fabs(theta);
      res_.t_theta_max = t;
      res_.theta_max_side = theta >= 0.0 ? +1 : -1;
    }
  }

  // The body leaves its base about pivot s from rest.
  static void lift_off(int s, double* y, int& mode) {
    mode = s;
    y[0] = y[1] = 0.0;
  }

  // Impact at theta = 0 (rocking.md §1.2-1.3): the velocity jump w = e w-,
  // the pivot changes to the side of w; a post-impact velocity below
  // rest_velocity (Zeno: impacts would accumulate) leaves the body at rest
  // unless the excitation lifts it at once.
  void impact(double t, double* y, int& mode) {
    ++impacts_;
    y[0] = 0.0;  // project onto the switching surface
    const double w = model_.has_restitution() ? model_.impact(y[1]) : y[1];
    if (!(model_.has_restitution() && std::fabs(w) < opt_.rest_velocity)) {
      y[1] = w;
      mode = w >= 0.0 ? +1 : -1;
      if (t >= motion_.duration()) {  // free motion: can the energy left reach the peak again?
        double peak_work = model_.work(res_.theta_max, +1);
        if (two_sided_) peak_work = std::min(peak_work, model_.work(res_.theta_max, -1));
        if (detail::energy_decayed(motion_, t, 0.5 * model_.body().I0 * w * w, peak_work)) {
          decayed_ = true;
          why_ = AnalysisEnd::energy_decayed;
        }
      }
      return;
    }
    const double ug = motion_.acc(t);
    if (model_.lifts(+1, ug)) {
      mode = +1, y[1] = w > 0.0 ? w : 0.0;
    } else if (two_sided_ && model_.lifts(-1, ug)) {
      mode = -1, y[1] = w < 0.0 ? w : 0.0;
    } else {
      mode = 0, y[1] = 0.0;
    }
  }

  // |theta| = theta_u: keep the kinetic energy there (seed §3.2, the demand of
  // an overturned wall); the end of the analysis under the theta_u criterion.
  EventAction reach_theta_u(double t, const double* y) {
    ke_theta_u_ = 0.5 * model_.body().I0 * y[1] * y[1];
    return opt_.overturn == OverturnCriterion::theta_u ? overturn(t) : EventAction::proceed;
  }

  // Full <-> partial contact at |theta| = theta_cr, same pivot.
  static void switch_branch(int& mode) {
    const int s = mode >= 0 ? 1 : -1;
    mode = std::abs(mode) == 1 ? 2 * s : s;
  }

  EventAction overturn(double t) {
    res_.overturned = true;
    res_.t_overturn = t;
    return EventAction::stop;
  }

  const RockingModel& model_;
  const GroundMotion& motion_;
  const RockingOptions& opt_;
  bool smooth_, two_sided_;
  Ev kinds_[5][6];  // event kinds per mode (-2..2)
  double ev_a_[5][6] = {}, ev_b_[5][6] = {};  // g = a + b theta per rocking mode
  std::size_t n_events_[5];
  KernelData kernel_{&model_};
  RockingResult res_;
  long impacts_ = 0;
  double ke_theta_u_ = 0.0;
  bool decayed_ = false;                        // energy_decayed reached at an impact
  AnalysisEnd why_ = AnalysisEnd::free_motion_cap;  // reason when finished() returns true
};

}  // namespace

void RockingOptions::validate() const {
  // The bounds of analysis_limits.hpp, one set for every front end (issue 10, defect 11).
  auto within = [](double v, double lo, double hi, const char* what) {
    if (!(std::isfinite(v) && v >= lo && v <= hi)) {
      char buf[160];
      std::snprintf(buf, sizeof buf, " must lie in [%g, %g], got %g", lo, hi, v);
      throw InputError(std::string(what) + buf);
    }
  };
  within(rel_tol, limits::rel_tol_min, limits::rel_tol_max, "relative tolerance (-)");
  within(abs_tol, limits::abs_tol_min, limits::abs_tol_max, "absolute tolerance (rad, rad/s)");
  auto positive = [](double v, const char* what) {
    if (!(std::isfinite(v) && v > 0.0)) throw InputError(std::string(what) + " must be a positive number");
  };
  positive(event_time_tol, "event time tolerance (s)");
  positive(rest_velocity, "rest velocity (rad/s)");
  if (!(std::isfinite(scale) && scale > 0.0 && scale <= limits::scale_max)) {
    char buf[120];
    std::snprintf(buf, sizeof buf, "scale factor must lie in (0, %g], got %g", limits::scale_max, scale);
    throw InputError(buf);
  }
  within(tail_s, 0.0, limits::tail_max_s, "tail duration (s)");
  if (max_steps <= 0 || max_events <= 0 || double(max_steps) > limits::max_steps_max ||
      double(max_events) > limits::max_events_max)
    throw InputError("step and event limits must lie in [1, 1e9]");
}

const char* to_string(AnalysisEnd e) {
  switch (e) {
    case AnalysisEnd::overturned: return "overturned";
    case AnalysisEnd::rest_input_below: return "rest_input_below";
    case AnalysisEnd::rest_after_motion: return "rest_after_motion";
    case AnalysisEnd::energy_decayed: return "energy_decayed";
    case AnalysisEnd::free_motion_cap: return "free_motion_cap";
    case AnalysisEnd::failed: return "failed";
  }
  return "unknown";
}

const char* to_string(RockingTermination t) {
  switch (t) {
    case RockingTermination::completed: return "completed";
    case RockingTermination::overturned: return "overturned";
    case RockingTermination::step_limit: return "step_limit";
    case RockingTermination::event_limit: return "event_limit";
    case RockingTermination::integrator_error: return "integrator_error";
  }
  return "unknown";
}

std::string RockingResult::brief_report() const {
  char buf[512];
  std::snprintf(buf, sizeof buf,
                "%s: theta_max = %.6g rad at t = %.6g s (theta_max/theta_u = %.4g), impacts = %ld, "
                "D/C = %.4g%s",
                to_string(termination), theta_max, t_theta_max, theta_u > 0 ? theta_max / theta_u : 0.0,
                impacts, dc, overturned ? ", overturned" : "");
  return buf;
}

namespace {

// The smooth model's full-contact branch |theta| <= theta_cr = W / (2 b^2 k)
// (seed Eq. 1) must be resolved by the integrator's error control, which sees
// theta only to abs_tol: theta_cr >= 10 abs_tol (analysis_limits.hpp, derived
// in docs/theory/rocking.md §"Upper bound on k"). Beyond it the stiff contact
// oscillation (frequency ~ sqrt(k)) is integrated unchecked and the result
// can be absurd (k = 1e20 kN/m^3: theta_max = 1.6e134 rad).
void check_resolvable(const RockingModel& model, const RockingOptions& o) {
  if (model.foundation().is_rigid()) return;
  const double k = model.foundation().k;
  char buf[512];
  if (!(k <= limits::winkler_k_max_N_m3)) {
    std::snprintf(buf, sizeof buf,
                  "Winkler modulus k = %g kN/m^3 exceeds %g kN/m^3 (a base stiffer than a steel contact): use the "
                  "rigid model",
                  k / units::kN, limits::winkler_k_max_N_m3 / units::kN);
    throw InputError(buf);
  }
  const double floor = limits::theta_cr_min_over_abs_tol * o.abs_tol;
  if (!(model.theta_cr() >= floor)) {
    // theta_cr is proportional to 1/k: the largest k that meets the floor.
    const double k_ok = k * model.theta_cr() / floor;
    std::snprintf(buf, sizeof buf,
                  "Winkler modulus k = %g kN/m^3 too stiff for the integration: theta_cr = W/(2 b^2 k) = %g rad is "
                  "below %g x the absolute tolerance (%g rad), so the full-contact branch is not resolved; use "
                  "k <= %g kN/m^3, a smaller absolute tolerance (<= %g rad) or the rigid model",
                  k / units::kN, model.theta_cr(), limits::theta_cr_min_over_abs_tol, o.abs_tol, k_ok / units::kN,
                  model.theta_cr() / limits::theta_cr_min_over_abs_tol);
    throw InputError(buf);
  }
}

// A result that cannot be true is a failed analysis, never a result: a
// non-finite peak or energy, or a peak beyond the overturning rotation that
// stops the analysis (theta_u, or pi/2) by more than the event location error.
}  // namespace

void flag_untrustworthy(const RockingModel& model, const RockingOptions& o, RockingResult& r) {
  if (r.termination != RockingTermination::completed && r.termination != RockingTermination::overturned) return;
  const double stop = o.overturn == OverturnCriterion::half_pi ? 0.5 * units::pi
                                                               : std::max(model.theta_u(+1), model.theta_u(-1));
  constexpr double peak_rel_tol = 1e-6;  // - (events are located to 1e-12 s)
  const bool finite = std::isfinite(r.theta_max) && std::isfinite(r.energy_demand) && std::isfinite(r.dc) &&
                      std::isfinite(r.d_max);
  if (finite && r.theta_max <= stop * (1.0 + peak_rel_tol)) return;
  char buf[320];
  std::snprintf(buf, sizeof buf,
                "loss of accuracy: theta_max = %g rad %s the overturning rotation %g rad at t = %g s; the result is "
                "not trustworthy (lower the Winkler modulus or the tolerances)",
                r.theta_max, finite ? "beyond" : "is not finite, against", stop, r.t_theta_max);
  r.termination = RockingTermination::integrator_error;
  r.message = buf;
}

RockingResult analyse(const RockingModel& model, const GroundMotion& motion, const RockingOptions& options,
                      const RockingInitialState& initial) {
  options.validate();
  if (!(std::isfinite(initial.theta) && std::isfinite(initial.omega)))
    throw InputError("initial rotation (rad) and angular velocity (rad/s) must be finite");
  const bool one_sided = model.sidedness() == Sidedness::one_sided;
  if (one_sided && (initial.theta < 0.0 || (initial.theta == 0.0 && initial.omega < 0.0)))
    throw InputError("one-sided rocking starts with theta >= 0 (rad) moving outward");

  check_resolvable(model, options);

  RockingSystem sys(model, motion, options);
  double y[2] = {initial.theta, initial.omega};
  int mode = 0;
  if (initial.theta != 0.0 || initial.omega != 0.0) {
    const int s = initial.theta != 0.0 ? (initial.theta > 0.0 ? 1 : -1) : (initial.omega > 0.0 ? 1 : -1);
    const bool partial = !model.foundation().is_rigid() && std::fabs(initial.theta) > model.theta_cr();
    mode = partial ? 2 * s : s;
  } else if (model.lifts(+1, motion.acc(0.0))) {
    mode = +1;
  } else if (model.lifts(-1, motion.acc(0.0))) {
    mode = -1;
  }
  sys.push_history(0.0, y);

  const HybridOdeResult h = integrate_hybrid(sys, 0.0, motion.duration() + options.tail_s, y, mode,
                                              detail::hybrid_options(options, motion));

  RockingResult r = std::move(sys.result());
  detail::take_integration(h, r);
  r.motion_duration = motion.duration();
  r.impacts = sys.impacts();
  r.alpha = model.body().alpha;
  if (!model.foundation().is_rigid()) r.theta_cr = model.theta_cr();
  if (model.has_restitution()) r.restitution = model.restitution();
  const int side = r.theta_max_side;
  r.theta_u = model.theta_u(side);
  r.capacity = model.work(r.theta_u, side);
  if (r.overturned) {
    r.kinetic_energy_overturn = sys.ke_theta_u();
    r.energy_demand = r.capacity + r.kinetic_energy_overturn;  // seed §3.2
  } else {
    r.energy_demand = model.energy_demand(r.theta_max, side);
  }
  r.dc = r.energy_demand / r.capacity;
  // Centroid displacement for a rotation theta_max about the toe: R [sin(alpha) - sin(alpha - theta)].
  const RockingBody& b = model.body();
  r.d_max = b.R * std::fabs(std::sin(b.alpha) - std::sin(b.alpha - r.theta_max));
  flag_untrustworthy(model, options, r);
  r.end = detail::analysis_end(r, h, sys.why());
  return r;
}

RockingResult analyse(const RockingModel& model, const Record& record, const RockingOptions& options) {
  options.validate();
  return analyse(model, GroundMotion::from_record(record, options.scale, options.reverse), options);
}

RockingResult analyse_free(const RockingModel& model, const RockingInitialState& initial, double duration_s,
                           const RockingOptions& options) {
  RockingOptions o = options;
  o.tail_s = 0.0;  // the duration is the free motion
  return analyse(model, GroundMotion::none(duration_s), o, initial);
}

}  // namespace assess
