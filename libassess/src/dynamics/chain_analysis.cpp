// chain_analysis.cpp: a 1-DOF chain as a hybrid system (state q, q'; mode 0
// at rest, 1 moving with the rigid base or the Winkler bed in full contact,
// 2 moving in partial contact) integrated by integrate_hybrid.
//
// Events (all falling unless stated):
//   rest:    lift-off, -(V'(0) + Mf(0)) - ug B(0) rising through 0
//   moving:  impact q = 0; ultimate coordinate q_u - q; branch q_cr - q
//            (full -> partial) or q - q_cr (partial -> full)
// Impact: q'+ = e q'- (docs/theory/chain-dynamics.md); when |q'+| is below
// the rest velocity and the excitation cannot lift the chain, it rests.
#include "assess/dynamics/chain_analysis.hpp"

#include "assess/support/error.hpp"
#include "dynamics/integration_run.hpp"
#include "dynamics/quintic.hpp"
#include "support/bracket_root.hpp"

#include <cmath>

namespace assess {
namespace {

enum class Ev { lift_out, lift_in, impact, q_u, branch };

class ChainSystem final : public HybridSystem {
 public:
  ChainSystem(const ChainDynamics& model, const GroundMotion& motion, const RockingOptions& opt, double e,
              bool two_sided)
      : model_(model), motion_(motion), opt_(opt), e_(e), smooth_(model.smooth()), two_sided_(two_sided) {}

  std::size_t dimension() const override { return 2; }
  bool rhs(double t, const double* y, int mode, double* dydt) const override {
    if (mode == 0) {
      dydt[0] = dydt[1] = 0.0;
      return true;
    }
    dydt[0] = y[1];
    dydt[1] = model_.acceleration(y[0], y[1], std::abs(mode) == 2, motion_.acc(t), mode > 0 ? 1 : -1);
    return std::isfinite(dydt[1]);
  }
  std::size_t event_count(int mode) const override {
    return mode == 0 ? (two_sided_ ? 2 : 1) : (smooth_ ? 3 : 2);
  }
  EventDirection event_direction(std::size_t k, int mode) const override {
    const Ev e = kind(k, mode);
    return e == Ev::lift_out || e == Ev::lift_in ? EventDirection::rising : EventDirection::falling;
  }
  double event(std::size_t k, double t, const double* y, int mode) const override {
    const double s = mode >= 0 ? 1.0 : -1.0;
    switch (kind(k, mode)) {
      case Ev::lift_out: return model_.rest_force(motion_.acc(t), +1);
      case Ev::lift_in: return model_.rest_force(motion_.acc(t), -1);
      case Ev::impact: return s * y[0];
      case Ev::q_u: return model_.q_u() - s * y[0];
      case Ev::branch: return std::abs(mode) == 1 ? model_.q_cr() - s * y[0] : s * y[0] - model_.q_cr();
    }
    return 1.0;
  }
  EventAction on_event(std::size_t k, double t, double* y, int& mode) override {
    const int side = mode >= 0 ? 1 : -1;
    switch (kind(k, mode)) {
      case Ev::lift_out:
      case Ev::lift_in:
        mode = kind(k, mode) == Ev::lift_out ? 1 : -1;
        y[0] = y[1] = 0.0;
        break;
      case Ev::impact: {
        ++impacts_;
        y[0] = 0.0;
        const double w = e_ * y[1];  // q'+ = e q'- (one-sided e <= 0: rebound; two-sided e >= 0: goes through)
        if (std::fabs(w) < opt_.rest_velocity) {
          const double ug = motion_.acc(t);
          if (model_.lifts(ug, +1)) {
            mode = 1, y[1] = w > 0.0 ? w : 0.0;
          } else if (two_sided_ && model_.lifts(ug, -1)) {
            mode = -1, y[1] = w < 0.0 ? w : 0.0;
          } else {
            mode = 0, y[1] = 0.0;
          }
        } else {
          if (two_sided_) {
            y[1] = w, mode = w >= 0.0 ? 1 : -1;
          } else {
            y[1] = std::fabs(w), mode = 1;
          }
          // Free motion: can the energy left (kinetic; the potential is zero
          // at q = 0) reach the peak again? Symmetric two-sided chains have
          // the same work on both sides.
          if (detail::energy_decayed(motion_, t, 0.5 * model_.mass(0.0) * w * w, model_.work(res_.theta_max))) {
            decayed_ = true;
            why_ = AnalysisEnd::energy_decayed;
          }
        }
        break;
      }
      case Ev::q_u:
        ke_q_u_ = 0.5 * model_.mass(std::fabs(y[0])) * y[1] * y[1];
        res_.overturned = true;
        res_.t_overturn = t;
        return EventAction::stop;
      case Ev::branch: mode = std::abs(mode) == 1 ? 2 * side : side; return EventAction::proceed;
    }
    push_history(t, y);
    return EventAction::proceed;
  }
  void on_step(double t0, const double* y0, const double* f0, double t1, const double* y1, const double* f1,
               int) override {
    peak(t0, y0[0]);
    peak(t1, y1[0]);
    // An extremum inside the step: the root of the slope of the quintic
    // Hermite of q from (q, q', q'') at both ends (as the rocking analysis).
    double tp, qp;
    if (detail::extremum_in_step(t0, y0, f0, t1, y1, f1, tp, qp)) peak(tp, qp);
    push_history(t1, y1);
  }
  double next_breakpoint(double t) const override { return motion_.next_breakpoint(t); }
  bool stationary(int mode) const override { return mode == 0; }
  // The end rule (analysis_end.hpp), as the rocking analysis.
  bool finished(double t, const double*, int mode) override {
    if (mode == 0) {
      auto lifts = [this](double ug) { return model_.lifts(ug, +1) || (two_sided_ && model_.lifts(ug, -1)); };
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
  double ke_q_u() const { return ke_q_u_; }

 private:
  Ev kind(std::size_t k, int mode) const {
    if (mode == 0) return k == 0 ? Ev::lift_out : Ev::lift_in;
    return k == 0 ? Ev::impact : k == 1 ? Ev::q_u : Ev::branch;
  }
  void peak(double t, double q) {
    if (std::fabs(q) > res_.theta_max)
      res_.theta_max = std::fabs(q), res_.t_theta_max = t, res_.theta_max_side = q >= 0.0 ? 1 : -1;
  }

  const ChainDynamics& model_;
  const GroundMotion& motion_;
  const RockingOptions& opt_;
  double e_;
  bool smooth_, two_sided_;
  RockingResult res_;
  long impacts_ = 0;
  double ke_q_u_ = 0.0;
  bool decayed_ = false;
  AnalysisEnd why_ = AnalysisEnd::free_motion_cap;
};

}  // namespace

RockingResult analyse_chain(const ChainDynamics& model, const GroundMotion& motion, const RockingOptions& options,
                            double e, const RockingInitialState& initial, Sidedness sidedness) {
  options.validate();
  const bool two_sided = sidedness == Sidedness::two_sided;
  if (two_sided && !model.symmetric())
    throw InputError("two-sided motion of a chain needs blocks and loads that are mirror images of themselves "
                     "(the inward mechanism is then the mirror of the outward one); this chain is not");
  if (!two_sided && !(std::isfinite(e) && e >= -1.0 && e <= 0.0))
    throw InputError("one-sided chain restitution must be in [-1, 0] (q'+ = e q'-, rebound at q = 0), got " +
                     std::to_string(e));
  if (two_sided && !(std::isfinite(e) && e >= 0.0 && e <= 1.0))
    throw InputError("two-sided chain restitution must be in [0, 1] (q'+ = e q'-, the chain goes through q = 0), got " +
                     std::to_string(e));
  if (options.overturn != OverturnCriterion::theta_u)
    throw InputError("the overturning criterion of a chain is q_u, where its net restoring force vanishes "
                     "(\"overturn_at\": \"half_pi\" applies to one rocking block)");
  if (!(std::isfinite(initial.theta) && std::isfinite(initial.omega)) ||
      (!two_sided && (initial.theta < 0.0 || (initial.theta == 0.0 && initial.omega < 0.0))))
    throw InputError("a one-sided chain starts with q >= 0 (rad) moving outward (finite values)");

  ChainSystem sys(model, motion, options, e, two_sided);
  double y[2] = {initial.theta, initial.omega};
  int mode = 0;
  if (initial.theta != 0.0 || initial.omega != 0.0) {
    const int s = initial.theta != 0.0 ? (initial.theta > 0.0 ? 1 : -1) : (initial.omega > 0.0 ? 1 : -1);
    mode = model.smooth() && std::fabs(initial.theta) > model.q_cr() ? 2 * s : s;
  } else if (model.lifts(motion.acc(0.0), +1)) {
    mode = 1;
  } else if (two_sided && model.lifts(motion.acc(0.0), -1)) {
    mode = -1;
  }
  sys.push_history(0.0, y);

  const HybridOdeResult h = integrate_hybrid(sys, 0.0, motion.duration() + options.tail_s, y, mode,
                                              detail::hybrid_options(options, motion));

  RockingResult r = std::move(sys.result());
  detail::take_integration(h, r);
  r.motion_duration = motion.duration();
  r.impacts = sys.impacts();
  r.alpha = 0.0;
  if (model.smooth()) r.theta_cr = model.q_cr();
  r.restitution = e;
  r.theta_u = model.q_u();
  r.capacity = model.capacity();
  if (r.overturned) {
    r.kinetic_energy_overturn = sys.ke_q_u();
    r.energy_demand = r.capacity + r.kinetic_energy_overturn;  // seed §3.2
  } else {
    r.energy_demand = model.energy_demand(r.theta_max);
  }
  r.dc = r.energy_demand / r.capacity;
  r.d_max = 0.0;
  r.end = detail::analysis_end(r, h, sys.why());
  return r;
}

RockingResult analyse_chain(const ChainDynamics& model, const Record& record, const RockingOptions& options,
                            double e, Sidedness sidedness) {
  options.validate();
  return analyse_chain(model, GroundMotion::from_record(record, options.scale, options.reverse), options, e, {},
                       sidedness);
}

}  // namespace assess
