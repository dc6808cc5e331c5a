// campaign_runner.hpp: runs a campaign on a pool of threads, streaming the
// rows of results.csv to disk in id order as they finish, resumable, and
// splittable into parts (one per MPI rank) that merge into the same file.
#pragma once

#include "assess/campaign/campaign.hpp"

#include <atomic>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace assess {

/// Settings of a campaign run, with documented defaults.
struct CampaignRunOptions {
  unsigned threads = 0;     ///< worker threads; 0 = std::thread::hardware_concurrency() (default)
  std::uint64_t limit = 0;  ///< run only the analyses with id < limit; 0 = all (default)
  bool resume = false;      ///< continue an existing results file after its last complete row (default false)
  /// Partition for distributed runs: this process runs the groups g with
  /// g mod parts == part (a group shares wall, record, scale, realisation).
  /// Defaults 0 of 1: everything.
  int part = 0;
  int parts = 1;
  /// Called after rows are written, with (analyses done, analyses to do) in
  /// this part, counting rows found on resume. Called from one thread at a time.
  std::function<void(std::uint64_t done, std::uint64_t total)> progress;
  /// If set, checked before each group: once true, no new group starts, the
  /// groups under way finish and are written, and run_campaign returns with
  /// `interrupted` set (e.g. set from a SIGINT handler; lock-free, so
  /// signal-safe). Default none.
  const std::atomic<bool>* cancel = nullptr;
  /// The caller already holds a CampaignOutputLock on the output directory
  /// for this part (output_lock.hpp), e.g. to keep it over a merge and the
  /// report; else run_campaign takes one for the run (default false).
  bool output_locked = false;

  /// @throws InputError naming the invalid field
  void validate() const;
};

/// What a run did.
struct CampaignRunSummary {
  std::uint64_t total = 0;    ///< analyses of this part (within the limit)
  std::uint64_t resumed = 0;  ///< rows already present when resuming
  std::uint64_t run = 0;      ///< analyses run now
  std::uint64_t failed = 0;   ///< of which failed (status "failed")
  double seconds = 0.0;       ///< wall-clock time of this run (s)
  bool interrupted = false;   ///< stopped by options.cancel before the end
};

/// The header of results.csv (column names with units).
std::string campaign_csv_header();
/// One CSV line (without newline) for a row.
std::string campaign_csv_row(const AnalysisRow& row);
/// Parses one line written by campaign_csv_row. @throws InputError if malformed.
AnalysisRow parse_campaign_csv_row(const std::string& line);
/// Reads every row of a results file. @throws InputError if the header differs.
std::vector<AnalysisRow> read_campaign_csv(const std::string& path);

/// Any flat, deterministic set of analyses the runner can run: ids 0..size()-1
/// in groups of group_size() consecutive ids (the unit of work of a thread
/// and of the partition between MPI ranks), one CSV line per id. The
/// campaign of this header is one; the multiple-stripe and IDA analyses of
/// risk/ are another. Implementations must be thread-safe (evaluate is called
/// concurrently) and deterministic (a line depends only on its id).
class CampaignJob {
 public:
  virtual ~CampaignJob() = default;
  virtual std::uint64_t size() const = 0;
  virtual std::uint64_t group_size() const = 0;
  /// File name of the normalised inputs in the output directory ("campaign.json").
  virtual std::string inputs_file() const = 0;
  /// The normalised inputs (compared byte for byte on resume).
  virtual std::string inputs_text() const = 0;
  /// Header line of the results file (without newline).
  virtual std::string csv_header() const = 0;
  /// The CSV lines (without newline) of ids [first, end), which lie in one
  /// group; `failed` is increased by the number of failed analyses. Never
  /// throws for a failing analysis.
  virtual std::vector<std::string> evaluate_csv(std::uint64_t first, std::uint64_t end,
                                                std::uint64_t& failed) const = 0;
  /// The id of a line written by evaluate_csv. @throws InputError if malformed.
  virtual std::uint64_t row_id(const std::string& line) const = 0;
};

/// The results file of part `part` of `parts` in out_dir: results.csv when
/// parts == 1, else results.part<part>of<parts>.csv.
std::string campaign_part_path(const std::string& out_dir, int part, int parts);

/// Runs (or resumes) the campaign's analyses of the options' part into
/// campaign_part_path(out_dir, ...), and writes out_dir/campaign.json (the
/// normalised spec). Rows are written in id order and flushed as soon as the
/// rows before them are done, so an interrupted run leaves a valid prefix.
/// Only one process writes to out_dir (CampaignOutputLock, output_lock.hpp).
/// @throws InputError if out_dir cannot be written, if another process holds
///   its lock, or when resuming a file whose header or campaign.json differs
///   from this campaign's.
CampaignRunSummary run_campaign(const Campaign& campaign, const std::string& out_dir,
                                const CampaignRunOptions& options);

/// The same runner for any job: results in campaign_part_path(out_dir, ...)
/// with job.csv_header(), inputs in out_dir/job.inputs_file().
CampaignRunSummary run_campaign_job(const CampaignJob& job, const std::string& out_dir,
                                    const CampaignRunOptions& options);

/// Merges the part files of a job (header job.csv_header()) in id order.
void merge_campaign_job_parts(const CampaignJob& job, const std::vector<std::string>& part_paths,
                              const std::string& out_path);

/// Merges the part files (each in increasing id order) into one file in id
/// order, identical to a single-process run. @throws InputError on a bad part.
void merge_campaign_parts(const std::vector<std::string>& part_paths, const std::string& out_path);

}  // namespace assess
