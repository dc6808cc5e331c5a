// bench_chain.cpp: kinematic analysis of large chains (issue 10, defect 13).
//  1. A 1-DOF stack of N blocks (default 200): a free wall 0.5 m thick and
//     10 m tall cut into N courses, each joined to the next by two hinges at
//     the corners of their interface (a rigid joint: 4 equations for 3 relative
//     coordinates, so the constraints are redundant) and to the ground by a
//     hinge at the outer toe. It is one rigid block: alpha0 = t / H = 0.05
//     (closed form of a free-standing wall, C8A.4.1), printed with its error.
//  2. The shipped 24-slice gable (mechanisms/gable.json).
// Prints the best wall-clock time of `repeats` analyses of each.
// Targets (issue 10): stack of 200 <= 2 s, gable <= 50 ms.
// Usage: bench_chain [blocks] [repeats]
#include <assess/assessment/case_file.hpp>
#include <assess/hazard/hazard.hpp>
#include <assess/kinematic/chain.hpp>
#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/support/units.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace assess;

Chain stack(int n, double t, double H) {
  std::vector<Block> blocks;
  std::vector<Constraint> cons;
  const double h = H / n;
  for (int i = 0; i < n; ++i) {
    Block b;
    b.name = "course " + std::to_string(i);
    b.polygon = {{-t, i * h}, {0.0, i * h}, {0.0, (i + 1) * h}, {-t, (i + 1) * h}};
    b.unit_weight = 18.0 * units::kN;
    b.length = 1.0;
    blocks.push_back(b);
  }
  Constraint g;
  g.type = ConstraintType::GroundHinge;
  g.block = 0;
  g.point = {0.0, 0.0};  // outer toe (x = 0 is the outer face, the wall is at x < 0)
  cons.push_back(g);
  for (int i = 0; i + 1 < n; ++i)
    for (double x : {-t, 0.0}) {
      Constraint c;
      c.type = ConstraintType::Hinge;
      c.block = i;
      c.other = i + 1;
      c.point = {x, (i + 1) * h};
      cons.push_back(c);
    }
  return Chain(blocks, cons, {});
}

template <class F>
double best_ms(int repeats, F&& f) {
  double best = 1e300;
  for (int i = 0; i < repeats; ++i) {
    const auto t0 = std::chrono::steady_clock::now();
    f();
    best = std::min(best, std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count());
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::atoi(argv[1]) : 200;
  const int repeats = argc > 2 ? std::atoi(argv[2]) : 3;
  const double t = 0.5, H = 10.0;

  const double ms_build = best_ms(1, [&] { (void)stack(n, t, H); });
  std::printf("stack of %d blocks: building the chain (1-DOF check, SVD) %.1f ms\n", n, ms_build);
  KinematicResult r;
  const double ms_stack = best_ms(repeats, [&] { r = analyse_kinematic(stack(n, t, H)); });
  std::printf("stack of %d blocks (1 DOF, %d redundant equations): %.1f ms (target <= 2000 ms)\n", n, n - 1,
              ms_stack);
  std::printf("  alpha0 = %.15g (closed form t/H = %.15g, error %.2e), dk0 = %.6g m, curve %s\n", r.alpha0, t / H,
              std::fabs(r.alpha0 - t / H), r.dk0, to_string(r.termination).c_str());

  const CaseFile gable = read_case_file(data_dir() + "/mechanisms/gable.json");
  KinematicCaseResult g;
  const double ms_gable = best_ms(std::max(repeats, 5), [&] {
    g = KinematicCaseResult{};
    for (const MechanismCandidate& m : gable.mechanism.candidates)
      g.candidates.push_back({m.label, m.parameter, m.Z, analyse_kinematic(m.chain, gable.options)});
  });
  std::printf("gable (mechanisms/gable.json, %zu blocks): %.2f ms (target <= 50 ms), alpha0 = %.9g\n",
              gable.mechanism.candidates.front().chain.blocks().size(), ms_gable,
              g.candidates.front().result.alpha0);
  return 0;
}
