// bench_flexure.cpp: a horizontal flexure at its caps (issue 39, class 9):
// tests/data/hostile/flexure_caps.json, 20 strips of 6 openings, 200 search
// points per strip. Prints the best CPU time (std::clock: the machine is
// shared, its wall-clock time varies with the load) of `repeats` runs of
//  1. the candidates (the middle hinge's search in closed form, one chain per strip);
//  2. the whole kinematic case (the candidates and their kinematic analyses);
//  3. the search alone, one strip: alpha0 in closed form (strip_alpha0) and by a
//     chain analysis per point (the search before issue 39), at the same points.
// Target: the whole case within 0.5 s of CPU (docs/reliability.md, "Round five").
// Usage: bench_flexure [repeats]
#include <assess/assessment/case_file.hpp>
#include <assess/kinematic/horizontal_flexure.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>
#include <assess/support/units.hpp>

#include <algorithm>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <string>

namespace {

using namespace assess;

template <typename F>
double best_ms(int repeats, F&& f) {
  double best = 1e300;
  for (int i = 0; i < repeats; ++i) {
    const std::clock_t t0 = std::clock();
    f();
    best = std::min(best, 1e3 * double(std::clock() - t0) / CLOCKS_PER_SEC);
  }
  return best;
}

}  // namespace

int main(int argc, char** argv) {
  const int repeats = argc > 1 ? std::atoi(argv[1]) : 3;
  const std::string path = data_dir() + "/tests/data/hostile/flexure_caps.json";
  const CaseFile kase = read_case_file(path);
  std::size_t n = 0;
  const double ms_candidates = best_ms(repeats, [&] { n = read_case_file(path).mechanism.candidates.size(); });
  const double ms_case = best_ms(repeats, [&] { run_kinematic_case(kase); });
  std::printf("horizontal flexure at its caps (%zu strips of 6 openings, 200 search points):\n", n);
  std::printf("  candidates (search in closed form, a chain per strip)  %8.1f ms\n", ms_candidates);
  std::printf("  whole kinematic case (with the analyses)              %8.1f ms   (target 500 ms of CPU)\n", ms_case);

  // One strip's search: the same 206 points by (1.3) and by a chain analysis each.
  HorizontalFlexureParams p;
  p.span = 6.0, p.thickness = 0.45, p.unit_weight = 18.0 * units::kN, p.strength = 2.0e6, p.tie = 40e3;
  HorizontalStrip s;
  s.height = 0.1;
  for (int j = 0; j < 6; ++j) s.openings.push_back({0.1 + 0.9 * j, 0.1 + 0.9 * j + 0.45, 0.01 + 0.012 * j});
  p.strips = {s};
  std::vector<double> points;
  for (int i = 1; i <= 200; ++i) points.push_back(p.span * i / 201.0);
  double sum = 0.0;
  const double ms_closed = best_ms(repeats, [&] {
    for (double um : points) sum += strip_alpha0(p, s, um);
  });
  const double ms_chain = best_ms(repeats, [&] {
    for (double um : points) {
      HorizontalFlexureParams q = p;
      q.strips[0].middle_hinge = um;
      sum += activation_multiplier(horizontal_flexure(q).candidates.front().chain);
    }
  });
  std::printf("  one strip's search, 200 points: closed form %.3f ms, a chain analysis each %.1f ms (x%.0f)\n",
              ms_closed, ms_chain, ms_chain / std::max(ms_closed, 1e-6));
  return sum > 0.0 ? 0 : 1;
}
