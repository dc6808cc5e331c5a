// cmd_campaign.cpp: `assess campaign CAMPAIGN.json --out DIR`, a parametric
// campaign of rocking analyses on all cores (and on MPI ranks when built with
// MPI): parses the options, runs the library's campaign runner, shows the
// progress on stderr, then writes the summary and the plots.
#include "commands.hpp"

#include <assess/support/number_rules.hpp>
#include <assess/support/termination.hpp>

#include <assess/campaign/campaign.hpp>
#include <assess/campaign/campaign_report.hpp>
#include <assess/campaign/campaign_runner.hpp>
#include <assess/campaign/output_lock.hpp>
#include <assess/support/error.hpp>
#include <assess/report/plot.hpp>

#include <atomic>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <iostream>
#include <optional>
#include <string>
#include <unistd.h>

#include "mpi_session.hpp"

namespace assess::cli {

namespace {

struct CampaignArgs {
  std::string file, out;
  unsigned threads = 0;
  std::uint64_t limit = 0;
  bool resume = false, quiet = false, no_plots = false;
  bool limit_given = false;
};

std::string hms(double s) {
  if (!std::isfinite(s) || s < 0) return "--";
  const long t = std::lround(s);
  char buf[32];
  if (t >= 3600) std::snprintf(buf, sizeof buf, "%ldh%02ldm", t / 3600, (t / 60) % 60);
  else if (t >= 60) std::snprintf(buf, sizeof buf, "%ldm%02lds", t / 60, t % 60);
  else std::snprintf(buf, sizeof buf, "%lds", t);
  return buf;
}

// Progress on stderr: a bar with rate and ETA redrawn in place on a terminal,
// a plain line every 10 s otherwise (logs, batch jobs).
class Progress {
 public:
  Progress(bool enabled, std::string prefix) : enabled_(enabled), tty_(isatty(2)), prefix_(std::move(prefix)) {}

  void operator()(std::uint64_t done, std::uint64_t total) {
    if (!enabled_) return;
    const auto now = std::chrono::steady_clock::now();
    if (!started_) started_ = true, start_ = now, first_ = done, last_ = now - std::chrono::hours(1);
    const double since = std::chrono::duration<double>(now - last_).count();
    const bool end = done == total;
    if (!end && since < (tty_ ? 0.2 : 10.0)) return;
    last_ = now;
    const double el = std::chrono::duration<double>(now - start_).count();
    const double rate = el > 0 ? double(done - first_) / el : 0.0;
    const double eta = rate > 0 ? double(total - done) / rate : NAN;
    const double frac = total ? double(done) / double(total) : 1.0;
    char line[200];
    if (tty_) {
      const int w = 30, fill = int(frac * w);
      std::string bar = std::string(std::size_t(fill), '#') + std::string(std::size_t(w - fill), '.');
      std::snprintf(line, sizeof line, "\r%s[%s] %llu/%llu %5.1f%% %.0f/s ETA %s   ", prefix_.c_str(), bar.c_str(),
                    (unsigned long long)done, (unsigned long long)total, 100 * frac, rate, hms(eta).c_str());
      std::cerr << line << (end ? "\n" : "") << std::flush;
    } else {
      std::snprintf(line, sizeof line, "%s%llu/%llu analyses (%.1f %%), %.0f/s, ETA %s", prefix_.c_str(),
                    (unsigned long long)done, (unsigned long long)total, 100 * frac, rate, hms(eta).c_str());
      std::cerr << line << "\n";
    }
  }

 private:
  bool enabled_, tty_;
  std::string prefix_;
  bool started_ = false;
  std::chrono::steady_clock::time_point start_, last_;
  std::uint64_t first_ = 0;
};

// Set by the first SIGINT/SIGTERM (support/termination.hpp): the runner
// finishes the groups under way, writes them, and stops; --resume continues.
std::atomic<bool> g_cancel{false};

void run(const CampaignArgs& a) {
  // MPI only when launched by mpirun, loaded at run time (mpi_session.hpp).
  const MpiSession mpi;
  const int rank = mpi.rank(), ranks = mpi.size();
  const Campaign campaign(read_campaign(a.file));
  CampaignRunOptions o;
  // Several ranks on one machine share its cores: one thread each unless told.
  o.threads = a.threads ? a.threads : (ranks > 1 ? 1u : 0u);
  o.limit = a.limit;
  o.resume = a.resume;
  o.part = rank;
  o.parts = ranks;
  Progress progress(!a.quiet && rank == 0, ranks > 1 ? "rank 0/" + std::to_string(ranks) + " " : "");
  o.progress = std::ref(progress);
  o.cancel = &g_cancel;
  set_interrupt_flag(&g_cancel);

  std::string error;
  CampaignRunSummary s;
  // One writer per output directory, held over the run, the merge and the
  // report (output_lock.hpp; the ranks of one MPI job share it).
  std::optional<CampaignOutputLock> lock;
  try {
    lock.emplace(a.out, rank, ranks);
    o.output_locked = true;
    s = run_campaign(campaign, a.out, o);
  } catch (const InputError& e) {
    error = e.what();
  }
  if (mpi.active()) {
    // Every rank must finish its part before rank 0 merges; a failure on any rank stops all.
    const int any = mpi.max_over_ranks(error.empty() ? 0 : 1);
    if (any && error.empty()) error = "another MPI rank failed (see its message)";
    // Counts summed over the ranks; the time is the slowest rank's.
    unsigned long long mine[3] = {s.resumed, s.run, s.failed}, all[3] = {0, 0, 0};
    mpi.sum_to_root(mine, all, 3);
    const double slowest = mpi.max_to_root(s.seconds);
    s.resumed = all[0], s.run = all[1], s.failed = all[2], s.seconds = slowest;
  }
  if (!error.empty()) throw InputError(error);
  if (mpi.active()) s.interrupted = mpi.max_over_ranks(s.interrupted ? 1 : 0) != 0;
  if (s.interrupted)
    throw InputError("campaign interrupted: the finished rows are in " + a.out +
                     "; run the same command with --resume to continue");
  if (rank != 0) return;
  if (ranks > 1) {
    std::vector<std::string> parts;
    for (int r = 0; r < ranks; ++r) parts.push_back(campaign_part_path(a.out, r, ranks));
    merge_campaign_parts(parts, campaign_part_path(a.out, 0, 1));
    for (const auto& p : parts) std::filesystem::remove(p);
  }
  const bool plots = !a.no_plots;
  const CampaignReportFiles files = write_campaign_report(campaign, a.out, plots);
  std::printf("campaign '%s': %llu analyses", campaign.spec().name.c_str(),
              (unsigned long long)(a.limit ? std::min<std::uint64_t>(a.limit, campaign.size()) : campaign.size()));
  if (ranks > 1) std::printf(" on %d MPI ranks", ranks);
  std::printf(" (%llu resumed, %llu run in %.2f s, %llu failed)\n", (unsigned long long)s.resumed,
              (unsigned long long)s.run, s.seconds, (unsigned long long)s.failed);
  std::printf("results: %s\nsummary: %s\n", campaign_part_path(a.out, 0, 1).c_str(), files.summary.c_str());
  for (const auto& p : files.plots) std::printf("plot:    %s\n", p.c_str());
  std::printf("index:   %s\n", files.index.c_str());
}

}  // namespace

void add_campaign_command(CLI::App& app) {
  auto a = std::make_shared<CampaignArgs>();
  auto* cmd = app.add_subcommand(
      "campaign",
      "Parametric campaign of rocking analyses (walls x records x scale factors x realisations x restitution x "
      "models), with the code's demand/capacity ratios; all cores, resumable, MPI-aware");
  cmd->add_option("campaign", a->file, "campaign file (JSON, see docs/user/campaign.md)")->required();
  cmd->add_option("--out", a->out, "output directory (results.csv, summary.json, campaign.json, plots)")->required();
  with_rule(cmd->add_option("--threads", a->threads, "worker threads (default: all cores; 1 per rank under mpirun)"),
            option_rules::threads);
  cmd->add_flag("--resume", a->resume, "continue the results in --out after their last complete row");
  static const NumberRule limit{"analyses", 1.0, 1e18, false, false, "only the analyses with id < N run: 0 would run none"};
  with_rule(cmd->add_option("--limit", a->limit, "run only the analyses with id < N (tests, trials)"), limit);
  cmd->add_flag("--quiet", a->quiet, "no progress on stderr");
  cmd->add_flag("--no-plots", a->no_plots, "write results and summary only");
  cmd->callback([a, cmd] {
    a->limit_given = cmd->count("--limit") > 0;
    run(*a);
  });
}

}  // namespace assess::cli
