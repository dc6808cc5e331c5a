// hybrid_ode.hpp: a generic event-driven integrator for hybrid systems
// (continuous state y with a discrete mode, events and jumps). It knows
// nothing of masonry. The implementation uses GSL gsl_odeiv2 explicit
// embedded Runge-Kutta steppers with adaptive step control; GSL stays in the
// source file.
//
// Thread safety: an integrate() call owns all its GSL objects, so calls may
// run concurrently. The first call switches GSL's error handler off
// (gsl_set_error_handler_off(), process-global and done once): every GSL
// status is checked and becomes a HybridTermination instead of an abort.
#pragma once

#include <cstddef>
#include <limits>
#include <optional>
#include <string>

namespace assess {

/// Explicit embedded Runge-Kutta stepper of gsl_odeiv2.
enum class OdeStepper {
  rk8pd,  ///< Prince-Dormand (8, 9), 13 stages (default)
  rkck,   ///< Cash-Karp (4, 5)
  rkf45   ///< Runge-Kutta-Fehlberg (4, 5)
};

/// The stepper named "rk8pd", "rkck" or "rkf45"; none for another name (the
/// caller reports it with the name of its own field or option).
std::optional<OdeStepper> parse_stepper(const std::string& name);

/// Direction in which an event function must cross zero to fire.
enum class EventDirection {
  falling,  ///< from g >= 0 at the start of a step to g < 0
  rising    ///< from g <= 0 at the start of a step to g > 0
};

/// What the integrator does after an event callback.
enum class EventAction { proceed, stop };

/// A right-hand side as a plain function for the integrator's hot path (no
/// virtual call, no adapter): dy/dt at the local time tau = t - origin.
/// Returns 0 on success, nonzero if the derivative cannot be computed. The
/// signature is the C callback of gsl_odeiv2_system, which is why it is a
/// plain function pointer and a context.
struct RhsKernel {
  int (*fn)(double tau, const double* y, double* dydt, void* ctx) = nullptr;  ///< nullptr: no kernel
  void* ctx = nullptr;
  double origin = 0.0;  ///< s: the kernel is called with t - origin
  /// s: next_breakpoint(t) for the t the kernel was made for, if the system
  /// knows it on the way (the same value to the bit); NaN: the integrator asks
  /// next_breakpoint(). Saves one virtual call and one index computation per
  /// sample interval.
  double end = std::numeric_limits<double>::quiet_NaN();
};

/// A hybrid system: state y (size n), a discrete mode, a right-hand side per
/// mode, event functions per mode and a jump map. A value exactly at zero
/// counts as not yet crossed, so an event that starts exactly at zero (a
/// state put on the switching surface by a jump) is not re-detected.
class HybridSystem {
 public:
  virtual ~HybridSystem() = default;
  virtual std::size_t dimension() const = 0;
  /// dy/dt at (t, y) in `mode`. Return false if the derivative cannot be computed.
  virtual bool rhs(double t, const double* y, int mode, double* dydt) const = 0;
  /// Number of event functions active in `mode`. The integrator reads the
  /// count and the directions once per mode (at the start and after each jump).
  virtual std::size_t event_count(int mode) const = 0;
  /// Event function g_k(t, y) in `mode` and its direction.
  virtual double event(std::size_t k, double t, const double* y, int mode) const = 0;
  virtual EventDirection event_direction(std::size_t k, int mode) const = 0;
  /// Called with the state just past the located event k: apply the jump
  /// (may change y and mode); return stop to end the integration.
  virtual EventAction on_event(std::size_t k, double t, double* y, int& mode) = 0;
  /// Called after every accepted step with its end points and derivatives
  /// (for dense output by cubic Hermite interpolation, history, peaks).
  virtual void on_step(double t0, const double* y0, const double* f0, double t1, const double* y1,
                       const double* f1, int mode) = 0;
  /// Next time > t at which the right-hand side is not smooth (e.g. a record
  /// sample); the integrator never steps across it. +inf if none. Called
  /// again only once t has reached the previous answer.
  virtual double next_breakpoint(double t) const = 0;
  /// True if dy/dt is identically zero in `mode` (e.g. a body at rest): the
  /// integrator then takes no Runge-Kutta steps, only evaluates the event
  /// functions at the breakpoints (at most h_max apart) and locates a sign
  /// change in time with the state held constant. Read once per mode (at the
  /// start and after each jump). Default: false.
  virtual bool stationary(int /*mode*/) const { return false; }
  /// True if integrating further cannot change anything the system reports
  /// (e.g. a body at rest that the rest of the excitation cannot move): the
  /// integration then ends with HybridTermination::finished. Asked at the
  /// start, after every jump and at every breakpoint of a stationary mode.
  /// Default: false (integrate to t_end).
  virtual bool finished(double /*t*/, const double* /*y*/, int /*mode*/) { return false; }

  // Optional fast paths (defaults: none; results are the same either way).

  /// A kernel equal to rhs(t, y, mode, .) for t from `t` up to
  /// next_breakpoint(t) (it may hold data of that interval, such as the
  /// excitation as a linear function of time). The integrator asks again for
  /// each new breakpoint interval and after each jump. Default: none (the
  /// integrator calls rhs()). A kernel need not check its result for
  /// non-finite values: the integrator checks the state at the end of every step.
  virtual RhsKernel rhs_kernel(int /*mode*/, double /*t*/) { return {}; }
  /// All event functions of `mode` at (t, y) into g[0 .. event_count(mode)).
  /// Default: event(k, ...) for each k.
  virtual void events(double t, const double* y, int mode, double* g) const;
  /// Dense output inside a step, used only to guess event times (each guess is
  /// checked by a real step): the state at t0 + s (t1 - t0), s in [0, 1], from
  /// the ends of the step and their derivatives. Default: cubic Hermite per
  /// component. A system that knows more (second derivatives of a
  /// second-order equation) may return a higher-order interpolant.
  virtual void interpolate(double t0, const double* y0, const double* f0, double t1, const double* y1,
                           const double* f1, int mode, double s, double* y) const;
};

/// Settings of HybridIntegrator::integrate. Defaults are documented per field.
struct HybridOdeOptions {
  OdeStepper stepper = OdeStepper::rk8pd;  ///< default rk8pd
  double rel_tol = 1e-8;                   ///< relative local error per step (default 1e-8)
  double abs_tol = 1e-10;                  ///< absolute local error per step (state units; default 1e-10)
  double event_time_tol = 1e-12;           ///< width of the final event bracket (s; default 1e-12)
  double h_initial = 1e-3;                 ///< first trial step (s; default 1e-3)
  double h_max = std::numeric_limits<double>::infinity();  ///< largest step (s; default unlimited)
  long max_steps = 50'000'000;             ///< limit on steps, accepted + rejected (default 5e7)
  long max_events = 10'000'000;            ///< limit on located events (default 1e7)
  /// @throws InputError naming the invalid field
  void validate() const;
};

/// How an integration ended.
enum class HybridTermination {
  completed,         ///< reached t_end
  finished,          ///< the system declared itself finished before t_end (HybridSystem::finished)
  stopped_by_event,  ///< an event callback returned stop
  step_limit,        ///< max_steps reached
  event_limit,       ///< max_events reached (e.g. an accumulation of events)
  integrator_error   ///< a GSL status other than success, or a failed rhs
};

const char* to_string(HybridTermination t);

/// Outcome of an integration: the state at t_end (or at the stop) and counters.
struct HybridOdeResult {
  HybridTermination termination = HybridTermination::completed;
  std::string message;     ///< human-readable detail (GSL error text, which event stopped)
  double t = 0.0;          ///< final time (s)
  int mode = 0;            ///< final mode
  long steps = 0;          ///< accepted steps (event re-steps excluded)
  long rejected_steps = 0; ///< steps rejected by the error control
  long event_steps = 0;    ///< re-steps taken to locate events
  long events = 0;         ///< located events
  long rhs_evaluations = 0;
};

/// Integrates `sys` from (t0, y, mode) to t_end, never stepping across a
/// breakpoint, and locates events by re-stepping from the saved start of the
/// step: the first re-step size is the root of the event function on the
/// system's dense output; a Newton step from each real value (with the dense
/// output's slope) gives the next one, and a re-step that falls on the fired
/// side within event_time_tol / 2 of the Newton root estimated from its own
/// value ends the search (at most two such re-steps); otherwise Illinois
/// regula falsi with bisection safeguard narrows a bracket on the step size
/// until it is narrower than event_time_tol. The jump is applied to the state
/// at the fired end and the stepper is reset. `y` (size sys.dimension())
/// holds the final state.
HybridOdeResult integrate_hybrid(HybridSystem& sys, double t0, double t_end, double* y, int mode,
                                 const HybridOdeOptions& options = {});

}  // namespace assess
