// integration_run.hpp (private to dynamics): what the rocking analysis and
// the chain analysis share around integrate_hybrid: the integrator's options
// from the analysis options and the motion, and the integrator's outcome
// (counters, end time, message, termination) copied into the result. The
// rest of each result (impacts, energies, theta_u) is the model's own.
#pragma once

#include "assess/dynamics/hybrid_ode.hpp"
#include "assess/dynamics/rocking_analysis.hpp"
#include "assess/records/ground_motion.hpp"

namespace assess::detail {

/// Integrator settings of an analysis: stepper, tolerances (rad, rad/s),
/// event time tolerance (s), limits, and the motion's largest step (s).
inline HybridOdeOptions hybrid_options(const RockingOptions& options, const GroundMotion& motion) {
  HybridOdeOptions h;
  h.stepper = options.stepper;
  h.rel_tol = options.rel_tol;
  h.abs_tol = options.abs_tol;
  h.event_time_tol = options.event_time_tol;
  h.max_steps = options.max_steps;
  h.max_events = options.max_events;
  h.h_max = motion.max_step();
  return h;
}

/// Copies the integrator's counters, end time (s) and message into r, and its
/// termination: a stopping event is the overturning of the body or chain.
inline void take_integration(const HybridOdeResult& h, RockingResult& r) {
  r.steps = h.steps;
  r.rejected_steps = h.rejected_steps;
  r.event_steps = h.event_steps;
  r.rhs_evaluations = h.rhs_evaluations;
  r.t_end = h.t;
  r.message = h.message;
  switch (h.termination) {
    case HybridTermination::completed: r.termination = RockingTermination::completed; break;
    case HybridTermination::stopped_by_event:
      r.termination = RockingTermination::overturned;
      r.message = "overturned";
      break;
    case HybridTermination::step_limit: r.termination = RockingTermination::step_limit; break;
    case HybridTermination::event_limit: r.termination = RockingTermination::event_limit; break;
    case HybridTermination::integrator_error: r.termination = RockingTermination::integrator_error; break;
  }
}

}  // namespace assess::detail
