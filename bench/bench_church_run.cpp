// bench_church_run: one case (default the church façade) end to end as
// `assess run CASE --json` computes it (kinematic analysis, record selection,
// the dynamic analyses of every candidate that needs them; no report), each
// run in a fresh process (fresh_process.hpp), CPU time (every thread) and wall
// time, best of N. Budgets: issue 21, <= 1.5x the CPU time before every record
// was integrated to its last sample; issue 32, vertical flexure with dynamics
// (mechanisms/vertical_flexure_dynamic.json) <= 1.0 s CPU.
// Usage: bench_church_run [N=5] [CASE.json]
#include "fresh_process.hpp"

#include <assess/assessment/case_file.hpp>
#include <assess/assessment/facade_assessment.hpp>
#include <assess/hazard/hazard.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  using namespace assess;
  const int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 5;
  const std::string file = argc > 2 ? argv[2] : data_dir() + "/mechanisms/church-facade.json";
  const bench::BestTime best = bench::best_of_fresh_processes(n, [&](int i) {
    FacadeOptions o;
    o.histories = false;
    const FacadeAssessment a = assess_facade(read_case_file(file), o);
    std::size_t runs = a.dynamics.runs.size();
    double integrated = 0.0;
    for (const DynamicRun& r : a.dynamics.runs) integrated += r.result.t_end;
    for (const FacadeAssessment& s : a.other_dynamics) {
      runs += s.dynamics.runs.size();
      for (const DynamicRun& r : s.dynamics.runs) integrated += r.result.t_end;
    }
    if (i == 0)
      std::printf("%s: %zu analyses (%zu other candidates), %.1f s integrated in total\n", file.c_str(), runs,
                  a.other_dynamics.size(), integrated);
    return 0;
  }, false);
  if (!best.ok) return 1;
  std::printf("best of %d fresh processes: CPU %.3f s (all threads), wall %.3f s\n", n, best.cpu_s, best.wall_s);
}
