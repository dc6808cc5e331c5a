// record_catalogue.cpp: generation (metadata.csv + files -> catalogue.json)
// and reading of the record catalogue of spectra/records/.
//
// Notation: PGA in g with g_n = 9.80665 m/s^2 (the unit of the files); Vs30
// in m/s; distances in km; D5-95 significant duration (s, Trifunac & Brady
// 1975) from the Arias intensity (strong_motion.hpp). Site class: NTC 2018
// §3.2.2 Tab. 3.2.II (Vs,eq = Vs30 for deposits deeper than 30 m), identical
// to EC8 Tab. 3.1. Rules for usable_for_design: docs/theory/record-selection.md §3.
#include "assess/records/record_catalogue.hpp"

#include "assess/records/record_io.hpp"
#include "assess/records/strong_motion.hpp"
#include "assess/support/content_hash.hpp"
#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/json_input.hpp"
#include "assess/support/units.hpp"
#include "support/parallel_for.hpp"

#include <nlohmann/json.hpp>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <iterator>
#include <map>
#include <set>
#include <sstream>

namespace assess {

namespace {

std::string directory_of(const std::string& path) {
  const auto slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : path.substr(0, slash);
}

std::string stem_of(const std::string& file) {
  const auto slash = file.find_last_of('/');
  std::string s = slash == std::string::npos ? file : file.substr(slash + 1);
  // ".cor.acc" is one extension; otherwise the last dot.
  const std::string cor = ".cor.acc";
  if (s.size() > cor.size() && s.compare(s.size() - cor.size(), cor.size(), cor) == 0)
    return s.substr(0, s.size() - cor.size());
  const auto dot = s.find_last_of('.');
  return dot == std::string::npos ? s : s.substr(0, dot);
}

/// Splits one CSV line (RFC 4180: quoted fields, "" inside quotes).
std::vector<std::string> split_csv(const std::string& line, const std::string& where) {
  std::vector<std::string> out;
  std::string cur;
  bool quoted = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (quoted) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') cur += '"', ++i;
      else if (c == '"') quoted = false;
      else cur += c;
    } else if (c == '"') {
      quoted = true;
    } else if (c == ',') {
      out.push_back(cur), cur.clear();
    } else if (c != '\r') {
      cur += c;
    }
  }
  if (quoted) throw InputError(where + ": unterminated quoted field");
  out.push_back(cur);
  return out;
}

double nan() { return std::numeric_limits<double>::quiet_NaN(); }

/// A number or NaN for an empty cell; range-checked.
double number_cell(const std::string& text, const std::string& where, const char* unit, double lo, double hi) {
  if (text.empty()) return nan();
  std::size_t used = 0;
  double v = 0.0;
  try {
    v = std::stod(text, &used);
  } catch (const std::exception&) {
    used = 0;
  }
  if (used != text.size() || !std::isfinite(v) || v < lo || v > hi)
    throw InputError(where + ": expected a number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "] " +
                     unit + " or an empty cell, got '" + text + "'");
  return v;
}

std::string fmt_g(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.3g", v);
  return buf;
}

/// 6 significant digits, as a JSON number.
double round6(double v) {
  if (!std::isfinite(v) || v == 0.0) return v;
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.6g", v);
  return std::stod(buf);
}

nlohmann::ordered_json num_or_null(double v) {
  return std::isfinite(v) ? nlohmann::ordered_json(v) : nlohmann::ordered_json(nullptr);
}

double num_or_nan(const nlohmann::json& r, const char* key) {
  if (!r.contains(key) || r.at(key).is_null()) return nan();
  return r.at(key).get<double>();
}

}  // namespace

std::string site_class_from_vs30(double v) {
  if (!std::isfinite(v) || !(v > 0.0)) return "";
  if (v > 800.0) return "A";
  if (v >= 360.0) return "B";
  if (v >= 180.0) return "C";
  return "D";
}

SiteClass site_class_of(double vs30_m_s, const std::string& stated) {
  const std::string v = site_class_from_vs30(vs30_m_s);
  // E: the velocities of C or D over a substrate within 30 m (Tab. 3.2.II),
  // which Vs30 alone cannot show: a stated E its Vs30 does not contradict stands.
  if (stated == "E" && (v == "C" || v == "D")) return {"E", "stated"};
  if (!v.empty()) return {v, "Vs30"};
  if (!stated.empty()) return {stated, "stated"};
  return {"", ""};
}

std::string near_fault_reason(const CatalogueEntry& e, double threshold_km) {
  std::string why;
  if (e.pulse == "pulse-like")
    why = "pulse-like (source classification" +
          (std::isfinite(e.pulse_period_s) ? ", Tp = " + fmt_g(e.pulse_period_s) + " s" : std::string()) + ")";
  if (std::isfinite(e.distance_km) && e.distance_km < threshold_km)
    why += (why.empty() ? "" : "; ") + std::string("near-fault: ") + (e.distance_kind.empty() ? "distance" : e.distance_kind) +
           " " + fmt_g(e.distance_km) + " km < " + fmt_g(threshold_km) + " km";
  return why;
}

const CatalogueEntry* RecordCatalogue::find(const std::string& id_or_file) const {
  for (const auto& e : entries)
    if (e.id == id_or_file || e.file == id_or_file) return &e;
  return nullptr;
}

std::vector<CatalogueEntry> RecordCatalogue::design_candidates() const {
  std::vector<CatalogueEntry> out;
  for (const auto& e : entries)
    if (e.usable_for_design) out.push_back(e);
  return out;
}

Record RecordCatalogue::load(const CatalogueEntry& e) const {
  const std::string path = directory + "/" + e.file;
  if (!e.plain_unit.empty()) {
    Record r = read_plain_record(path, e.plain_dt_s, parse_acceleration_unit(e.plain_unit));
    r.name = e.id;
    return r;
  }
  Record r = read_record(path);
  r.name = e.id;
  return r;
}

Record RecordCatalogue::load(const std::string& id_or_file) const {
  const CatalogueEntry* e = find(id_or_file);
  if (!e) throw InputError("record '" + id_or_file + "' is not in the catalogue of " + directory);
  return load(*e);
}

std::vector<Record> RecordCatalogue::load_all(const std::vector<CatalogueEntry>& entries,
                                              std::vector<std::string>& errors) const {
  std::vector<Record> out(entries.size());
  errors.assign(entries.size(), "");
  detail::parallel_for(entries.size(), [&](std::size_t i) {
    try {
      out[i] = load(entries[i]);
    } catch (const InputError& e) {
      errors[i] = e.what();
    }
  });
  return out;
}

RecordCatalogue build_catalogue(const std::string& table) {
  std::istringstream in(read_input_file(table, input_kinds::metadata_table));
  RecordCatalogue cat;
  cat.directory = directory_of(table);
  cat.description =
      "Accelerograms in spectra/records/: one entry per horizontal component, generated by `assess records build` "
      "from metadata.csv and the files. npts, dt_s, pga_g (max|a|/g_n, g_n = 9.80665 m/s^2) and "
      "significant_duration_s (D5-95, Arias) are computed from the data; site_class from vs30_m_s (NTC 2018 "
      "Tab. 3.2.II) or as stated; usable_for_design = false with the reason in note.";
  std::string line;
  if (!std::getline(in, line)) throw InputError(table + ": empty metadata table");
  const std::vector<std::string> header = split_csv(line, table + ":1");
  const std::vector<std::string> required = {
      "file", "event", "date", "Mw", "mechanism", "station", "station_code", "component", "positive_direction",
      "distance_km", "distance_kind", "vs30_m_s", "site_class_stated", "country", "lowest_usable_hz", "pulse",
      "pulse_period_s", "plain_dt_s", "plain_unit", "excluded_reason", "source", "terms", "notes"};
  std::map<std::string, std::size_t> col;
  for (std::size_t i = 0; i < header.size(); ++i) col[header[i]] = i;
  for (const auto& r : required)
    if (!col.count(r)) throw InputError(table + ":1: missing column '" + r + "'");
  std::set<std::string> ids;
  for (int lineno = 2; std::getline(in, line); ++lineno) {
    if (line.empty() || line == "\r") continue;
    const std::string where = table + ":" + std::to_string(lineno);
    const std::vector<std::string> cells = split_csv(line, where);
    if (cells.size() != header.size())
      throw InputError(where + ": expected " + std::to_string(header.size()) + " columns, got " +
                       std::to_string(cells.size()));
    auto cell = [&](const char* name) { return cells[col.at(name)]; };
    auto at = [&](const char* name) { return where + " column " + name; };
    CatalogueEntry e;
    e.file = cell("file");
    if (e.file.empty()) throw InputError(at("file") + ": expected a record file name");
    e.id = stem_of(e.file);
    if (!ids.insert(e.id).second) throw InputError(where + ": duplicate record id '" + e.id + "'");
    e.event = cell("event");
    e.date = cell("date");
    e.mechanism = cell("mechanism");
    e.station = cell("station");
    e.station_code = cell("station_code");
    e.component = cell("component");
    e.positive_direction = cell("positive_direction");
    e.distance_kind = cell("distance_kind");
    e.country = cell("country");
    e.source = cell("source");
    e.terms = cell("terms");
    e.Mw = number_cell(cell("Mw"), at("Mw"), "(-)", 2.0, 10.0);
    e.distance_km = number_cell(cell("distance_km"), at("distance_km"), "km", 0.0, 20000.0);
    if (std::isfinite(e.distance_km) && e.distance_kind != "Rjb" && e.distance_kind != "Repi" &&
        e.distance_kind != "Rrup")
      throw InputError(at("distance_kind") + ": expected Rjb, Repi or Rrup, got '" + e.distance_kind + "'");
    e.vs30_m_s = number_cell(cell("vs30_m_s"), at("vs30_m_s"), "m/s", 50.0, 5000.0);
    e.lowest_usable_hz = number_cell(cell("lowest_usable_hz"), at("lowest_usable_hz"), "Hz", 0.0, 100.0);
    const std::string stated = cell("site_class_stated");
    if (!stated.empty() && stated.find_first_not_of("ABCDE") != std::string::npos)
      throw InputError(at("site_class_stated") + ": expected one of A, B, C, D, E, got '" + stated + "'");
    if (!stated.empty() && stated.size() != 1)
      throw InputError(at("site_class_stated") + ": expected one of A, B, C, D, E, got '" + stated + "'");
    // Issue 38: the Tab. 3.2.II band of the measured Vs30 first, the stated
    // class only without one (record-selection.md §3; site_class_of).
    e.vs30_class = site_class_from_vs30(e.vs30_m_s);
    const SiteClass sc = site_class_of(e.vs30_m_s, stated);
    e.site_class = sc.site_class;
    e.site_class_basis = sc.basis;
    e.pulse = cell("pulse");
    if (!e.pulse.empty() && e.pulse != "pulse-like" && e.pulse != "non-pulse")
      throw InputError(at("pulse") + ": expected pulse-like, non-pulse or an empty cell, got '" + e.pulse + "'");
    e.pulse_period_s = number_cell(cell("pulse_period_s"), at("pulse_period_s"), "s", 0.01, 100.0);
    if (std::isfinite(e.pulse_period_s) && e.pulse != "pulse-like")
      throw InputError(at("pulse_period_s") + ": a pulse period needs pulse = pulse-like");
    e.plain_unit = cell("plain_unit");
    Record rec;
    try {
      if (!e.plain_unit.empty()) {
        e.plain_dt_s = number_cell(cell("plain_dt_s"), at("plain_dt_s"), "s", 1e-5, 1.0);
        if (!std::isfinite(e.plain_dt_s)) throw InputError(at("plain_dt_s") + ": a plain text file needs its time step (s)");
        rec = read_plain_record(cat.directory + "/" + e.file, e.plain_dt_s, parse_acceleration_unit(e.plain_unit));
      } else {
        rec = read_record(cat.directory + "/" + e.file);
      }
    } catch (const InputError& err) {
      throw InputError(where + ": " + err.what());
    }
    e.format = rec.format;
    e.content_hash = hash_hex(file_content_hash(cat.directory + "/" + e.file));
    e.npts = long(rec.size());
    e.dt_s = rec.dt;
    e.pga_g = round6(rec.pga() / units::g_n);
    e.significant_duration_s = round6(significant_duration(rec));
    std::string reason = cell("excluded_reason");
    std::vector<std::string> missing;
    if (!std::isfinite(e.Mw)) missing.push_back("Mw");
    if (!std::isfinite(e.distance_km)) missing.push_back("distance");
    if (e.site_class.empty()) missing.push_back("Vs30 or site class");
    if (reason.empty() && e.pga_g < weak_motion_pga_g)
      reason = "weak motion: PGA " + fmt_g(e.pga_g) + " g < " + fmt_g(weak_motion_pga_g) + " g";
    if (reason.empty() && !missing.empty()) {
      reason = "metadata incomplete: no ";
      for (std::size_t i = 0; i < missing.size(); ++i) reason += (i ? (i + 1 == missing.size() ? " or " : ", ") : "") + missing[i];
    }
    e.usable_for_design = reason.empty();
    e.note = reason.empty() ? cell("notes") : reason + (cell("notes").empty() ? "" : "; " + cell("notes"));
    cat.entries.push_back(std::move(e));
  }
  return cat;
}

std::string catalogue_json(const RecordCatalogue& cat) {
  nlohmann::ordered_json j;
  j["description"] = cat.description;
  j["records"] = nlohmann::ordered_json::array();
  for (const CatalogueEntry& e : cat.entries) {
    nlohmann::ordered_json r;
    r["id"] = e.id;
    r["file"] = e.file;
    r["format"] = e.format;
    r["event"] = e.event;
    r["date"] = e.date;
    r["Mw"] = num_or_null(e.Mw);
    r["mechanism"] = e.mechanism;
    r["station"] = e.station;
    r["station_code"] = e.station_code;
    r["component"] = e.component;
    r["positive_direction"] = e.positive_direction;
    r["distance_km"] = num_or_null(e.distance_km);
    r["distance_kind"] = e.distance_kind;
    r["vs30_m_s"] = num_or_null(e.vs30_m_s);
    r["site_class"] = e.site_class;
    r["site_class_basis"] = e.site_class_basis;
    r["vs30_class"] = e.vs30_class;
    r["country"] = e.country;
    r["lowest_usable_hz"] = num_or_null(e.lowest_usable_hz);
    r["pulse"] = e.pulse;
    r["pulse_period_s"] = num_or_null(e.pulse_period_s);
    r["near_fault"] = near_fault_reason(e);
    r["npts"] = e.npts;
    r["dt_s"] = e.dt_s;
    r["pga_g"] = e.pga_g;
    r["significant_duration_s"] = e.significant_duration_s;
    if (!e.plain_unit.empty()) {
      r["plain_dt_s"] = e.plain_dt_s;
      r["plain_unit"] = e.plain_unit;
    }
    r["source"] = e.source;
    r["terms"] = e.terms;
    r["content_hash"] = e.content_hash;
    r["usable_for_design"] = e.usable_for_design;
    r["note"] = e.note;
    j["records"].push_back(std::move(r));
  }
  return j.dump(1) + "\n";
}

RecordCatalogue read_catalogue(const std::string& path) {
  // The bounded reader and the JSON parser of case files (depth limit, the
  // path of a malformed value); a directory or /dev/zero is named.
  const std::string text = read_input_file(path, input_kinds::record_catalogue);
  const nlohmann::json j = parse_json_text(text, path);
  RecordCatalogue cat;
  cat.directory = directory_of(path);
  cat.path = path;
  cat.text_hash = content_hash(text);
  try {
    cat.description = j.value("description", "");
    for (const auto& r : j.at("records")) {
      CatalogueEntry e;
      e.id = r.at("id").get<std::string>();
      e.file = r.at("file").get<std::string>();
      e.format = r.at("format").get<std::string>();
      e.event = r.value("event", "");
      e.date = r.value("date", "");
      e.station = r.value("station", "");
      e.component = r.value("component", "");
      e.source = r.value("source", "");
      e.note = r.value("note", "");
      e.mechanism = r.value("mechanism", "");
      e.station_code = r.value("station_code", "");
      e.positive_direction = r.value("positive_direction", "");
      e.distance_kind = r.value("distance_kind", "");
      e.site_class = r.value("site_class", "");
      e.site_class_basis = r.value("site_class_basis", "");
      e.vs30_class = r.value("vs30_class", "");
      e.pulse = r.value("pulse", "");
      e.pulse_period_s = num_or_nan(r, "pulse_period_s");
      e.content_hash = r.value("content_hash", "");
      e.country = r.value("country", "");
      e.terms = r.value("terms", "");
      e.Mw = num_or_nan(r, "Mw");
      e.distance_km = num_or_nan(r, "distance_km");
      e.vs30_m_s = num_or_nan(r, "vs30_m_s");
      e.lowest_usable_hz = num_or_nan(r, "lowest_usable_hz");
      e.significant_duration_s = r.value("significant_duration_s", 0.0);
      e.npts = r.at("npts").get<long>();
      e.dt_s = r.at("dt_s").get<double>();
      e.pga_g = r.at("pga_g").get<double>();
      e.plain_dt_s = r.value("plain_dt_s", 0.0);
      e.plain_unit = r.value("plain_unit", "");
      e.usable_for_design = r.value("usable_for_design", true);
      cat.entries.push_back(std::move(e));
    }
  } catch (const nlohmann::json::exception& ex) {
    throw InputError("malformed record catalogue '" + path + "': " + ex.what());
  }
  return cat;
}

}  // namespace assess
