// fragility_job.cpp: one dynamic analysis (rocking body or chain,
// FragilityStudy::respond) per (stripe, record, polarity, restitution), with
// the quantities of the three limit states (docs/theory/fragility.md §4):
// overturning (the integrator's criterion), energy D/C >= 1 (seed §3.2), and
// d* >= d_SLV (Circ. 2019 C8.7.1.2.1.9).
#include "assess/risk/fragility_job.hpp"

#include "assess/support/error.hpp"
#include "assess/support/content_hash.hpp"
#include "assess/support/input_file.hpp"

#include "campaign/csv_fields.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>

namespace assess {

namespace {

// FNV-1a 64 of a file's bytes as 16 hex digits ("" if unreadable), as the
// fragility summary's case_fnv1a64 (fragility_report.cpp): the bounded reader
// and the one hash of support/content_hash.hpp.
std::string content_fnv1a64(const std::string& path) {
  try {
    return hash_hex(file_content_hash(path, input_kinds::case_file));
  } catch (const InputError&) {
    return "";
  }
}


const char* const kColumns[] = {"id",           "stripe",        "TR_years",        "im_m_s2",   "record",
                                "scale",        "polarity",      "restitution",     "theta_max_rad",
                                "theta_u_rad",  "theta_ratio",   "d_star_m",        "dc_energy",
                                "dc_displacement", "overturned", "termination",     "status",    "reason"};
constexpr std::size_t kNumColumns = sizeof(kColumns) / sizeof(kColumns[0]);

using csv::num;
using csv::quoted;
using csv::to_double;
const auto& split_csv = csv::split;

std::string base_name(const std::string& path) {
  const auto p = path.find_last_of('/');
  return p == std::string::npos ? path : path.substr(p + 1);
}

}  // namespace

std::string fragility_csv_header() {
  std::string h;
  for (std::size_t i = 0; i < kNumColumns; ++i) h += (i ? "," : "") + std::string(kColumns[i]);
  return h;
}

std::string fragility_csv_row(const FragilityRow& r) {
  std::string s = std::to_string(r.id) + "," + std::to_string(r.stripe) + "," + num(r.TR_years) + "," +
                  num(r.im_m_s2) + "," + quoted(r.record) + "," + num(r.scale) + "," +
                  (r.reversed ? "reversed" : "normal") + "," + std::to_string(r.restitution) + ",";
  if (r.ok) {
    s += num(r.theta_max_rad) + "," + num(r.theta_u_rad) + "," + num(r.theta_ratio) + "," + num(r.d_star_m) + "," +
         num(r.dc_energy) + "," + num(r.dc_displacement) + "," + (r.overturned ? "1" : "0") + ",";
  } else {
    s += ",,,,,,,";
  }
  s += r.termination + "," + (r.ok ? "ok" : "failed") + "," + quoted(r.reason);
  return s;
}

FragilityRow parse_fragility_csv_row(const std::string& line) {
  const std::vector<std::string> f = split_csv(line);
  if (f.size() != kNumColumns)
    throw InputError("fragility row has " + std::to_string(f.size()) + " fields, expected " +
                     std::to_string(kNumColumns) + ": " + line.substr(0, 80));
  FragilityRow r;
  try {
    std::size_t n = 0;
    r.id = std::stoull(f[0], &n);
    if (n != f[0].size()) throw std::invalid_argument("id");
    r.stripe = std::stoul(f[1]);
    r.TR_years = to_double(f[2]);
    r.im_m_s2 = to_double(f[3]);
    r.record = f[4];
    r.scale = to_double(f[5]);
    if (f[6] != "normal" && f[6] != "reversed") throw std::invalid_argument("polarity");
    r.reversed = f[6] == "reversed";
    r.restitution = std::stoul(f[7]);
    if (f[16] != "ok" && f[16] != "failed") throw std::invalid_argument("status");
    r.ok = f[16] == "ok";
    if (r.ok) {
      r.theta_max_rad = to_double(f[8]);
      r.theta_u_rad = to_double(f[9]);
      r.theta_ratio = to_double(f[10]);
      r.d_star_m = to_double(f[11]);
      r.dc_energy = to_double(f[12]);
      r.dc_displacement = to_double(f[13]);
      if (f[14] != "0" && f[14] != "1") throw std::invalid_argument("overturned");
      r.overturned = f[14] == "1";
    }
    r.termination = f[15];
    r.reason = f[17];
  } catch (const std::exception&) {
    throw InputError("malformed fragility row: " + line.substr(0, 80));
  }
  return r;
}

std::vector<FragilityRow> read_fragility_csv(const std::string& path) {
  if (!non_regular_file_type(path).empty()) check_input_file(path, input_kinds::own_output);  // not a FIFO, /dev/zero
  std::ifstream in(path);
  if (!in) throw InputError("cannot open fragility results '" + path + "'");
  std::string line;
  if (!std::getline(in, line) || line != fragility_csv_header())
    throw InputError("'" + path + "' is not a fragility results file (its header differs)");
  std::vector<FragilityRow> rows;
  while (std::getline(in, line))
    if (!line.empty()) {
      try {
        rows.push_back(parse_fragility_csv_row(line));
      } catch (const InputError& e) {
        throw InputError("'" + path + "': " + e.what());
      }
    }
  return rows;
}

std::string FragilityJob::inputs_text() const {
  using nlohmann::json;
  json j;
  j["case"] = s_.file;
  // The case's content, not only its name: a --resume into the output of
  // another case with the same file name (another folder, or the file edited
  // since) is refused (issue 31).
  j["case_fnv1a64"] = content_fnv1a64(s_.file);
  j["project"] = s_.project;
  j["method"] = to_string(s_.options.method);
  j["mechanism"] = s_.mechanism;
  j["site"] = s_.site_description;
  j["restitution"] = s_.restitution_labels;
  json pol = json::array();
  for (bool r : s_.polarities) pol.push_back(r ? "reversed" : "normal");
  j["polarities"] = pol;
  const RockingOptions& o = s_.dynamic.options;
  j["integrator"] = {{"stepper", int(o.stepper)}, {"rel_tol", o.rel_tol}, {"abs_tol", o.abs_tol},
                     {"max_steps", o.max_steps}, {"tail_s", o.tail_s}, {"overturn", int(o.overturn)}};
  for (const Stripe& st : s_.stripes) {
    json js{{"im_m_s2", st.im}, {"TR_years", st.TR}};
    for (const StripeRecord& r : st.records)
      js["records"].push_back({{"file", base_name(s_.record_files[r.record])}, {"scale", r.scale}});
    j["stripes"].push_back(js);
  }
  j["analyses"] = s_.size();
  return j.dump(2) + "\n";
}

std::vector<FragilityRow> FragilityJob::evaluate(std::uint64_t first, std::uint64_t end) const {
  const std::uint64_t G = s_.group_size();
  if (!(first < end && end <= s_.size() && (end - 1) / G == first / G))
    throw InputError("analyses [" + std::to_string(first) + ", " + std::to_string(end) +
                     ") are not a non-empty range within one group of " + std::to_string(G));
  const auto [si, ri] = s_.group(first / G);
  const Stripe& stripe = s_.stripes[si];
  const StripeRecord& sr = stripe.records[ri];
  const Record& rec = s_.base_motion(sr.record);  // ground record, or its floor motion at height
  std::vector<FragilityRow> rows;
  for (std::uint64_t id = first; id < end; ++id) {
    const std::uint64_t in_group = id % G;
    FragilityRow row;
    row.id = id;
    row.stripe = si;
    row.TR_years = stripe.TR;
    row.im_m_s2 = stripe.im;
    row.record = base_name(s_.record_files[sr.record]);
    row.scale = sr.scale;
    row.reversed = s_.polarities[in_group / s_.restitutions()];
    row.restitution = in_group % s_.restitutions();
    try {
      const MechanismResponse m = s_.respond(rec, sr.scale, row.reversed, row.restitution);
      row.termination = to_string(m.termination);
      if (!m.ok()) {
        row.ok = false;
        row.reason = m.message;
      } else {
        row.theta_max_rad = m.theta_max;
        row.theta_u_rad = m.theta_u;
        row.theta_ratio = m.theta_u > 0 ? m.theta_max / m.theta_u : 0.0;
        row.d_star_m = m.d_star;
        row.dc_energy = m.dc_energy;
        row.dc_displacement = m.dc_displacement;
        row.overturned = m.overturned;
      }
    } catch (const std::exception& e) {
      row.ok = false;
      row.reason = e.what();
    }
    rows.push_back(std::move(row));
  }
  return rows;
}

std::vector<std::string> FragilityJob::evaluate_csv(std::uint64_t first, std::uint64_t end,
                                                    std::uint64_t& failed) const {
  std::vector<std::string> lines;
  for (const FragilityRow& r : evaluate(first, end)) {
    lines.push_back(fragility_csv_row(r));
    failed += r.ok ? 0 : 1;
  }
  return lines;
}

}  // namespace assess
