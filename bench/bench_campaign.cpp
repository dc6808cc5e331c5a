// bench_campaign.cpp: the seed's §3.2 study with 100 realisations
// (4 walls x 4 records x 10 scales x 100 realisations x 2 models = 32,000
// analyses) on 2 threads: total seconds and analyses per second per core,
// plus the cost of each part of one analysis (single thread).
//
// Usage: bench_campaign [REALISATIONS=100] [THREADS=2]
// The campaign file is mechanisms/campaign-seed-3.2.json under data_dir().
#include <assess/campaign/campaign.hpp>
#include <assess/campaign/campaign_runner.hpp>
#include <assess/hazard/hazard.hpp>
#include <assess/records/response_spectrum.hpp>

#include <chrono>
#include <ctime>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <string>


namespace {

double seconds_since(std::chrono::steady_clock::time_point t0) {
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
}

}  // namespace

int main(int argc, char** argv) {
  using namespace assess;
  const int realisations = argc > 1 ? std::atoi(argv[1]) : 100;
  const unsigned threads = argc > 2 ? unsigned(std::atoi(argv[2])) : 2u;
  CampaignSpec spec = read_campaign(data_dir() + "/mechanisms/campaign-seed-3.2.json");
  spec.realisations = realisations;
  const Campaign campaign(spec);

  // Parts of one group, single thread: the applied record and its SDe(Ts), and
  // each model's rocking analysis, averaged over the walls, records and scales.
  {
    const auto t0 = std::chrono::steady_clock::now();
    long n = 0;
    for (std::size_t w = 0; w < spec.walls.size(); ++w)
      for (std::size_t r = 0; r < spec.records.size(); ++r)
        for (std::size_t s = 0; s < spec.scale_factors.size(); ++s, ++n) {
          const Record rec = campaign.applied_record(r, 1, spec.scale_factors[s]);
          volatile double sd = spectral_ordinates(rec, free_wall_capacity(spec.walls[w].b_m, spec.walls[w].h_m).Ts).SD;
          (void)sd;
        }
    std::printf("record + SDe(Ts) per group: %.3f ms\n", 1e3 * seconds_since(t0) / double(n));
    for (std::size_t m = 0; m < spec.models.size(); ++m) {
      const auto t1 = std::chrono::steady_clock::now();
      long k = 0;
      for (std::size_t w = 0; w < spec.walls.size(); ++w)
        for (std::size_t r = 0; r < spec.records.size(); ++r)
          for (std::size_t s = 0; s < spec.scale_factors.size(); ++s, ++k)
            analyse(campaign.model(w, 0, m), campaign.applied_record(r, 1, spec.scale_factors[s]), spec.rocking);
      std::printf("%s rocking analysis: %.3f ms (mean over %ld walls x records x scales)\n",
                  to_string(spec.models[m]), 1e3 * seconds_since(t1) / double(k), k);
    }
  }

  const std::string dir = (std::filesystem::temp_directory_path() / "assess_bench_campaign").string();
  std::filesystem::remove_all(dir);
  CampaignRunOptions o;
  o.threads = threads;
  const auto t0 = std::chrono::steady_clock::now();
  const std::clock_t c0 = std::clock();
  const CampaignRunSummary s = run_campaign(campaign, dir, o);
  const double total = seconds_since(t0);
  // Process CPU time over all threads: on a machine shared with other jobs the
  // wall-clock rate drops, the rate per CPU-second much less.
  const double cpu = double(std::clock() - c0) / CLOCKS_PER_SEC;
  std::printf("seed study: %llu analyses (%d realisations) on %u threads in %.2f s: %.0f analyses/s, "
              "%.0f analyses/s/core, %llu failed (target < 30 s for 32,000)\n",
              (unsigned long long)s.run, realisations, threads, total, double(s.run) / total,
              double(s.run) / total / threads, (unsigned long long)s.failed);
  std::printf("CPU time %.2f s: %.0f analyses per CPU-second, %.3f ms CPU per analysis; "
              "on %u idle cores: %.1f s expected\n",
              cpu, double(s.run) / cpu, 1e3 * cpu / double(s.run), threads, cpu / threads);
  std::filesystem::remove_all(dir);
  return 0;
}
