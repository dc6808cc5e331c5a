// bench_building: a building end to end as `assess run BUILDING.json --json`
// computes it (parse and expansion with the kinematic pre-pass of the shared
// selection, then every mechanism in parallel: kinematic checks, record
// selection, dynamic analyses; safety indices; no report), each run in a
// fresh process (fresh_process.hpp: nothing read before it, as one command),
// wall and CPU time (every thread), best of N. Budgets: issue 22, <= 10 s wall
// on 2 cores; issue 32, <= 1.0 s CPU for the house and for the four-mechanism
// church of tests/cli/building/chiesa_piccola.json; 60 mechanisms sharing one
// selection "must not take minutes" (the house's walls repeated, --repeat 8:
// 64 mechanisms).
// Usage: bench_building [N=3] [BUILDING.json] [--repeat K]
#include "fresh_process.hpp"

#include <assess/assessment/building_assessment.hpp>
#include <assess/hazard/hazard.hpp>

#include <nlohmann/json.hpp>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <cstdlib>
#include <string>

int main(int argc, char** argv) {
  using namespace assess;
  const int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const std::string file = argc > 2 && std::strncmp(argv[2], "--", 2) != 0 ? argv[2]
                                                                           : data_dir() + "/mechanisms/building-house.json";
  int repeat = 1;
  for (int i = 1; i + 1 < argc; ++i)
    if (std::strcmp(argv[i], "--repeat") == 0) repeat = std::max(1, std::atoi(argv[i + 1]));
  // The building's walls repeated K times (each mechanism renamed): K times as
  // many mechanisms, the same shared selection.
  nlohmann::json doc;
  {
    std::ifstream in(file);
    doc = nlohmann::json::parse(in);
    const nlohmann::json walls = doc.at("walls");
    doc["walls"] = nlohmann::json::array();
    for (int k = 0; k < repeat; ++k)
      for (nlohmann::json w : walls) {
        w["name"] = w.value("name", std::string("wall")) + (repeat > 1 ? " #" + std::to_string(k + 1) : "");
        for (auto& m : w.at("mechanisms"))
          m["name"] = m.value("name", std::string("mechanism")) + (repeat > 1 ? " #" + std::to_string(k + 1) : "");
        doc["walls"].push_back(w);
      }
  }
  const bench::BestTime best = bench::best_of_fresh_processes(n, [&](int i) {
    FacadeOptions o;
    o.histories = false;
    const BuildingAssessment a = assess_building(parse_building(doc, file), o);
    std::size_t analyses = 0, dynamic = 0;
    for (const BuildingMechanismResult& r : a.results) analyses += r.a.dynamics.runs.size(), dynamic += !r.a.dynamics.runs.empty();
    if (i == 0)
      std::printf("%s: %zu mechanisms (%zu with dynamic analyses), %zu dynamic analyses\n", file.c_str(),
                  a.results.size(), dynamic, analyses);
    return 0;
  }, true);
  if (!best.ok) return 1;
  std::printf("best of %d fresh processes: CPU %.3f s (all threads), wall %.3f s\n", n, best.cpu_s, best.wall_s);
}
