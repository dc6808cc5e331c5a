// bench_selection: the church façade selection (soil C, 1.37-4.0 s) with the
// full record library (issues 12, 30, 32), each measurement in a fresh
// process (fresh_process.hpp), best of N:
//   1. the library opened (catalogue.json parsed, spectra.bin read and
//      checked against it) and nothing else;
//   2. the selection as `assess run` makes it: library opened, precomputed
//      spectra interpolated at the check periods, the search;
//   3. the same selection with every candidate's spectrum integrated (a
//      library without spectra.bin: the cost before issue 30, on today's
//      library), files read on all cores;
//   4. the selection asked again in the same process (the memo: what every
//      other mechanism or candidate sharing it pays).
// Usage: bench_selection [N=3]
#include "fresh_process.hpp"

#include <assess/assessment/case_file.hpp>
#include <assess/hazard/hazard.hpp>
#include <assess/hazard/site.hpp>
#include <assess/records/library_selection.hpp>
#include <assess/records/record_library.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>

using namespace assess;

namespace {

struct Church {
  ElasticSpectrum slv;
  PeriodRange range;
};

Church church() {
  const CaseFile c = read_case_file(data_dir() + "/mechanisms/church-facade.json");
  const KinematicCaseResult k = run_kinematic_case(c);
  const KinematicResult& kin = k.candidates[k.governing].result;
  return {Site(*c.site).spectrum(LimitState::SLV),
          rocking_period_range(std::min(kin.Ts, kin.T_SLV), std::max(kin.Ts, kin.T_SLV))};
}

std::shared_ptr<const LibrarySelection> select(const RecordLibrary& lib, const Church& ch) {
  LibrarySelectionRules rules;
  rules.filters.site_classes = {"C"};
  SelectionOptions so;
  so.range = ch.range;
  return select_from_library(lib, rules, [&ch](double T) { return ch.slv.Se(T); }, so);
}

double cpu_now() {
  struct rusage ru {};
  getrusage(RUSAGE_SELF, &ru);
  return double(ru.ru_utime.tv_sec + ru.ru_stime.tv_sec) + 1e-6 * double(ru.ru_utime.tv_usec + ru.ru_stime.tv_usec);
}

}  // namespace

int main(int argc, char** argv) {
  const int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const std::string catalogue = data_dir() + "/spectra/records/catalogue.json";
  auto best = [n](const char* what, auto&& work) {
    // The church's spectrum and range are computed in the child too; they are
    // timed apart and subtracted (the measured work is what follows them).
    const bench::BestTime t = bench::best_of_fresh_processes(n, [&](int i) { return work(i == 0); }, false);
    if (!t.ok) std::exit(1);
    std::printf("%-62s CPU %8.1f ms, wall %8.1f ms (best of %d processes)\n", what, 1e3 * t.cpu_s, 1e3 * t.wall_s, n);
  };
  best("process start, church kinematics and site spectrum only", [&](bool) {
    church();
    return 0;
  });
  best("  + library opened (catalogue.json, spectra.bin checked)", [&](bool first) {
    church();
    const auto lib = RecordLibrary::open(catalogue);
    if (first)
      std::printf("library: %zu components, %zu precomputed spectra at %zu periods%s%s\n",
                  lib->catalogue().entries.size(), lib->spectra() ? lib->spectra()->ids.size() : 0,
                  lib->spectra() ? lib->spectra()->periods.size() : 0, lib->spectra() ? "" : ": ",
                  lib->spectra_problem().c_str());
    return lib->spectra() ? 0 : 1;
  });
  best("  + selection from the precomputed spectra (as assess run)", [&](bool first) {
    const Church ch = church();
    const auto sel = select(*RecordLibrary::open(catalogue), ch);
    if (first)
      std::printf("selection: %zu candidates, %zu eligible, %.0f sets examined, spectra %s; %s\n",
                  sel->candidates.size(), sel->result.eligible, sel->result.combinations, sel->spectra_source.c_str(),
                  sel->result.message.c_str());
    return sel->result.status == SelectionResult::Status::Compatible ? 0 : 1;
  });
  best("  + selection with every candidate's spectrum integrated", [&](bool first) {
    const Church ch = church();
    RecordCatalogue cat = RecordLibrary::open(catalogue)->catalogue();
    cat.text_hash = 0;  // held in memory: no spectra.bin
    const RecordLibrary integrated(cat);
    const auto sel = select(integrated, ch);
    if (first) std::printf("integrated: %s; %s\n", sel->spectra_source.c_str(), sel->result.message.c_str());
    return sel->result.status == SelectionResult::Status::Compatible ? 0 : 1;
  });
  // The memo: the same selection asked again in one process.
  bench::in_fresh_process([&] {
    const Church ch = church();
    const auto lib = RecordLibrary::open(catalogue);
    select(*lib, ch);
    const double c0 = cpu_now();
    const auto t0 = std::chrono::steady_clock::now();
    constexpr int asks = 60;  // e.g. 60 mechanisms sharing one selection
    for (int i = 0; i < asks; ++i) select(*RecordLibrary::open(catalogue), ch);
    const double cpu = cpu_now() - c0;
    const double wall = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
    const SelectionMemoStats s = selection_memo_stats();
    std::printf("the same selection asked %d more times: CPU %.2f ms, wall %.2f ms in all (computed %zu, reused %zu)\n",
                asks, 1e3 * cpu, 1e3 * wall, s.computed, s.reused);
    return 0;
  });
  return 0;
}
