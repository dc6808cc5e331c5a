// cmd_fragility.cpp: `assess fragility CASE.json [--stripes TR,...] [--ida]
// [--out DIR] [--json]`: fragility curves of the case's governing mechanism
// by multiple-stripe analysis (or IDA) through the campaign runner (all
// cores, resumable, MPI ranks under mpirun), the lognormal fits and the
// annual risk of overturning on the site's hazard curve (docs/user/fragility.md).
#include "commands.hpp"

#include <assess/assessment/building_assessment.hpp>
#include <assess/assessment/case_file.hpp>
#include <assess/support/json_input.hpp>
#include <assess/campaign/campaign_runner.hpp>
#include <assess/hazard/seismic_action.hpp>
#include <assess/report/plot.hpp>
#include <assess/risk/fragility_case.hpp>
#include <assess/risk/fragility_job.hpp>
#include <assess/risk/fragility_report.hpp>
#include <assess/risk/fragility_result.hpp>
#include <assess/risk/fragility_study.hpp>
#include <assess/support/error.hpp>
#include <assess/support/number_rules.hpp>
#include <assess/support/termination.hpp>
#include <assess/support/units.hpp>

#include <atomic>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <sstream>
#include <optional>
#include <string>

#include "mpi_session.hpp"

namespace assess::cli {

namespace {

struct FragilityArgs {
  std::string file, out, stripes, ida_levels, mechanism;
  bool ida = false, json = false, resume = false, quiet = false, no_plots = false;
  unsigned threads = 0;
  int records = 0, bootstrap = 500;
  std::uint64_t seed = 1;
};

// Set by the first SIGINT/SIGTERM (support/termination.hpp): the analyses
// under way finish and are written; --resume continues.
std::atomic<bool> g_cancel{false};

void run(const FragilityArgs& a) {
  // MPI only when launched by mpirun, loaded at run time (mpi_session.hpp).
  const MpiSession mpi;
  const int rank = mpi.rank(), ranks = mpi.size();
  FragilityOptions fo;
  fo.method = a.ida ? FragilityMethod::ida : FragilityMethod::stripes;
  if (!a.stripes.empty()) {
    if (a.ida) throw InputError("--stripes: not with --ida (IDA levels are given by --ida-levels)");
    static const NumberRule stripe{"years", tr_min_years, tr_max_years, false, false, "the range of the hazard data"};
    fo.return_periods = parse_number_list(a.stripes, "--stripes", stripe);
  }
  if (!a.ida_levels.empty()) {
    if (!a.ida) throw InputError("--ida-levels: only with --ida");
    static const NumberRule level{"g", 0.0, 10.0, true, false, "a PGA above 0 and at most 10 g"};
    for (double g : parse_number_list(a.ida_levels, "--ida-levels", level)) fo.ida_levels.push_back(g * units::g);
  }
  fo.records = a.records;
  fo.bootstrap = a.bootstrap;
  fo.seed = a.seed;
  const nlohmann::json doc = read_json_file(a.file, input_kinds::case_file);
  // The mechanism studied (risk/fragility_case.hpp): a building case's named
  // or governing one (issue 22; docs/user/building.md, "Fragility").
  const FragilityCase fc = fragility_case(doc, a.file, a.mechanism);
  if (!fc.note.empty() && !a.quiet && rank == 0) std::cerr << "assess fragility: " << fc.note << "\n";
  const FragilityStudy study = prepare_case_fragility(fc, fo);
  const FragilityJob job(study);
  const std::string out = a.out.empty() ? fc.default_out : a.out;

  CampaignRunOptions o;
  o.threads = a.threads ? a.threads : (ranks > 1 ? 1u : 0u);
  o.resume = a.resume;
  o.part = rank;
  o.parts = ranks;
  o.cancel = &g_cancel;
  set_interrupt_flag(&g_cancel);
  if (!a.quiet && rank == 0)
    std::cerr << "assess fragility: " << study.stripes.size() << " levels, " << job.size() << " analyses";
  std::string error;
  CampaignRunSummary s;
  try {
    s = run_campaign_job(job, out, o);
  } catch (const InputError& e) {
    error = e.what();
  }
  if (mpi.active()) {
    const int any = mpi.max_over_ranks(error.empty() ? 0 : 1);
    if (any && error.empty()) error = "another MPI rank failed (see its message)";
    s.interrupted = mpi.max_over_ranks(s.interrupted ? 1 : 0) != 0;
    s.seconds = mpi.max_to_root(s.seconds);
  }
  if (!a.quiet && rank == 0) std::cerr << (error.empty() ? ", done in " + std::to_string(s.seconds) + " s\n" : "\n");
  if (!error.empty()) throw InputError(error);
  if (s.interrupted)
    throw InputError("fragility interrupted: the finished analyses are in " + out +
                     "; run the same command with --resume to continue");
  if (rank != 0) return;
  if (ranks > 1) {
    std::vector<std::string> parts;
    for (int r = 0; r < ranks; ++r) parts.push_back(campaign_part_path(out, r, ranks));
    merge_campaign_job_parts(job, parts, campaign_part_path(out, 0, 1));
    for (const auto& p : parts) std::filesystem::remove(p);
  }
  const FragilityResult result = fit_fragility(study, read_fragility_csv(campaign_part_path(out, 0, 1)));
  const bool plots = !a.no_plots;
  const FragilityReportFiles files = write_fragility_report(study, result, out, plots);
  if (a.json) {
    std::cout << fragility_to_json(study, result).dump(2) << "\n";
    return;
  }
  std::cout << fragility_text(study, result);
  if (ranks > 1) std::cout << "run on " << ranks << " MPI ranks\n";
  std::cout << "results: " << campaign_part_path(out, 0, 1) << "\nsummary: " << files.summary
            << "\ncurves:  " << files.curves_csv << "\nreport:  " << files.html << "\n";
}

}  // namespace

void add_fragility_command(CLI::App& app) {
  auto a = std::make_shared<FragilityArgs>();
  auto* cmd = app.add_subcommand(
      "fragility",
      "Fragility curves of the case's mechanism (multiple-stripe analysis or IDA with the record catalogue) and the "
      "annual risk of overturning at the site; all cores, resumable, MPI-aware");
  cmd->add_option("case", a->file, "case file (JSON) with a site and a dynamic section, or a building case")->required();
  cmd->add_option("--mechanism", a->mechanism,
                  "building case: the mechanism (id M1, M2, ... or its name; default: the governing one)");
  cmd->add_option("--stripes", a->stripes,
                  "return periods of the stripes, comma-separated (years, in [30, 2475]; default the nine of the "
                  "hazard grid)");
  cmd->add_flag("--ida", a->ida, "incremental dynamic analysis: one record set scaled to each PGA level");
  cmd->add_option("--ida-levels", a->ida_levels,
                  "PGA levels of the IDA, comma-separated (g; default 16 from half the 30-year to 3x the 2475-year PGA)");
  // Every number option with its range and reason (FragilityOptions::validate's, one place each).
  static const NumberRule records{"records", 1.0, 1000.0, false, false,
                                  "records per stripe; leave --records out for the case's select/count"};
  static const NumberRule bootstrap{"replicates", 0.0, 100000.0, false, false, "0 = no bounds"};
  with_rule(cmd->add_option("--records", a->records, "records per stripe (default: the case's select/count, 7)"), records);
  with_rule(cmd->add_option("--bootstrap", a->bootstrap,
                            "bootstrap replicates over records for the bounds (default 500; 0 = none)"),
            bootstrap);
  with_rule(cmd->add_option("--seed", a->seed, "seed of the bootstrap (default 1)"), option_rules::seed);
  cmd->add_option("--out", a->out, "output directory (default CASE.fragility next to the working directory)");
  with_rule(cmd->add_option("--threads", a->threads, "worker threads (default: all cores; 1 per rank under mpirun)"),
            option_rules::threads);
  cmd->add_flag("--resume", a->resume, "continue the results in --out after their last complete row");
  cmd->add_flag("--json", a->json, "print the summary as JSON");
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  cmd->add_flag("--no-plots", a->no_plots, "no SVG plots in the HTML page");
  cmd->callback([a] { run(*a); });
}

}  // namespace assess::cli
