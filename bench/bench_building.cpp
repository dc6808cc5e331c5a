// bench_building: the example building end to end as `assess run
// mechanisms/building-house.json` computes it (parse and expansion with the
// kinematic pre-pass of the shared selection, then every mechanism in
// parallel: kinematic checks, record selection, dynamic analyses; safety
// indices; no report), wall and CPU time, best of N. Issue 22 budget: <= 10 s
// wall on 2 cores. Usage: bench_building [N=3] [BUILDING.json]
#include <assess/assessment/building_assessment.hpp>
#include <assess/hazard/hazard.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <string>

int main(int argc, char** argv) {
  using namespace assess;
  const int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const std::string file = argc > 2 ? argv[2] : data_dir() + "/mechanisms/building-house.json";
  FacadeOptions o;
  o.histories = false;
  double best_cpu = 1e300, best_wall = 1e300, best_parse = 1e300;
  std::size_t mechanisms = 0, analyses = 0;
  for (int i = 0; i < n; ++i) {
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    BuildingCase b = read_building_file(file);
    const double parse = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const BuildingAssessment a = assess_building(std::move(b), o);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    best_cpu = std::min(best_cpu, cpu);
    best_wall = std::min(best_wall, wall);
    best_parse = std::min(best_parse, parse);
    mechanisms = a.results.size();
    analyses = 0;
    for (const BuildingMechanismResult& r : a.results) analyses += r.a.runs.size();
  }
  std::printf("building run: %zu mechanisms, %zu dynamic analyses; best of %d: wall %.3f s (parse and pre-pass "
              "%.3f s), CPU %.3f s (all threads)\n",
              mechanisms, analyses, n, best_wall, best_parse, best_cpu);
}
