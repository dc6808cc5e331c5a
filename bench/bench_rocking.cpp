// bench_rocking.cpp: one smooth-block analysis of the benchmark
// (2b = 0.25 m, 2h = 3 m, 12.06 kN/m^3, k = 1e6 kN/m^3, two-sided, Housner e)
// under the Sturno E-W record (RSN292_ITALY_A-STU270.AT2) at scale 0.2.
// Prints ms per analysis (best of N repeats), steps and right-hand-side
// evaluations per analysis, and theta_max against a run at 1000x tighter
// tolerances. Usage: bench_rocking [repeats] [rel_tol abs_tol] [stepper]
#include <assess/hazard/hazard.hpp>
#include <assess/records/record_io.hpp>
#include <assess/dynamics/hybrid_ode.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/records/ground_motion.hpp>
#include <assess/support/units.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>

namespace {

// The integrator's floor: a linear oscillator theta'' = -w^2 theta - ug''
// (w = 2 pi 2 rad/s) under the same record, with the same one step per sample
// through the same driver and GSL rk8pd, a kernel of a few flops and no events.
// The difference to an analysis is the rocking right-hand side and events.
class FloorSystem final : public assess::HybridSystem {
 public:
  explicit FloorSystem(const assess::GroundMotion& g) : g_(g) {}
  std::size_t dimension() const override { return 2; }
  bool rhs(double t, const double* y, int, double* f) const override {
    f[0] = y[1];
    f[1] = -kW2 * y[0] - g_.acc(t);
    return true;
  }
  assess::RhsKernel rhs_kernel(int, double t) override {
    assess::GroundMotion::LinearPiece p;
    if (!g_.linear_piece(t, p)) return {};
    u0_ = p.a0, u1_ = p.a1;
    assess::RhsKernel k;
    k.fn = &kernel;
    k.ctx = this;
    k.origin = p.origin;
    k.end = p.end;
    return k;
  }
  static int kernel(double tau, const double* y, double* f, void* ctx) {
    const auto* s = static_cast<const FloorSystem*>(ctx);
    f[0] = y[1];
    f[1] = -kW2 * y[0] - (s->u0_ + s->u1_ * tau);
    return 0;
  }
  std::size_t event_count(int) const override { return 0; }
  double event(std::size_t, double, const double*, int) const override { return 1.0; }
  assess::EventDirection event_direction(std::size_t, int) const override { return assess::EventDirection::falling; }
  assess::EventAction on_event(std::size_t, double, double*, int&) override { return assess::EventAction::proceed; }
  void on_step(double, const double*, const double*, double, const double*, const double*, int) override {}
  double next_breakpoint(double t) const override { return g_.next_breakpoint(t); }

 private:
  static constexpr double kW2 = 16.0 * 3.141592653589793 * 3.141592653589793;  // (2 pi 2 Hz)^2, 1/s^2
  const assess::GroundMotion& g_;
  double u0_ = 0.0, u1_ = 0.0;
};

}  // namespace

int main(int argc, char** argv) {
  using namespace assess;
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 50;
  RockingOptions opt;
  if (argc > 3) opt.rel_tol = std::atof(argv[2]), opt.abs_tol = std::atof(argv[3]);
  if (argc > 4) {
    const std::string s = argv[4];
    opt.stepper = s == "rkck" ? OdeStepper::rkck : s == "rkf45" ? OdeStepper::rkf45 : OdeStepper::rk8pd;
  }
  opt.scale = 0.2;
  const std::string root = data_dir();  // $ASSESS_DATA_DIR, the install prefix or the source tree
  const Record rec = read_record(root + "/spectra/records/RSN292_ITALY_A-STU270.AT2");
  const RockingModel model(RockingBody::rectangle(0.25, 3.0, 12.06 * units::kN), Foundation::winkler(1e9),
                           Sidedness::two_sided, Restitution::housner());

  // Wall-clock time and the process's CPU time (which a loaded machine
  // inflates less: time spent descheduled is not counted), best of N each.
  auto cpu_ms = [] {
    timespec ts{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
    return 1e3 * double(ts.tv_sec) + 1e-6 * double(ts.tv_nsec);
  };
  RockingResult r;
  double best = 1e300, best_cpu = 1e300;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    const double c0 = cpu_ms();
    r = analyse(model, rec, opt);
    const double c1 = cpu_ms();
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::milli>(t1 - t0).count());
    best_cpu = std::min(best_cpu, c1 - c0);
  }
  RockingOptions tight = opt;
  tight.rel_tol /= 1000.0;
  tight.abs_tol /= 1000.0;
  const RockingResult ref = analyse(model, rec, tight);
  RockingOptions independent = opt;  // rk8pd at 1e-12: a reference independent of the stepper under test
  independent.stepper = OdeStepper::rk8pd;
  independent.rel_tol = 1e-12;
  independent.abs_tol = 1e-14;
  const RockingResult ref8 = analyse(model, rec, independent);

  std::printf("bench_rocking: smooth block 2b=0.25 m 2h=3 m gamma=12.06 kN/m^3 k=1e6 kN/m^3, two-sided, Housner e\n");
  std::printf("record %s (%zu points, dt = %g s) x 0.2; rel_tol %g abs_tol %g\n", rec.name.c_str(), rec.size(), rec.dt,
              opt.rel_tol, opt.abs_tol);
  std::printf("time per analysis (best of %d): %.3f ms\n", repeats, best);
  std::printf("CPU time per analysis (best of %d): %.3f ms\n", repeats, best_cpu);
  std::printf("steps %ld (rejected %ld, event re-steps %ld), rhs evaluations %ld, impacts %ld\n", r.steps,
              r.rejected_steps, r.event_steps, r.rhs_evaluations, r.impacts);
  std::printf("theta_max %.10g rad (tight: %.10g rad, %ld rhs), relative difference %.3g\n", r.theta_max,
              ref.theta_max, ref.rhs_evaluations, std::fabs(r.theta_max - ref.theta_max) / ref.theta_max);
  std::printf("theta_max vs rk8pd at rel_tol 1e-12: relative difference %.3g\n",
              std::fabs(r.theta_max - ref8.theta_max) / ref8.theta_max);
  std::printf("impacts %ld, D/C %.6g, termination %s\n", r.impacts, r.dc, to_string(r.termination));

  // The floor: GSL rk8pd + the driver with the same steps and a trivial kernel.
  const GroundMotion g = GroundMotion::from_record(rec, opt.scale);
  HybridOdeOptions hopt;
  hopt.rel_tol = opt.rel_tol;
  hopt.abs_tol = opt.abs_tol;
  double best_floor = 1e300;
  HybridOdeResult hf;
  FloorSystem floor_sys(g);
  for (int i = 0; i < repeats; ++i) {
    double y[2] = {0.0, 0.0};
    const double c0 = cpu_ms();
    hf = integrate_hybrid(floor_sys, 0.0, r.t_end, y, 1, hopt);
    best_floor = std::min(best_floor, cpu_ms() - c0);
  }
  std::printf("integrator floor (rk8pd + driver, same record and t_end, trivial kernel, no events): CPU %.3f ms "
              "(best of %d), steps %ld\n",
              best_floor, repeats, hf.steps);
  return 0;
}
