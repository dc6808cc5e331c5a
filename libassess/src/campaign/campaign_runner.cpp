// campaign_runner.cpp: thread pool, ordered streaming CSV, resume and merge
// of campaign parts.
//
// Notation:
//   group   analyses sharing wall, record, scale and realisation (one applied
//           record, one response spectrum); the unit of work of a thread and
//           of the partition between MPI ranks (group mod parts == part)
//   task    the ids of one group still to run, [first, end)
//   reorder buffer: rows of finished tasks wait until every earlier task is
//           written, so the file is always a prefix of the part's id sequence
#include "assess/campaign/campaign_runner.hpp"

#include "assess/campaign/output_lock.hpp"
#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/output_file.hpp"

#include "campaign/csv_fields.hpp"

#include <atomic>
#include <chrono>
#include <cstdio>
#include <exception>
#include <filesystem>
#include <fstream>
#include <map>
#include <mutex>
#include <optional>
#include <sstream>
#include <thread>

namespace assess {

namespace fs = std::filesystem;

namespace {

const char* const kColumns[] = {
    "id",          "wall",           "b_m",          "h_m",          "unit_weight_kN_m3",
    "k_kN_m3",     "record",         "scale",        "realisation",  "time_mult",
    "amp_mult",    "restitution",    "model",        "pga_m_s2",     "a0_star_m_s2",
    "du_star_m",   "Ts_s",           "SDe_Ts_m",     "dc_strength",  "dc_displacement",
    "e",           "theta_u_rad",    "theta_max_rad", "theta_max_over_theta_u", "t_theta_max_s",
    "overturned",  "impacts",        "dc_energy",    "termination",  "status",
    "reason"};
constexpr std::size_t kNumColumns = sizeof(kColumns) / sizeof(kColumns[0]);

using csv::num;
using csv::quoted;
using csv::to_double;
const auto& split_csv = csv::split;

struct Task {
  std::uint64_t first, end;
};

// The tasks of one part, built on demand (issue 10, defect 10: a list of
// 1e8 / G tasks was built before --limit applied): task t is group
// g = part + t * parts, ids [g G, min((g + 1) G, end)).
struct TaskList {
  std::uint64_t G = 1, part = 0, parts = 1, end = 0;
  std::uint64_t count = 0;  // groups g = part (mod parts) with g G < end
  TaskList(std::uint64_t group_size, int part_, int parts_, std::uint64_t end_)
      : G(group_size), part(std::uint64_t(part_)), parts(std::uint64_t(parts_)), end(end_) {
    const std::uint64_t groups = (end + G - 1) / G;
    count = groups > part ? (groups - part + parts - 1) / parts : 0;
  }
  Task at(std::uint64_t t) const {
    const std::uint64_t g = part + t * parts;
    return {g * G, std::min((g + 1) * G, end)};
  }
  // Ids in all tasks: every task is a full group but possibly the last.
  std::uint64_t ids() const {
    if (count == 0) return 0;
    const Task last = at(count - 1);
    return (count - 1) * G + (last.end - last.first);
  }
};

}  // namespace

void CampaignRunOptions::validate() const {
  if (parts < 1) throw InputError("parts must be >= 1");
  if (part < 0 || part >= parts) throw InputError("part must lie in [0, parts)");
}

std::string campaign_csv_header() {
  std::string h;
  for (std::size_t i = 0; i < kNumColumns; ++i) h += (i ? "," : "") + std::string(kColumns[i]);
  return h;
}

std::string campaign_csv_row(const AnalysisRow& r) {
  std::string s;
  auto put = [&s](const std::string& v) { s += s.empty() ? v : "," + v; };
  put(std::to_string(r.id));
  put(quoted(r.wall));
  put(num(r.b_m));
  put(num(r.h_m));
  put(num(r.unit_weight_kN_m3));
  put(r.k_kN_m3 ? num(*r.k_kN_m3) : "");
  put(quoted(r.record));
  put(num(r.scale));
  put(std::to_string(r.realisation));
  put(num(r.time_mult));
  put(num(r.amp_mult));
  put(quoted(r.restitution));
  put(r.model);
  for (double v : {r.pga_m_s2, r.a0_star_m_s2, r.du_star_m, r.Ts_s, r.SDe_Ts_m, r.dc_strength, r.dc_displacement})
    put(r.has_code ? num(v) : "");
  if (r.has_dynamics) {
    put(r.e ? num(*r.e) : "");
    for (double v : {r.theta_u_rad, r.theta_max_rad, r.theta_ratio, r.t_theta_max_s}) put(num(v));
    put(r.overturned ? "1" : "0");
    put(std::to_string(r.impacts));
    put(num(r.dc_energy));
    put(r.termination);
  } else {
    for (int i = 0; i < 9; ++i) s += ",";
  }
  put(r.ok ? "ok" : "failed");
  put(quoted(r.reason));
  return s;
}

AnalysisRow parse_campaign_csv_row(const std::string& line) {
  const std::vector<std::string> f = split_csv(line);
  if (f.size() != kNumColumns)
    throw InputError("campaign row has " + std::to_string(f.size()) + " fields, expected " +
                     std::to_string(kNumColumns) + ": " + line.substr(0, 80));
  AnalysisRow r;
  try {
    std::size_t i = 0;
    std::size_t n = 0;
    r.id = std::stoull(f[i++], &n);
    if (n != f[0].size()) throw std::invalid_argument("id");
    r.wall = f[i++];
    r.b_m = to_double(f[i++]);
    r.h_m = to_double(f[i++]);
    r.unit_weight_kN_m3 = to_double(f[i++]);
    if (!f[i].empty()) r.k_kN_m3 = to_double(f[i]);
    ++i;
    r.record = f[i++];
    r.scale = to_double(f[i++]);
    r.realisation = std::stoi(f[i++]);
    r.time_mult = to_double(f[i++]);
    r.amp_mult = to_double(f[i++]);
    r.restitution = f[i++];
    r.model = f[i++];
    r.has_code = !f[i].empty();
    if (r.has_code) {
      r.pga_m_s2 = to_double(f[i]);
      r.a0_star_m_s2 = to_double(f[i + 1]);
      r.du_star_m = to_double(f[i + 2]);
      r.Ts_s = to_double(f[i + 3]);
      r.SDe_Ts_m = to_double(f[i + 4]);
      r.dc_strength = to_double(f[i + 5]);
      r.dc_displacement = to_double(f[i + 6]);
    }
    i += 7;
    r.has_dynamics = !f[i + 8].empty();
    if (r.has_dynamics) {
      if (!f[i].empty()) r.e = to_double(f[i]);
      r.theta_u_rad = to_double(f[i + 1]);
      r.theta_max_rad = to_double(f[i + 2]);
      r.theta_ratio = to_double(f[i + 3]);
      r.t_theta_max_s = to_double(f[i + 4]);
      r.overturned = f[i + 5] == "1";
      r.impacts = std::stol(f[i + 6]);
      r.dc_energy = to_double(f[i + 7]);
      r.termination = f[i + 8];
    }
    i += 9;
    if (f[i] != "ok" && f[i] != "failed") throw std::invalid_argument("status");
    r.ok = f[i++] == "ok";
    r.reason = f[i];
  } catch (const std::exception&) {
    throw InputError("malformed campaign row: " + line.substr(0, 80));
  }
  return r;
}

std::vector<AnalysisRow> read_campaign_csv(const std::string& path) {
  if (!non_regular_file_type(path).empty()) check_input_file(path, input_kinds::own_output);  // not a FIFO, /dev/zero
  std::ifstream in(path);
  if (!in) throw InputError("cannot open campaign results '" + path + "'");
  std::string line;
  if (!std::getline(in, line) || line != campaign_csv_header())
    throw InputError("'" + path + "' is not a campaign results file (its header differs)");
  std::vector<AnalysisRow> rows;
  while (std::getline(in, line))
    if (!line.empty()) rows.push_back(parse_campaign_csv_row(line));
  return rows;
}

std::string campaign_part_path(const std::string& out_dir, int part, int parts) {
  if (parts == 1) return out_dir + "/results.csv";
  return out_dir + "/results.part" + std::to_string(part) + "of" + std::to_string(parts) + ".csv";
}

namespace {

// The complete rows at the start of an existing part file that follow the
// expected id sequence; returns their count and the byte offset after them.
std::pair<std::uint64_t, std::uint64_t> valid_prefix(const CampaignJob& job, const std::string& path,
                                                     const TaskList& tasks) {
  if (!non_regular_file_type(path).empty()) check_input_file(path, input_kinds::own_output);  // not a FIFO, /dev/zero
  std::ifstream in(path, std::ios::binary);
  std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  const std::string header = job.csv_header() + "\n";
  if (text.compare(0, header.size(), header) != 0)
    throw InputError("cannot resume '" + path + "': its header is not this version's results header");
  std::uint64_t offset = header.size(), count = 0;
  std::uint64_t t = 0;
  Task task = tasks.count ? tasks.at(0) : Task{0, 0};
  std::uint64_t next = task.first;
  while (t < tasks.count) {
    const std::size_t nl = text.find('\n', offset);
    if (nl == std::string::npos) break;  // an incomplete last line is dropped
    std::uint64_t id = 0;
    try {
      id = job.row_id(text.substr(offset, nl - offset));
    } catch (const InputError&) {
      break;
    }
    if (id != next) break;
    offset = nl + 1;
    ++count;
    if (++next == task.end && ++t < tasks.count) {
      task = tasks.at(t);
      next = task.first;
    }
  }
  return {count, offset};
}

// The campaign as a job: rows of AnalysisRow, inputs in campaign.json.
class CampaignAsJob final : public CampaignJob {
 public:
  explicit CampaignAsJob(const Campaign& c) : c_(c) {}
  std::uint64_t size() const override { return c_.size(); }
  std::uint64_t group_size() const override { return c_.spec().group_size(); }
  std::string inputs_file() const override { return "campaign.json"; }
  std::string inputs_text() const override { return to_json(c_.spec()).dump(2) + "\n"; }
  std::string csv_header() const override { return campaign_csv_header(); }
  std::vector<std::string> evaluate_csv(std::uint64_t first, std::uint64_t end, std::uint64_t& failed) const override {
    std::vector<std::string> lines;
    for (const auto& r : c_.evaluate(first, end)) {
      lines.push_back(campaign_csv_row(r));
      failed += r.ok ? 0 : 1;
    }
    return lines;
  }
  std::uint64_t row_id(const std::string& line) const override { return parse_campaign_csv_row(line).id; }

 private:
  const Campaign& c_;
};

}  // namespace

CampaignRunSummary run_campaign(const Campaign& campaign, const std::string& out_dir,
                                const CampaignRunOptions& options) {
  return run_campaign_job(CampaignAsJob(campaign), out_dir, options);
}

void merge_campaign_parts(const std::vector<std::string>& part_paths, const std::string& out_path) {
  // A merge needs only the header and the row parser of a campaign.
  struct Rows final : CampaignJob {
    std::uint64_t size() const override { return 0; }
    std::uint64_t group_size() const override { return 1; }
    std::string inputs_file() const override { return "campaign.json"; }
    std::string inputs_text() const override { return ""; }
    std::string csv_header() const override { return campaign_csv_header(); }
    std::vector<std::string> evaluate_csv(std::uint64_t, std::uint64_t, std::uint64_t&) const override { return {}; }
    std::uint64_t row_id(const std::string& line) const override { return parse_campaign_csv_row(line).id; }
  } rows;
  merge_campaign_job_parts(rows, part_paths, out_path);
}

CampaignRunSummary run_campaign_job(const CampaignJob& job, const std::string& out_dir,
                                    const CampaignRunOptions& options) {
  options.validate();
  const auto start = std::chrono::steady_clock::now();
  std::error_code ec;
  // A new or an existing folder (an existing regular file is refused by name).
  make_output_folder(out_dir, "--out");
  // One writer per output directory (and per part), before anything is written.
  std::optional<CampaignOutputLock> lock;
  if (!options.output_locked) lock.emplace(out_dir, options.part, options.parts);

  // The normalised spec: a resumed run must be the same campaign.
  const std::string spec_path = out_dir + "/" + job.inputs_file();
  const std::string spec_text = job.inputs_text();
  if (options.resume && !fs::exists(spec_path) && fs::exists(campaign_part_path(out_dir, options.part, options.parts)))
    throw InputError("cannot resume into '" + out_dir + "': it holds results but no " + job.inputs_file() +
                     " saying what they are results of: choose another --out");
  if (options.resume && fs::exists(spec_path)) {
    const std::string old = read_input_file(spec_path, input_kinds::own_output);
    if (old != spec_text)
      throw InputError("cannot resume into '" + out_dir + "': its " + job.inputs_file() +
                       " describes a different campaign or fragility study (another case or campaign file, or the same "
                       "file edited since, other records or options): choose another --out, or run without --resume "
                       "into a new folder");
  } else {
    // Written by every part to a private temporary name and renamed: identical content, atomic replacement.
    write_output_file(spec_path, spec_text, "--out " + out_dir, out_dir);
  }

  // The tasks of this part, lazily: `all` ignores the limit (a resumed file
  // may hold more rows than this run asks for: they are kept).
  const std::uint64_t size = job.size();
  const std::uint64_t end = options.limit > 0 ? std::min(options.limit, size) : size;
  const std::uint64_t G = job.group_size();
  const TaskList all(G, options.part, options.parts, size), tasks(G, options.part, options.parts, end);
  CampaignRunSummary summary;
  summary.total = tasks.ids();

  const std::string path = campaign_part_path(out_dir, options.part, options.parts);
  std::ofstream out;
  std::uint64_t skip = 0;  // ids of `tasks` already in the file
  if (options.resume && fs::exists(path)) {
    const auto [count, offset] = valid_prefix(job, path, all);
    fs::resize_file(path, offset, ec);  // drops a partly written last line
    if (ec) throw InputError("cannot truncate '" + path + "' to its complete rows");
    summary.resumed = std::min(count, summary.total);
    skip = summary.resumed;
    out.open(path, std::ios::binary | std::ios::app);
  } else {
    // A part run must not silently replace a merged results.csv either.
    for (const std::string& p : {path, campaign_part_path(out_dir, 0, 1)})
      if (fs::exists(p) && !options.resume)
        throw InputError("'" + p + "' exists: pass --resume to continue it, or choose another output directory");
    out.open(path, std::ios::binary | std::ios::trunc);
    out << job.csv_header() << "\n";
  }
  if (!out) throw InputError("cannot write '" + path + "'");
  out.flush();
  if (!out) throw SystemError("cannot write '" + path + "' (disk full or an I/O error)");
  // Every task but the last is a full group: the first task to run and its offset.
  const std::uint64_t first_task = skip >= summary.total ? tasks.count : skip / G;
  const std::uint64_t first_offset = skip >= summary.total ? 0 : skip % G;
  const std::uint64_t n_tasks = tasks.count - first_task;
  auto task = [&](std::uint64_t t) {
    Task k = tasks.at(first_task + t);
    if (t == 0) k.first += first_offset;
    return k;
  };

  std::uint64_t done = summary.resumed;
  if (options.progress) options.progress(done, summary.total);

  std::mutex mutex;
  std::map<std::uint64_t, std::pair<std::string, std::uint64_t>> pending;  // task -> (rows, count), waiting
  std::uint64_t next_write = 0;
  std::atomic<std::uint64_t> next_task{0};
  std::atomic<bool> stop{false};
  std::exception_ptr error;

  auto worker = [&] {
    try {
      for (std::uint64_t t; !stop && !(options.cancel && options.cancel->load()) && (t = next_task++) < n_tasks;) {
        const Task k = task(t);
        std::uint64_t failed = 0;
        const std::vector<std::string> lines = job.evaluate_csv(k.first, k.end, failed);
        std::string text;
        for (const auto& l : lines) text += l + "\n";
        std::lock_guard<std::mutex> guard(mutex);
        summary.failed += failed;
        pending.emplace(t, std::make_pair(std::move(text), k.end - k.first));
        bool wrote = false;
        for (auto it = pending.begin(); it != pending.end() && it->first == next_write; it = pending.erase(it)) {
          out << it->second.first;
          done += it->second.second;
          ++next_write;
          wrote = true;
        }
        if (wrote) {
          out.flush();
          if (!out) throw SystemError("cannot write '" + path + "' (disk full or an I/O error)");
          if (options.progress) options.progress(done, summary.total);
        }
      }
    } catch (...) {
      std::lock_guard<std::mutex> guard(mutex);
      if (!error) error = std::current_exception();
      stop = true;
    }
  };
  unsigned n = options.threads ? options.threads : std::max(1u, std::thread::hardware_concurrency());
  n = unsigned(std::min<std::uint64_t>(n, std::max<std::uint64_t>(n_tasks, 1)));
  std::vector<std::thread> pool;
  for (unsigned i = 1; i < n; ++i) pool.emplace_back(worker);
  worker();
  for (auto& th : pool) th.join();
  if (error) std::rethrow_exception(error);

  summary.run = done - summary.resumed;
  summary.interrupted = done < summary.total;
  summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return summary;
}

void merge_campaign_job_parts(const CampaignJob& job, const std::vector<std::string>& part_paths,
                              const std::string& out_path) {
  struct Part {
    std::ifstream in;
    std::string line;
    std::uint64_t id = 0;
    bool live = false;
  };
  std::vector<Part> parts(part_paths.size());
  auto advance = [&job](Part& p, const std::string& name) {
    p.live = false;
    while (std::getline(p.in, p.line)) {
      if (p.line.empty()) continue;
      p.id = job.row_id(p.line);
      p.live = true;
      return;
    }
    if (!p.in.eof()) throw InputError("cannot read '" + name + "'");
  };
  for (std::size_t i = 0; i < parts.size(); ++i) {
    if (!non_regular_file_type(part_paths[i]).empty()) check_input_file(part_paths[i], input_kinds::own_output);
    parts[i].in.open(part_paths[i], std::ios::binary);
    std::string header;
    if (!parts[i].in || !std::getline(parts[i].in, header) || header != job.csv_header())
      throw InputError("'" + part_paths[i] + "' is not a campaign results part");
    advance(parts[i], part_paths[i]);
  }
  const std::string tmp = out_path + ".tmp";
  std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
  out << job.csv_header() << "\n";
  for (;;) {
    Part* best = nullptr;
    std::size_t bi = 0;
    for (std::size_t i = 0; i < parts.size(); ++i)
      if (parts[i].live && (!best || parts[i].id < best->id)) best = &parts[i], bi = i;
    if (!best) break;
    out << best->line << "\n";
    advance(*best, part_paths[bi]);
  }
  out.close();
  if (!out) {
    std::error_code ec;
    fs::remove(tmp, ec);
    throw SystemError("cannot write '" + tmp + "' (disk full or an I/O error)");
  }
  std::error_code ec;
  fs::rename(tmp, out_path, ec);
  if (ec) throw SystemError("cannot write '" + out_path + "': " + ec.message());
}

}  // namespace assess
