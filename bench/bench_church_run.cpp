// bench_church_run: the church façade assessment end to end as `assess run`
// computes it (kinematic analysis, record selection, 21 dynamic analyses;
// no report), CPU time per run (both threads) and wall time, best of N.
// Issue 21 budget: <= 1.5x the CPU time before every record was integrated
// to its last sample. Usage: bench_church_run [N=5]
#include <assess/assessment/case_file.hpp>
#include <assess/assessment/facade_assessment.hpp>
#include <assess/hazard/hazard.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <ctime>
#include <cstdlib>

int main(int argc, char** argv) {
  using namespace assess;
  const int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const CaseFile c = read_case_file(data_dir() + "/mechanisms/church-facade.json");
  FacadeOptions o;
  o.histories = false;
  double best_cpu = 1e300, best_wall = 1e300, integrated = 0.0;
  std::size_t runs = 0;
  for (int i = 0; i < n; ++i) {
    const std::clock_t c0 = std::clock();
    const auto t0 = std::chrono::steady_clock::now();
    const FacadeAssessment a = assess_facade(c, o);
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
    best_cpu = std::min(best_cpu, cpu);
    best_wall = std::min(best_wall, wall);
    runs = a.runs.size();
    integrated = 0.0;
    for (const DynamicRun& r : a.runs) integrated += r.result.t_end;
  }
  std::printf("church run: %zu analyses, %.1f s integrated in total; best of %d: CPU %.3f s, wall %.3f s\n", runs,
              integrated, n, best_cpu, best_wall);
}
