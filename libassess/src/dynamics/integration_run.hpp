// integration_run.hpp (private to dynamics): what the rocking analysis and
// the chain analysis share around integrate_hybrid: the integrator's options
// from the analysis options and the motion, and the integrator's outcome
// (counters, end time, message, termination) copied into the result. The
// rest of each result (impacts, energies, theta_u) is the model's own.
#pragma once

#include "assess/dynamics/analysis_end.hpp"
#include "assess/dynamics/analysis_limits.hpp"
#include "assess/dynamics/hybrid_ode.hpp"
#include "assess/dynamics/rocking_analysis.hpp"
#include "assess/records/ground_motion.hpp"

#include <algorithm>
#include <cmath>
#include <string>

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
  // The accumulation bound of analysis_limits.hpp (chatter fails in milliseconds, not seconds).
  const double span = motion.duration() + options.tail_s;
  const double accumulation = limits::events_floor + limits::events_per_second_max * (std::isfinite(span) ? span : 0.0);
  h.max_events = static_cast<long>(std::min<double>(double(options.max_events), accumulation));
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
    case HybridTermination::completed:
    case HybridTermination::finished: r.termination = RockingTermination::completed; break;
    case HybridTermination::stopped_by_event:
      r.termination = RockingTermination::overturned;
      r.message = "overturned";
      break;
    case HybridTermination::step_limit: r.termination = RockingTermination::step_limit; break;
    case HybridTermination::event_limit:
      r.termination = RockingTermination::event_limit;
      r.message += "; events accumulate (at most " + std::to_string(long(limits::events_per_second_max)) +
                   " per second of motion): the body chatters at rest, e.g. under a record scaled far below any "
                   "effect (docs/theory/rocking.md §7)";
      break;
    case HybridTermination::integrator_error: r.termination = RockingTermination::integrator_error; break;
  }
}

/// The end rule of analysis_end.hpp, shared by the rocking body and the chain.
/// At rest at time t: true if the body stays at rest for good, with the
/// reason: no ug'' left in the motion lifts it. `lifts(ug)` must be the
/// model's lift-off test, affine in ug'' (a static moment or force), so the
/// test at the two extremes of the remaining motion covers every value
/// between them, and the rest is exact (docs/theory/rocking.md §8).
template <class Lifts>
bool rests_for_good(const GroundMotion& motion, double t, const Lifts& lifts, AnalysisEnd& why) {
  double lo = 0.0, hi = 0.0;
  motion.acc_range_from(t, lo, hi);
  if (!(std::isfinite(lo) && std::isfinite(hi)) || lifts(lo) || lifts(hi)) return false;
  why = t >= motion.duration() ? AnalysisEnd::rest_after_motion : AnalysisEnd::rest_input_below;
  return true;
}

/// Free motion (t past the end of the motion), just after an impact at the
/// rest position: true if the energy left, `energy` (kinetic: the potential
/// is zero there), is at most free_energy_fraction x `work_to_peak`, the
/// least work of the restoring moment (force) from rest to the peak rotation
/// on a side the body can move to. With no excitation the energy can only
/// decrease (conservative restoring moment between impacts, |e| <= 1 at
/// them), so no later excursion reaches the peak: it is final.
inline bool energy_decayed(const GroundMotion& motion, double t, double energy, double work_to_peak) {
  return t >= motion.duration() && energy <= free_energy_fraction * work_to_peak;
}

/// Why the analysis ended, from its termination and, for a finished
/// integration, the reason the system gave.
inline AnalysisEnd analysis_end(const RockingResult& r, const HybridOdeResult& h, AnalysisEnd finished_why) {
  if (!succeeded(r)) return AnalysisEnd::failed;
  if (r.overturned) return AnalysisEnd::overturned;
  return h.termination == HybridTermination::finished ? finished_why : AnalysisEnd::free_motion_cap;
}

}  // namespace assess::detail
