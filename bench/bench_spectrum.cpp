// bench_spectrum: hazard grid load time and one site lookup + full spectrum.
// Targets (issue 2): grid load < 50 ms; lookup + spectrum < 10 us.
// Usage: bench_spectrum [grid.csv]
#include <assess/hazard/hazard.hpp>
#include <assess/hazard/spectrum.hpp>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <random>
#include <string>

int main(int argc, char** argv) {
  using clock = std::chrono::steady_clock;
  const std::string path = argc > 1 ? argv[1] : assess::data_dir() + "/spectra/ntc2008_hazard_grid.csv";
  double best_load_ms = 1e300;
  assess::HazardGrid grid = assess::HazardGrid::load(path);
  for (int rep = 0; rep < 5; ++rep) {
    const auto t0 = clock::now();
    grid = assess::HazardGrid::load(path);
    best_load_ms = std::min(best_load_ms, std::chrono::duration<double, std::milli>(clock::now() - t0).count());
  }
  // Random sites inside random grid cells (a point between a node and its
  // south-east neighbour), screened once so the timed loop never throws.
  std::mt19937 rng(42);
  std::uniform_int_distribution<int> id(4977, 52085);
  std::uniform_real_distribution<double> f(0.05, 0.95);
  constexpr int n_sites = 200000;
  std::vector<std::pair<double, double>> sites;
  while (int(sites.size()) < n_sites) {
    const assess::HazardNode* a = grid.node(id(rng));
    const assess::HazardNode* b = a ? grid.node(a->id + 223) : nullptr;
    if (!b) continue;
    const double t = f(rng), la = a->lat + t * (b->lat - a->lat), lo = a->lon + f(rng) * (b->lon - a->lon);
    try {
      grid.cell_nodes(la, lo);
      sites.emplace_back(la, lo);
    } catch (const std::exception&) {
    }
  }
  const double periods[] = {0.0, 0.1, 0.2, 0.3, 0.4, 0.5, 0.75, 1.0, 1.25, 1.5, 2.0, 2.5, 3.0, 3.5, 4.0, 5.0};
  double sink = 0.0;
  const auto t0 = clock::now();
  for (const auto& [la, lo] : sites) {
    const assess::HazardParams h = grid.at(la, lo, 474.5611);
    const assess::ElasticSpectrum s(h, {assess::SoilClass::C, assess::Topography::T1, 1.0}, 5.0);
    for (double T : periods) sink += s.Se(T) + s.SDe(T);
  }
  const double us = std::chrono::duration<double, std::micro>(clock::now() - t0).count() / n_sites;
  std::printf("grid load (10751 nodes, best of 5): %.2f ms   [target < 50 ms]\n", best_load_ms);
  std::printf("lookup + spectrum (16 periods Se and SDe), mean of %d sites: %.3f us   [target < 10 us]\n", n_sites, us);
  std::printf("(checksum %.6g)\n", sink);
  return 0;
}
