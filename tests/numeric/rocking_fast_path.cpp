// The rocking analysis' fast path (issue 15) against its generic path:
// GroundMotion::linear_piece against acc() (the same straight line between
// samples), and a record analysed through the right-hand-side kernel (ug'' as
// a0 + a1 tau per sample interval) against the same record given as a
// function of time, which the integrator evaluates through the virtual rhs()
// with breakpoints at the samples: the same steps, so the same results up to
// rounding.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/dynamics/hybrid_ode.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/records/ground_motion.hpp>
#include <assess/support/units.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>
#include <vector>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

// ug'' from the piece against acc(): a0 + a1 (t - t_k) and s_k + (t/dt - k)(s_k+1 - s_k)
// differ by rounding only; acc() forms t/dt, whose fraction carries an error
// of about eps t/dt, times the jump s_k+1 - s_k. Bound: this many ulp of
// (t/dt + 1) max|s_k+1 - s_k| (m/s^2).
constexpr double kPieceUlps = 8.0;
// Kernel path against generic path: the same steps and events; the two forms
// of ug''(t) differ by rounding, which a rocking history (impacts, near-chaotic
// response) may amplify a little over 20 s.
constexpr double kThetaMaxRelTol = 1e-8;  // relative, theta_max (rad)
constexpr double kTimeTol = 1e-9;         // s, time of theta_max

Record synthetic(double dt, int n) {
  Record r;
  r.name = "synthetic";
  r.dt = dt;
  for (int i = 0; i < n; ++i) {
    const double t = i * dt;
    r.acc.push_back(4.0 * std::sin(2.0 * units::pi * 1.7 * t) * std::exp(-0.1 * t) + 1.5 * std::sin(0.731 * i * i));
  }
  return r;
}

}  // namespace

TEST_CASE("linear_piece is acc() on every sample interval, before the record and in the tail") {
  const Record rec = synthetic(0.005, 2001);  // 10 s
  const GroundMotion g = GroundMotion::from_record(rec, 0.7, true);
  double jump = 0.0;  // max |s_k+1 - s_k| of the scaled record (m/s^2)
  for (std::size_t k = 0; k + 1 < rec.size(); ++k) jump = std::max(jump, 0.7 * std::fabs(rec.acc[k + 1] - rec.acc[k]));
  std::vector<double> times;
  for (int i = -20; i < 2400; ++i) times.push_back(0.0041 * i + 1e-4);
  for (int k : {0, 1, 500, 1999, 2000}) times.push_back(k * rec.dt);  // sample times themselves
  for (double t : times) {
    GroundMotion::LinearPiece p;
    REQUIRE(g.linear_piece(t, p));
    CAPTURE(t);
    // The piece carries next_breakpoint(t) itself, the same double (the
    // integrator uses it instead of asking): exact equality, before the record too.
    CHECK(p.end == g.next_breakpoint(t));
    // The piece ends at the next breakpoint and starts one sample before it (at or before t).
    if (t >= 0.0) {
      CHECK(p.origin <= t);
      CHECK_CLOSE(p.origin + rec.dt, g.next_breakpoint(t), abs_tol(1e-12));
    }
    // acc() jumps to zero at the record's end: its value exactly there is
    // the last sample, the piece past it is the tail's zero.
    if (t == g.duration()) continue;
    const double t_mid = std::max(t, p.origin);
    const double tol = kPieceUlps * std::numeric_limits<double>::epsilon() * (std::fabs(t_mid) / rec.dt + 1.0) * jump;
    CHECK_CLOSE(p.a0 + p.a1 * (t_mid - p.origin), g.acc(t_mid), abs_tol(tol));
  }
  const GroundMotion f = GroundMotion::from_function([](double) { return 1.0; }, 1.0);
  GroundMotion::LinearPiece p;
  CHECK_FALSE(f.linear_piece(0.5, p));
}

TEST_CASE("a record through the kernel and the same record as a function give the same response") {
  const Record rec = synthetic(0.01, 2001);  // 20 s
  const double scale = 0.25;
  const GroundMotion as_record = GroundMotion::from_record(rec, scale);
  std::vector<double> samples;
  const double tail = 2.0;  // s of free motion; a record keeps its sample breakpoints there
  for (int i = 1; i < int(rec.size() + tail / rec.dt + 1); ++i) samples.push_back(i * rec.dt);
  const GroundMotion as_function =
      GroundMotion::from_function([&](double t) { return as_record.acc(t); }, as_record.duration(), samples,
                                  /*max_step_s=*/1.0);  // the samples bound the steps, as for the record
  const RockingBody body = RockingBody::rectangle(0.25, 3.0, 12.06 * units::kN);
  for (const RockingModel& model :
       {RockingModel(body, Foundation::winkler(1e9), Sidedness::two_sided, Restitution::housner()),
        RockingModel(body, Foundation::rigid(), Sidedness::two_sided, Restitution::housner())}) {
    RockingOptions o;
    o.tail_s = tail;
    const RockingResult a = analyse(model, as_record, o), b = analyse(model, as_function, o);
    CAPTURE(model.foundation().is_rigid());
    REQUIRE(a.termination == b.termination);
    CHECK(a.theta_max > 1e-4);  // the record makes the block rock
    CHECK(a.impacts == b.impacts);
    CHECK(a.steps == b.steps);
    CHECK_CLOSE(a.theta_max, b.theta_max, rel_tol(kThetaMaxRelTol));
    CHECK_CLOSE(a.t_theta_max, b.t_theta_max, abs_tol(kTimeTol));
  }
}

namespace {

/// y' = 1 through a kernel that returns NaN from t = 0.5 s on (a kernel does
/// not check its results): the integrator must stop with integrator_error at
/// the step that produced it, not carry NaN on.
class NanAfterHalf final : public HybridSystem {
 public:
  std::size_t dimension() const override { return 1; }
  bool rhs(double t, const double*, int, double* f) const override {
    f[0] = t < 0.5 ? 1.0 : std::numeric_limits<double>::quiet_NaN();
    return true;
  }
  RhsKernel rhs_kernel(int, double t) override {
    origin_ = t;
    return {&kernel, this, t};
  }
  static int kernel(double tau, const double*, double* f, void* ctx) {
    const double t = tau + static_cast<NanAfterHalf*>(ctx)->origin_;
    f[0] = t < 0.5 ? 1.0 : std::numeric_limits<double>::quiet_NaN();
    return 0;
  }
  std::size_t event_count(int) const override { return 0; }
  double event(std::size_t, double, const double*, int) const override { return 1.0; }
  EventDirection event_direction(std::size_t, int) const override { return EventDirection::falling; }
  EventAction on_event(std::size_t, double, double*, int&) override { return EventAction::proceed; }
  void on_step(double, const double*, const double*, double, const double*, const double*, int) override {}
  double next_breakpoint(double t) const override { return 0.1 * (std::floor(t / 0.1 + 1e-9) + 1.0); }

 private:
  double origin_ = 0.0;
};

}  // namespace

TEST_CASE("a kernel that yields NaN ends the integration with integrator_error at that step") {
  NanAfterHalf sys;
  double y[1] = {0.0};
  const HybridOdeResult r = integrate_hybrid(sys, 0.0, 1.0, y, 0);
  CHECK(r.termination == HybridTermination::integrator_error);
  CHECK(r.t < 0.5 + 0.1);                 // stopped at the first step past t = 0.5 s
  CHECK(r.message.find("non-finite") != std::string::npos);
}
