// bench_docx: the Word writer (issue 36, item 7) on a building's relazione:
// the case assessed once as `assess run --docx` does (histories and review),
// its two documents built, then each written to .docx bytes (docx_bytes) in a
// fresh process (fresh_process.hpp: libzip, librsvg and fontconfig loaded and
// initialised by the work, as in one command), CPU (every thread) and wall
// time, best of N, with the figures and the size. Budget: well under 2 CPU-s
// for the house's two documents (through pandoc and rsvg-convert: 11.6 s).
// Usage: bench_docx [N=3] [BUILDING.json]
#include "fresh_process.hpp"

#include <assess/assessment/building_assessment.hpp>
#include <assess/hazard/hazard.hpp>
#include <assess/report/building_report.hpp>
#include <assess/report/docx_writer.hpp>
#include <assess/support/json_input.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <variant>

namespace {

std::size_t pictures(const std::vector<assess::DocBlock>& blocks) {
  std::size_t n = 0;
  for (const assess::DocBlock& b : blocks) {
    if (const auto* f = std::get_if<assess::Figure>(&b.value)) n += f->panels.size();
    if (const auto* x = std::get_if<assess::Box>(&b.value)) n += pictures(x->content);
  }
  return n;
}

}  // namespace

int main(int argc, char** argv) {
  using namespace assess;
  const int n = argc > 1 ? std::max(1, std::atoi(argv[1])) : 3;
  const std::string file = argc > 2 ? argv[2] : data_dir() + "/mechanisms/building-house.json";
  FacadeOptions o;
  o.histories = true;
  o.review = true;
  o.review_records = true;
  const BuildingAssessment a = assess_building(parse_building(read_json_file(file, input_kinds::case_file), file), o);
  ReportOptions ro;
  ro.lang = Lang::it;
  const Relazione r = building_relazione(a, ro);
  const Document* docs[2] = {&r.body, &r.tabulati};
  for (const Document* d : docs) {
    std::printf("%s: %zu pictures\n", d->title.c_str(), pictures(d->blocks));
    const bench::BestTime best = bench::best_of_fresh_processes(n, [&](int i) {
      const std::string bytes = docx_bytes(*d);
      if (i == 0) std::printf("  %.2f MB\n", double(bytes.size()) / 1e6);
      return 0;
    }, true);
    if (!best.ok) return 1;
    std::printf("  best of %d fresh processes: CPU %.3f s, wall %.3f s\n", n, best.cpu_s, best.wall_s);
  }
}
