// bench_rocking.cpp: one smooth-block analysis of the benchmark
// (2b = 0.25 m, 2h = 3 m, 12.06 kN/m^3, k = 1e6 kN/m^3, two-sided, Housner e)
// under the Sturno E-W record (RSN292_ITALY_A-STU270.AT2) at scale 0.2.
// Prints ms per analysis (best of N repeats), steps and right-hand-side
// evaluations per analysis, and theta_max against a run at 1000x tighter
// tolerances. Usage: bench_rocking [repeats] [rel_tol abs_tol] [stepper]
#include <assess/hazard/hazard.hpp>
#include <assess/records/record_io.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/support/units.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

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

  RockingResult r;
  double best = 1e300;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    r = analyse(model, rec, opt);
    const auto t1 = std::chrono::steady_clock::now();
    best = std::min(best, std::chrono::duration<double, std::milli>(t1 - t0).count());
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
  std::printf("steps %ld (rejected %ld, event re-steps %ld), rhs evaluations %ld, impacts %ld\n", r.steps,
              r.rejected_steps, r.event_steps, r.rhs_evaluations, r.impacts);
  std::printf("theta_max %.10g rad (tight: %.10g rad, %ld rhs), relative difference %.3g\n", r.theta_max,
              ref.theta_max, ref.rhs_evaluations, std::fabs(r.theta_max - ref.theta_max) / ref.theta_max);
  std::printf("theta_max vs rk8pd at rel_tol 1e-12: relative difference %.3g\n",
              std::fabs(r.theta_max - ref8.theta_max) / ref8.theta_max);
  std::printf("impacts %ld, D/C %.6g, termination %s\n", r.impacts, r.dc, to_string(r.termination));
  return 0;
}
