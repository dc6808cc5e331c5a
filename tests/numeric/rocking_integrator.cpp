// The generic event-driven integrator (hybrid_ode.hpp) on problems with known
// solutions: convergence order of each GSL stepper, error against tolerance,
// event location and jumps (bouncing ball), and termination reasons.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/dynamics/hybrid_ode.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

// Observed order log2(e(H)/e(H/2)) of the max error within this margin of the
// nominal order (GSL gsl_odeiv2_step_order): the steps are chosen in the
// asymptotic range, the margin covers the remaining higher-order terms.
constexpr double kOrderMargin = 0.6;
// Bouncing-ball impact times (s): event_time_tol is 1e-12 s, the integration
// of a parabola by any of the steppers is exact to rounding.
constexpr double kImpactTimeTol = 1e-10;

/// Logistic equation y' = y (1 - y), y(0) = 0.1: y = 1 / (1 + 9 e^-t)
/// (nonlinear, so that the observed order is the nonlinear order of the
/// method, not the higher order its stability function may have on linear
/// problems). Breakpoints every H force a fixed step when the tolerances are loose.
class Logistic final : public HybridSystem {
 public:
  explicit Logistic(double H) : H_(H) {}
  static double exact(double t) { return 1.0 / (1.0 + 9.0 * std::exp(-t)); }
  std::size_t dimension() const override { return 1; }
  bool rhs(double, const double* y, int, double* f) const override {
    f[0] = y[0] * (1.0 - y[0]);
    return true;
  }
  std::size_t event_count(int) const override { return 0; }
  double event(std::size_t, double, const double*, int) const override { return 1.0; }
  EventDirection event_direction(std::size_t, int) const override { return EventDirection::falling; }
  EventAction on_event(std::size_t, double, double*, int&) override { return EventAction::proceed; }
  void on_step(double, const double*, const double*, double t1, const double* y1, const double*, int) override {
    max_error = std::max(max_error, std::fabs(y1[0] - exact(t1)));
  }
  double max_error = 0.0;  ///< max |y - exact| over the step ends
  double next_breakpoint(double t) const override {
    return H_ > 0 ? H_ * (std::floor(t / H_ + 1e-9) + 1.0) : std::numeric_limits<double>::infinity();
  }

 private:
  double H_;
};

/// Ball dropped from height z0 = 1 m: z'' = -g; at z = 0, z' -> -e z'.
class Ball final : public HybridSystem {
 public:
  explicit Ball(double e) : e_(e) {}
  std::size_t dimension() const override { return 2; }
  bool rhs(double, const double* y, int, double* f) const override {
    f[0] = y[1];
    f[1] = -9.81;
    return true;
  }
  std::size_t event_count(int) const override { return 1; }
  double event(std::size_t, double, const double* y, int) const override { return y[0]; }
  EventDirection event_direction(std::size_t, int) const override { return EventDirection::falling; }
  EventAction on_event(std::size_t, double t, double* y, int&) override {
    if (n_ < 8) times_[n_] = t;
    ++n_;
    y[0] = 0.0;
    y[1] = -e_ * y[1];
    return EventAction::proceed;
  }
  void on_step(double, const double*, const double*, double, const double*, const double*, int) override {}
  double next_breakpoint(double) const override { return std::numeric_limits<double>::infinity(); }
  double times_[8] = {};
  long n_ = 0;

 private:
  double e_;
};

double error_fixed(OdeStepper s, double H) {
  Logistic sys(H);
  HybridOdeOptions o;
  o.stepper = s;
  o.rel_tol = o.abs_tol = 1.0;  // the breakpoints, not the control, set the step
  o.h_initial = H;
  double y[1] = {0.1};
  const HybridOdeResult r = integrate_hybrid(sys, 0.0, 10.0, y, 0, o);
  REQUIRE(r.termination == HybridTermination::completed);
  CHECK(r.rejected_steps == 0);
  return sys.max_error;
}

double error_adaptive(OdeStepper s, double tol) {
  Logistic sys(0.0);
  HybridOdeOptions o;
  o.stepper = s;
  o.rel_tol = o.abs_tol = tol;
  double y[1] = {0.1};
  integrate_hybrid(sys, 0.0, 10.0, y, 0, o);
  return sys.max_error;
}

}  // namespace

TEST_CASE("halving the step reduces the error by 2^order for each stepper") {
  struct Case {
    OdeStepper s;
    double order, H;
  };
  for (const Case c : {Case{OdeStepper::rk8pd, 8.0, 0.5}, Case{OdeStepper::rkck, 5.0, 0.25},
                       Case{OdeStepper::rkf45, 5.0, 0.25}}) {
    CAPTURE(c.order);
    const double e1 = error_fixed(c.s, c.H), e2 = error_fixed(c.s, 0.5 * c.H);
    CHECK_CLOSE(std::log2(e1 / e2), c.order, abs_tol(kOrderMargin));
  }
}

TEST_CASE("the global error follows the tolerance: 100x tighter gives 30x to 300x smaller error") {
  for (OdeStepper s : {OdeStepper::rk8pd, OdeStepper::rkck, OdeStepper::rkf45}) {
    const double e1 = error_adaptive(s, 1e-7), e2 = error_adaptive(s, 1e-9);
    CHECK(e1 < 1e-5);
    CHECK(e1 / e2 > 30.0);
    CHECK(e1 / e2 < 300.0);
  }
}

TEST_CASE("bouncing ball: impact times located to 1e-10 s, jumps applied, event limit ends a Zeno run") {
  Ball ball(0.5);
  HybridOdeOptions o;
  o.max_events = 60;
  double y[2] = {1.0, 0.0};
  const HybridOdeResult r = integrate_hybrid(ball, 0.0, 10.0, y, 0, o);
  // t1 = sqrt(2 z0/g); then flights of 2 e^k v1/g with v1 = g t1
  const double t1 = std::sqrt(2.0 / 9.81);
  double t = t1;
  for (int k = 0; k < 8; ++k) {
    CHECK_CLOSE(ball.times_[k], t, abs_tol(kImpactTimeTol));
    t += 2.0 * std::pow(0.5, k + 1) * t1;
  }
  // the impacts accumulate at t1 (1 + 2 e/(1 - e)) = 3 t1 < 10 s: a hang without the limit
  CHECK(r.termination == HybridTermination::event_limit);
  CHECK(r.events == 60);
  // stopped at the accumulation point; each located event may lag by event_time_tol
  CHECK_CLOSE(r.t, 3.0 * t1, abs_tol(double(o.max_events) * o.event_time_tol));
}

TEST_CASE("the step limit ends a run with its own termination reason") {
  Logistic sys(0.01);
  HybridOdeOptions o;
  o.max_steps = 50;
  double y[1] = {0.1};
  const HybridOdeResult r = integrate_hybrid(sys, 0.0, 10.0, y, 0, o);
  CHECK(r.termination == HybridTermination::step_limit);
  CHECK(r.steps == 50);
  CHECK(std::string(to_string(r.termination)) == "step_limit");
}

TEST_CASE("event location: guesses from the step's interpolant need 3 re-steps per impact of the ball") {
  Ball ball(0.5);
  HybridOdeOptions o;
  o.max_events = 8;
  double y[2] = {1.0, 0.0};
  const HybridOdeResult r = integrate_hybrid(ball, 0.0, 10.0, y, 0, o);
  CHECK(r.events == 8);
  CHECK(r.event_steps <= 3 * r.events);
}
