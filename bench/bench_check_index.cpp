// bench_check_index: the cost of the safety index of a check (issue 41:
// kinematic/check_index.hpp, the return period at which the check reaches
// D/C = 1, found by a scan of the return-period axis and Brent), per check and
// per case: the kinematic checks of a case with and without their indices.
// Usage: bench_check_index [N=20] [CASE.json]   (default: the church façade)
#include <assess/assessment/case_file.hpp>
#include <assess/hazard/hazard.hpp>
#include <assess/kinematic/check_index.hpp>
#include <assess/kinematic/code_checks.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  using namespace assess;
  using clock = std::chrono::steady_clock;
  const int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 20;
  const std::string file = argc > 2 ? argv[2] : data_dir() + "/mechanisms/church-facade.json";
  const CaseFile c = read_case_file(file);
  const KinematicCaseResult k = run_kinematic_case(c);  // the site and the grid loaded once
  const Site site(*c.site);
  const HazardAxis axis = [&site](double tr) { return site.hazard_extrapolated(tr); };
  std::size_t rows = 0;
  for (const CandidateResult& cr : k.candidates) rows += cr.checks.size();
  double best_index = 1e300, best_case = 1e300;
  for (int it = 0; it < n; ++it) {
    const auto t0 = clock::now();
    for (const CandidateResult& cr : k.candidates) {
      CheckInput in = *k.check_input;
      in.Z = cr.Z;
      for (const CheckRow& r : cr.checks) (void)check_index(cr.result, in, r, axis);
    }
    const auto t1 = clock::now();
    (void)run_kinematic_case(c);
    const auto t2 = clock::now();
    best_index = std::min(best_index, std::chrono::duration<double>(t1 - t0).count());
    best_case = std::min(best_case, std::chrono::duration<double>(t2 - t1).count());
  }
  std::printf("%s: %zu candidates, %zu checks\n", file.c_str(), k.candidates.size(), rows);
  std::printf("indices of every check: %.3f ms (%.1f us per check), best of %d\n", best_index * 1e3,
              best_index * 1e6 / double(std::max<std::size_t>(rows, 1)), n);
  std::printf("run_kinematic_case with the indices: %.3f ms\n", best_case * 1e3);
  return 0;
}
