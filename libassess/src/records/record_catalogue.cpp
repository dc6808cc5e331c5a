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
#include <filesystem>
#include <map>
#include <set>
#include <sstream>
#include <tuple>

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

/// A number or NaN for an empty cell: a decimal number within `rule` (its
/// unit), the rules of case files (number_rules.hpp).
double number_cell(const std::string& text, const std::string& where, const NumberRule& rule) {
  if (text.empty()) return nan();
  double v = 0.0;
  std::string bad = decimal_number_violation(text, v);
  if (bad.empty()) bad = number_rule_violation(v, rule);
  if (!bad.empty()) throw InputError(where + ": " + bad + " (or an empty cell: unknown)");
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

/// An optional number of a catalogue entry: null or absent is unknown (NaN).
double num_or_nan(const JsonNode& r, const char* key, const NumberRule& rule) {
  const auto n = r.find(key);
  if (!n || n->value().is_null()) return nan();
  return n->as_number(rule);
}

std::string text_or(const JsonNode& r, const char* key) {
  const auto n = r.find(key);
  return n ? n->as_string() : std::string();
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
  // The bounded reader (a directory, a device or a FIFO is named), and the
  // bytes the catalogue was built from (issue 39: every command refuses a
  // record changed since `assess records build`, not only the selections).
  const std::string bytes = read_input_file(path, input_kinds::record_file);
  if (!e.content_hash.empty() && hash_hex(content_hash(bytes)) != e.content_hash)
    throw InputError(path + ": the file changed since the catalogue was built (content hash " +
                     hash_hex(content_hash(bytes)) + ", catalogue " + e.content_hash +
                     "): run `assess records build`");
  Record r = e.plain_unit.empty()
                 ? parse_record_text(bytes, path)
                 : parse_plain_record_text(bytes, path, e.plain_dt_s, parse_acceleration_unit(e.plain_unit));
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
  return catalogue_from_metadata(read_input_file(table, input_kinds::metadata_table), table,
                                 [](const std::string& path) { return read_input_file(path, input_kinds::record_file); });
}

RecordCatalogue catalogue_from_metadata(const std::string& text, const std::string& table,
                                        const std::function<std::string(const std::string&)>& read_record_file) {
  // A UTF-8 byte order mark (spreadsheets write one) is not part of the first column's name.
  std::istringstream in(text.compare(0, 3, "\xEF\xBB\xBF") == 0 ? text.substr(3) : text);
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
  for (std::size_t i = 0; i < header.size(); ++i) {
    const std::string bad = control_character_violation(header[i]);
    if (!bad.empty()) throw InputError(table + ":1: column " + std::to_string(i + 1) + ": " + bad);
    if (!col.emplace(header[i], i).second)
      throw InputError(table + ":1: column '" + header[i] + "' is named twice (columns " +
                       std::to_string(col[header[i]] + 1) + " and " + std::to_string(i + 1) + ")");
  }
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
    // Every cell is text printed by `records list`/`show` and in reports: no
    // control characters (an ESC sequence re-programs a terminal; issue 39).
    for (std::size_t i = 0; i < cells.size(); ++i) {
      const std::string bad = control_character_violation(cells[i]);
      if (!bad.empty()) throw InputError(where + " column " + header[i] + ": " + bad);
    }
    CatalogueEntry e;
    e.file = cell("file");
    if (e.file.empty()) throw InputError(at("file") + ": expected a record file name");
    e.id = stem_of(e.file);
    if (e.id.empty())
      throw InputError(at("file") + ": '" + e.file + "' gives an empty record id (the id is the file's name "
                       "without its folder and extension)");
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
    e.Mw = number_cell(cell("Mw"), at("Mw"), catalogue_rules::Mw);
    e.distance_km = number_cell(cell("distance_km"), at("distance_km"), catalogue_rules::distance_km);
    if (std::isfinite(e.distance_km) && e.distance_kind != "Rjb" && e.distance_kind != "Repi" &&
        e.distance_kind != "Rrup")
      throw InputError(at("distance_kind") + ": expected Rjb, Repi or Rrup, got '" + e.distance_kind + "'");
    e.vs30_m_s = number_cell(cell("vs30_m_s"), at("vs30_m_s"), catalogue_rules::vs30_m_s);
    e.lowest_usable_hz = number_cell(cell("lowest_usable_hz"), at("lowest_usable_hz"), catalogue_rules::lowest_usable_hz);
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
    e.pulse_period_s = number_cell(cell("pulse_period_s"), at("pulse_period_s"), catalogue_rules::pulse_period_s);
    if (std::isfinite(e.pulse_period_s) && e.pulse != "pulse-like")
      throw InputError(at("pulse_period_s") + ": a pulse period needs pulse = pulse-like");
    e.plain_unit = cell("plain_unit");
    Record rec;
    try {
      // One read of the file: its record and the hash of the same bytes.
      const std::string path = cat.directory + "/" + e.file;
      if (!e.plain_unit.empty()) {
        e.plain_dt_s = number_cell(cell("plain_dt_s"), at("plain_dt_s"), catalogue_rules::plain_dt_s);
        if (!std::isfinite(e.plain_dt_s)) throw InputError(at("plain_dt_s") + ": a plain text file needs its time step (s)");
        const AccelerationUnit unit = parse_acceleration_unit(e.plain_unit);
        const std::string bytes = read_record_file(path);
        rec = parse_plain_record_text(bytes, path, e.plain_dt_s, unit);
        e.content_hash = hash_hex(content_hash(bytes));
      } else {
        const std::string bytes = read_record_file(path);
        rec = parse_record_text(bytes, path);
        e.content_hash = hash_hex(content_hash(bytes));
      }
    } catch (const InputError& err) {
      throw InputError(where + ": " + err.what());
    }
    e.format = rec.format;
    if (rec.acc.empty()) throw InputError(where + ": " + cat.directory + "/" + e.file + ": the record has no samples");
    e.npts = long(rec.size());
    e.dt_s = rec.dt;
    e.pga_g = round6(rec.pga() / units::g_n);
    e.significant_duration_s = round6(significant_duration(rec));
    // What the build computes obeys the rules the catalogue is read with (parse_catalogue_text).
    for (const auto& [v, rule, name] : {std::tuple<double, const NumberRule&, const char*>{e.pga_g, catalogue_rules::pga_g, "PGA"},
                                        {e.significant_duration_s, catalogue_rules::significant_duration_s, "D5-95"}}) {
      const std::string bad = number_rule_violation(v, rule);
      if (!bad.empty()) throw InputError(where + ": " + cat.directory + "/" + e.file + ": its " + name + ": " + bad);
    }
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

void relocate_catalogue(RecordCatalogue& cat, const std::string& directory) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const fs::path to = fs::weakly_canonical(fs::absolute(directory, ec), ec);
  for (CatalogueEntry& e : cat.entries) {
    const fs::path file = fs::weakly_canonical(fs::absolute(fs::path(cat.directory) / e.file, ec), ec);
    const fs::path rel = file.lexically_relative(to);
    if (ec || rel.empty())
      throw InputError(directory + ": no path from this folder to the record file " + cat.directory + "/" + e.file);
    e.file = rel.generic_string();
  }
  cat.directory = directory;
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
  return parse_catalogue_text(read_input_file(path, input_kinds::record_catalogue), path);
}

RecordCatalogue parse_catalogue_text(const std::string& text, const std::string& path) {
  const nlohmann::json j = parse_json_text(text, path);
  RecordCatalogue cat;
  cat.directory = directory_of(path);
  cat.path = path;
  cat.text_hash = content_hash(text);
  // The rules of case files and of metadata.csv (issue 39): the file and the
  // JSON path of a bad value, numbers within catalogue_rules, no control
  // characters in any text (JsonNode::as_string).
  const JsonNode root(j, path);
  if (!root.is_object()) root.fail("expected a record catalogue (an object with \"records\")");
  cat.description = text_or(root, "description");
  std::set<std::string> ids;
  for (const JsonNode& r : root.array("records")) {
    if (!r.is_object()) r.fail("expected a record entry (an object)");
    CatalogueEntry e;
    e.id = r.string("id");
    if (e.id.empty() || e.id.find('/') != std::string::npos)
      r.at("id").fail("expected a record id (the file's name without folder and extension)");
    if (!ids.insert(e.id).second) r.at("id").fail("duplicate record id '" + e.id + "'");
    e.file = r.string("file");
    if (e.file.empty()) r.at("file").fail("expected the record file's path (relative to the catalogue's folder)");
    e.format = r.string("format");
    e.event = text_or(r, "event");
    e.date = text_or(r, "date");
    e.station = text_or(r, "station");
    e.component = text_or(r, "component");
    e.source = text_or(r, "source");
    e.note = text_or(r, "note");
    e.mechanism = text_or(r, "mechanism");
    e.station_code = text_or(r, "station_code");
    e.positive_direction = text_or(r, "positive_direction");
    e.distance_kind = text_or(r, "distance_kind");
    e.site_class = text_or(r, "site_class");
    if (!e.site_class.empty() && (e.site_class.size() != 1 || std::string("ABCDE").find(e.site_class) == std::string::npos))
      r.at("site_class").fail("\"" + e.site_class + "\": expected one of A, B, C, D, E or \"\" (unknown)");
    e.site_class_basis = text_or(r, "site_class_basis");
    e.vs30_class = text_or(r, "vs30_class");
    e.pulse = text_or(r, "pulse");
    e.pulse_period_s = num_or_nan(r, "pulse_period_s", catalogue_rules::pulse_period_s);
    e.content_hash = text_or(r, "content_hash");
    if (!e.content_hash.empty() &&
        (e.content_hash.size() != 16 || e.content_hash.find_first_not_of("0123456789abcdef") != std::string::npos))
      r.at("content_hash").fail("expected 16 hexadecimal digits (the FNV-1a 64 of the file) or \"\"");
    e.country = text_or(r, "country");
    e.terms = text_or(r, "terms");
    e.Mw = num_or_nan(r, "Mw", catalogue_rules::Mw);
    e.distance_km = num_or_nan(r, "distance_km", catalogue_rules::distance_km);
    if (std::isfinite(e.distance_km) && e.distance_kind != "Rjb" && e.distance_kind != "Repi" && e.distance_kind != "Rrup")
      r.fail("distance_kind \"" + e.distance_kind + "\": expected Rjb, Repi or Rrup with a distance");
    e.vs30_m_s = num_or_nan(r, "vs30_m_s", catalogue_rules::vs30_m_s);
    e.lowest_usable_hz = num_or_nan(r, "lowest_usable_hz", catalogue_rules::lowest_usable_hz);
    e.significant_duration_s = r.number_or("significant_duration_s", 0.0, catalogue_rules::significant_duration_s);
    const JsonNode npts = r.at("npts");
    if (!npts.value().is_number_integer() || npts.value().get<double>() < 1.0 ||
        npts.value().get<double>() > catalogue_rules::npts_max)
      npts.fail("expected a number of samples, an integer from 1 to 1e9");
    e.npts = npts.value().get<long>();
    e.dt_s = r.number("dt_s", catalogue_rules::dt_s);
    e.pga_g = r.number("pga_g", catalogue_rules::pga_g);
    e.plain_unit = text_or(r, "plain_unit");
    if (!e.plain_unit.empty()) {
      try {
        parse_acceleration_unit(e.plain_unit);
      } catch (const InputError& ex) {
        r.at("plain_unit").fail(ex.what());
      }
      e.plain_dt_s = r.number("plain_dt_s", catalogue_rules::plain_dt_s);
    }
    e.usable_for_design = r.boolean_or("usable_for_design", true);
    // A record usable for design has what the selection filters on (build_catalogue's rule).
    if (e.usable_for_design && (!std::isfinite(e.Mw) || !std::isfinite(e.distance_km) || e.site_class.empty()))
      (r.has("usable_for_design") ? r.at("usable_for_design") : r).fail("true, but the entry has no Mw, distance or site class: the selection "
                                     "cannot filter it (rebuild the catalogue with `assess records build`)");
    cat.entries.push_back(std::move(e));
  }
  return cat;
}

}  // namespace assess
