// record_io.cpp: accelerogram readers (PEER AT2, ESM/ITACA ASCII, GEM
// .cor.acc, plain text). Format notes: spectra/records/README.md §4.
//
// Notation: npts = number of samples declared by the header, dt = time step
// (s), factor = conversion of the file's unit to m/s^2 (g -> g_n = 9.80665,
// record files only; cm/s^2 -> 0.01).
#include "assess/records/record_io.hpp"

#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/number_rules.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>
#include <vector>

namespace assess {
namespace {

std::string trim(const std::string& s) {
  const auto b = s.find_first_not_of(" \t\r\n");
  if (b == std::string::npos) return "";
  const auto e = s.find_last_not_of(" \t\r\n");
  return s.substr(b, e - b + 1);
}

std::string upper(std::string s) {
  for (char& c : s) c = static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
  return s;
}

std::string stem(const std::string& path) {
  const auto slash = path.find_last_of("/\\");
  std::string f = slash == std::string::npos ? path : path.substr(slash + 1);
  for (const char* ext : {".cor.acc", ".AT2", ".at2", ".DAT", ".ASC", ".txt", ".dat", ".csv"}) {
    const std::string e(ext);
    if (f.size() > e.size() && f.compare(f.size() - e.size(), e.size(), e) == 0) return f.substr(0, f.size() - e.size());
  }
  return f;
}

/// Lines of a text with every '\r' removed (LF, CRLF and CR CR LF endings).
std::vector<std::string> split_lines(std::string text) {
  text.erase(std::remove(text.begin(), text.end(), '\r'), text.end());
  std::vector<std::string> lines;
  std::istringstream is(text);
  for (std::string line; std::getline(is, line);) lines.push_back(line);
  return lines;
}

/// The content of a record file.
/// (The bounded reader: a regular file of at most 256 MB; a directory, a
/// device such as /dev/zero or a FIFO is named, never read.)
std::string read_text(const std::string& path) { return read_input_file(path, input_kinds::record_file); }

/// Appends the numbers of `line`, times `factor`, to `out`. Numbers may
/// touch (fixed-width E15.7 fields with no blank before a minus sign).
/// Throws on anything else, on a value that overflows a double, and on a
/// value that overflows once converted to m/s^2 (1e308 g). A subnormal value
/// (1.0E-310) is a number: strtod flags its underflow with ERANGE, but the
/// result is the nearest double, which is kept.
void parse_numbers(const std::string& line, const std::string& path, std::size_t line_no,
                   std::vector<double>& out, double factor) {
  const char* p = line.c_str();
  auto token = [&](const char* from) {
    std::string tok(from);
    tok = tok.substr(0, std::min<std::size_t>(tok.find_first_of(" \t,"), 40));
    return tok;
  };
  while (*p) {
    while (*p == ' ' || *p == '\t' || *p == ',') ++p;
    if (!*p) break;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(p, &end);
    // The location is built only for an error message (not once per value).
    const auto where = [&] { return path + ":" + std::to_string(line_no) + ": "; };
    if (end == p || std::isnan(v))
      throw InputError(where() + "non-numeric value '" + token(p) + "' (expected an acceleration value)");
    // strtod reads C99 hexadecimal floats (0x1p-3): no record format writes them.
    const char* digits = (*p == '+' || *p == '-') ? p + 1 : p;
    if (digits[0] == '0' && (digits[1] == 'x' || digits[1] == 'X'))
      throw InputError(where() + "hexadecimal value '" + token(p) + "' (expected a decimal acceleration value)");
    if (!std::isfinite(v) || (errno == ERANGE && std::fabs(v) > 1.0))
      throw InputError(where() + "value '" + token(p) + "' is out of the range of a double (|a| < 1.8e308)");
    const double a = v * factor;
    if (!std::isfinite(a))
      throw InputError(where() + "value '" + token(p) + "' overflows once converted to m/s^2");
    out.push_back(a);
    p = end;
  }
}

/// A count from a header field (NPTS, NDATA, Number of Data): a decimal
/// integer in [0, max_count], else an InputError naming the file and field.
constexpr long max_count = 1'000'000'000;  // 1e9 samples: 8 GB of doubles
long parse_count(const std::string& text, const std::string& path, const char* field) {
  const std::string t = trim(text);
  const std::string shown = t.substr(0, 40) + (t.size() > 40 ? "..." : "");
  std::size_t i = t.size() > 0 && t[0] == '+' ? 1 : 0;
  const std::size_t digits_from = i;
  long v = 0;
  bool too_many = false;
  for (; i < t.size() && std::isdigit(static_cast<unsigned char>(t[i])); ++i) {
    if (v <= max_count) v = 10 * v + (t[i] - '0');  // stops growing past the limit: no overflow
    too_many = too_many || v > max_count;
  }
  if (i == digits_from || i != t.size())
    throw InputError(path + ": header field " + field +
                     ": expected a number of points (a non-negative integer), got '" + shown + "'");
  if (too_many)
    throw InputError(path + ": header field " + field + ": " + shown + " points is more than the limit of " +
                     std::to_string(max_count));
  return v;
}

/// A real number from a header field (dt); `strict`: nothing may follow it.
double parse_header_real(const std::string& text, const std::string& path, const char* field, bool strict = true) {
  const std::string t = trim(text);
  char* end = nullptr;
  const double v = std::strtod(t.c_str(), &end);
  const bool hex = t.find_first_of("xX") != std::string::npos && t.find_first_of("xX") < std::size_t(end - t.c_str());
  if (t.empty() || end == t.c_str() || (strict && !trim(end).empty()) || !std::isfinite(v) || hex)
    throw InputError(path + ": header field " + field + ": expected a number (s), got '" + t.substr(0, 40) + "'");
  return v;
}

bool is_numeric_line(const std::string& line) {
  const std::string t = trim(line);
  if (t.empty()) return false;
  char* end = nullptr;
  std::strtod(t.c_str(), &end);
  return end != t.c_str() && (*end == '\0' || *end == ' ' || *end == '\t' || *end == '-' || *end == '+');
}

std::string show(double v) {
  if (std::isnan(v)) return "not a number";
  if (std::isinf(v)) return v > 0 ? "infinite" : "minus infinite";
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

/// dt within [record_dt_min_s, record_dt_max_s]; `where` says where it came from.
void check_dt_range(double dt, const std::string& path, const std::string& where) {
  if (std::isfinite(dt) && dt >= record_dt_min_s && dt <= record_dt_max_s) return;
  if (!(dt > 0.0))
    throw InputError(path + ": time step must be positive (s): " + where + " " + show(dt) + " s");
  throw InputError(path + ": " + where + " " + show(dt) + " s: expected a time step in [" + show(record_dt_min_s) +
                   ", " + show(record_dt_max_s) + "] s (strong-motion records are sampled at 0.001-0.04 s)");
}
void check_dt(double dt, const std::string& path) { check_dt_range(dt, path, "the header gives the time step"); }

/// Reads data values from line index `first` to the end and checks the count.
std::vector<double> read_data(const std::vector<std::string>& lines, std::size_t first, long npts,
                              const std::string& path, double factor) {
  std::vector<double> acc;
  // Never reserve more than the file can hold: a value takes at least one
  // character and a separator.
  std::size_t bytes = 0;
  for (std::size_t i = first; i < lines.size(); ++i) bytes += lines[i].size() + 1;
  if (npts > 0) acc.reserve(std::min(static_cast<std::size_t>(npts), bytes / 2 + 1));
  for (std::size_t i = first; i < lines.size(); ++i) parse_numbers(lines[i], path, i + 1, acc, factor);
  if (npts >= 0 && static_cast<long>(acc.size()) < npts)
    throw InputError(path + ": truncated record: the header declares " + std::to_string(npts) +
                     " points, the file has " + std::to_string(acc.size()));
  if (npts >= 0 && static_cast<long>(acc.size()) > npts)
    throw InputError(path + ": the file has " + std::to_string(acc.size()) + " values, more than the " +
                     std::to_string(npts) + " points its header declares");
  return acc;
}

// Header scanning without std::regex (whose executor recursed once per
// character and overflowed the stack on a 30 000-character line).
bool word_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }
std::size_t skip_blanks(const std::string& s, std::size_t i) {
  while (i < s.size() && (s[i] == ' ' || s[i] == '\t')) ++i;
  return i;
}
/// Position of `key` (upper case) in `u` (upper-cased line) followed by
/// optional blanks and '=', at a word start if `word_start`; returns the index
/// after the '=' or npos.
std::size_t find_assignment(const std::string& u, const char* key, bool word_start) {
  const std::string k(key);
  for (std::size_t at = u.find(k); at != std::string::npos; at = u.find(k, at + 1)) {
    if (word_start && at > 0 && word_char(u[at - 1])) continue;
    const std::size_t e = skip_blanks(u, at + k.size());
    if (e < u.size() && u[e] == '=') return e + 1;
  }
  return std::string::npos;
}
/// The run of characters from `i` in `chars` (after blanks).
std::string field_at(const std::string& s, std::size_t i, const char* chars) {
  i = skip_blanks(s, i);
  const std::size_t e = s.find_first_not_of(chars, i);
  return s.substr(i, (e == std::string::npos ? s.size() : e) - i);
}

Record read_at2(const std::vector<std::string>& lines, const std::string& path) {
  std::size_t k = 0;
  long npts = -1;
  double dt = 0.0;
  for (; k < lines.size() && k < 10; ++k) {
    const std::string u = upper(lines[k]);
    // "NPTS=  1559, DT=   .0200 SEC" (any order, any blanks)
    const std::size_t n_at = find_assignment(u, "NPTS", false), d_at = find_assignment(u, "DT", true);
    if (n_at != std::string::npos && d_at != std::string::npos) {
      const std::string n = field_at(u, n_at, "0123456789");
      if (!n.empty()) {
        npts = parse_count(n, path, "NPTS");
        dt = parse_header_real(field_at(u, d_at, "+-0123456789.E"), path, "DT", false);
        break;
      }
    }
    // "  1559   0.0200   NPTS, DT, SEC" (numbers first)
    const std::size_t i0 = skip_blanks(u, 0);
    const std::string n = field_at(u, i0, "0123456789");
    if (!n.empty()) {
      std::size_t i = i0 + n.size();
      if (i < u.size() && (u[i] == ' ' || u[i] == '\t')) {
        const std::string d = field_at(u, i, "+-0123456789.E");
        i = skip_blanks(u, skip_blanks(u, i) + d.size());
        if (!d.empty() && u.compare(i, 4, "NPTS") == 0 && skip_blanks(u, i + 4) < u.size() &&
            u[skip_blanks(u, i + 4)] == ',' && u.compare(skip_blanks(u, skip_blanks(u, i + 4) + 1), 2, "DT") == 0) {
          npts = parse_count(n, path, "NPTS");
          dt = parse_header_real(d, path, "DT", false);
          break;
        }
      }
    }
  }
  if (npts < 0) throw InputError(path + ": PEER AT2 header without an 'NPTS=..., DT=...' line");
  check_dt(dt, path);
  Record r;
  r.format = "PEER AT2";
  r.dt = dt;
  const std::string units_line = k >= 1 ? upper(lines[k - 1]) : "";
  double factor = units::g_n;
  if (units_line.find("CM/S") != std::string::npos) factor = 0.01;
  else if (units_line.find("M/S") != std::string::npos) factor = 1.0;
  const std::string title = k >= 3 ? upper(lines[k - 3]) : "";
  if (title.find("PEER") == std::string::npos && title.find("PACIFIC") == std::string::npos) {
    r.event = k >= 3 ? trim(lines[k - 3]) : "";  // free-text header (e.g. elCentro.AT2)
  } else if (k >= 2) {  // "event, date, station, component"
    std::vector<std::string> f;
    std::stringstream ss(lines[k - 2]);
    for (std::string item; std::getline(ss, item, ',');) f.push_back(trim(item));
    if (f.size() >= 3) {
      r.component = f.back();
      r.station = f[f.size() - 2];
      for (std::size_t i = 0; i + 2 < f.size(); ++i) r.event += (i ? ", " : "") + f[i];
    } else {
      r.event = trim(lines[k - 2]);
    }
  }
  r.acc = read_data(lines, k + 1, npts, path, factor);
  return r;
}

Record read_dyna(const std::vector<std::string>& lines, const std::string& path) {
  std::map<std::string, std::string> h;
  std::size_t k = 0;
  for (; k < lines.size() && !is_numeric_line(lines[k]); ++k) {
    const auto c = lines[k].find(": ");
    const auto c2 = lines[k].find(':');
    const auto pos = c != std::string::npos ? c : c2;
    if (pos == std::string::npos) continue;
    h[trim(lines[k].substr(0, pos))] = trim(lines[k].substr(pos + 1));
  }
  auto need = [&](const char* key) {
    auto it = h.find(key);
    if (it == h.end() || it->second.empty())
      throw InputError(path + ": ESM/ITACA header has no value for " + key);
    return it->second;
  };
  const double dt = parse_header_real(need("SAMPLING_INTERVAL_S"), path, "SAMPLING_INTERVAL_S");
  check_dt(dt, path);
  const long npts = parse_count(need("NDATA"), path, "NDATA");
  const std::string unit = need("UNITS");
  double factor = 1.0;
  try {
    factor = to_m_s2(parse_acceleration_unit(unit));
  } catch (const InputError& e) {
    throw InputError(path + ": header field UNITS: " + e.what());
  }
  Record r;
  const std::string version = h["DATABASE_VERSION"] + h["DATA_VERSION"];
  r.format = version.find("ITACA") != std::string::npos ? "ITACA ASCII" : "ESM ASCII";
  r.dt = dt;
  r.event = h["EVENT_NAME"] + (h["EVENT_DATE_YYYYMMDD"].empty() ? "" : ", " + h["EVENT_DATE_YYYYMMDD"]);
  r.station = h["STATION_CODE"] + (h["STATION_NAME"].empty() ? "" : " " + h["STATION_NAME"]);
  r.component = !h["COMPONENT"].empty() ? h["COMPONENT"] : h["STREAM"];
  r.acc = read_data(lines, k, npts, path, factor);
  return r;
}

Record read_cor_acc(const std::vector<std::string>& lines, const std::string& path) {
  std::map<std::string, std::string> h;
  std::size_t k = 0;
  for (; k < lines.size() && !is_numeric_line(lines[k]); ++k) {
    const auto pos = lines[k].find(" : ");
    if (pos != std::string::npos) h[trim(lines[k].substr(0, pos))] = trim(lines[k].substr(pos + 3));
  }
  auto need = [&](const char* key) {
    auto it = h.find(key);
    if (it == h.end() || it->second.empty()) throw InputError(path + ": .cor.acc header has no '" + key + "'");
    return it->second;
  };
  const double dt = parse_header_real(need("Time Increment (s)"), path, "Time Increment (s)");
  check_dt(dt, path);
  const long npts = parse_count(need("Number of Data"), path, "Number of Data");
  Record r;
  r.format = "GEM cor.acc";
  r.dt = dt;
  r.event = h["Event Date & Time"];
  r.station = h["Station Code / Name"];
  r.component = h["Orientation"];
  r.acc = read_data(lines, k, npts, path, 1.0);  // m/s/s
  return r;
}

}  // namespace

AccelerationUnit parse_acceleration_unit(const std::string& text) {
  const std::string t = upper(trim(text));
  if (t == "G") return AccelerationUnit::g;
  if (t == "M/S2" || t == "M/S^2" || t == "M/S/S") return AccelerationUnit::m_s2;
  if (t == "CM/S2" || t == "CM/S^2" || t == "CM/S/S" || t == "GAL") return AccelerationUnit::cm_s2;
  throw InputError("unknown acceleration unit '" + text + "' (expected g, m/s^2 or cm/s^2)");
}

double to_m_s2(AccelerationUnit unit) {
  switch (unit) {
    case AccelerationUnit::g: return units::g_n;
    case AccelerationUnit::cm_s2: return units::cm;
    case AccelerationUnit::m_s2: break;
  }
  return 1.0;
}

Record read_record(const std::string& path) { return parse_record_text(read_text(path), path); }

Record parse_record_text(const std::string& text, const std::string& path) {
  const std::vector<std::string> lines = split_lines(text);
  Record r;
  bool dyna = false, cor = false, at2 = false;
  for (std::size_t i = 0; i < lines.size() && i < 12; ++i) {
    if (lines[i].rfind("SAMPLING_INTERVAL_S:", 0) == 0 || lines[i].rfind("EVENT_NAME:", 0) == 0) dyna = true;
    if (lines[i].rfind("Time Increment (s)", 0) == 0) cor = true;
    if (upper(lines[i]).find("NPTS") != std::string::npos) at2 = true;
  }
  if (dyna) r = read_dyna(lines, path);
  else if (cor) r = read_cor_acc(lines, path);
  else if (at2) r = read_at2(lines, path);
  else
    throw InputError(path + ": unrecognised record format (expected PEER AT2, ESM/ITACA ASCII or .cor.acc; "
                            "for a plain file give the time step and unit)");
  r.name = stem(path);
  r.source = path;
  // The header's texts are printed in the reports (a listed record's event,
  // station, component): the text rule of case files, a tab read as a blank
  // (issue 39: an ESC sequence in a header re-programs the terminal).
  for (const auto& [text, field] : {std::pair<std::string*, const char*>{&r.event, "event"},
                                    {&r.station, "station"}, {&r.component, "component"}}) {
    std::replace(text->begin(), text->end(), '\t', ' ');
    const std::string bad = control_character_violation(*text);
    if (!bad.empty()) throw InputError(path + ": the header's " + field + ": " + bad);
  }
  return r;
}

Record read_plain_record(const std::string& path, double dt_s, AccelerationUnit unit) {
  check_dt_range(dt_s, path, "time step");
  return parse_plain_record_text(read_text(path), path, dt_s, unit);
}

Record parse_plain_record_text(const std::string& text, const std::string& path, double dt_s, AccelerationUnit unit) {
  check_dt_range(dt_s, path, "time step");
  const std::vector<std::string> lines = split_lines(text);
  Record r;
  r.format = "plain";
  r.dt = dt_s;
  r.name = stem(path);
  r.source = path;
  const double factor = to_m_s2(unit);
  std::vector<double> row;
  std::size_t columns = 0;
  double t_prev = 0.0;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    const std::string t = trim(lines[i]);
    if (t.empty() || t[0] == '#') continue;
    row.clear();
    parse_numbers(t, path, i + 1, row, 1.0);
    if (row.empty())
      throw InputError(path + ":" + std::to_string(i + 1) + ": no value on this line (only separators)");
    if (columns == 0) columns = row.size();
    if (row.size() != columns || columns > 2)
      throw InputError(path + ":" + std::to_string(i + 1) + ": expected " +
                       std::to_string(columns > 2 ? 2 : columns) + " column(s), found " + std::to_string(row.size()));
    if (columns == 2) {
      if (!r.acc.empty() && !(row[0] > t_prev))
        throw InputError(path + ":" + std::to_string(i + 1) + ": the time column must increase: t = " + show(row[0]) +
                         " s after t = " + show(t_prev) + " s");
      if (!r.acc.empty() && std::fabs(row[0] - t_prev - dt_s) > 1e-6 * dt_s + 1e-9)
        throw InputError(path + ":" + std::to_string(i + 1) + ": time column spacing " +
                         std::to_string(row[0] - t_prev) + " s differs from the declared time step " +
                         std::to_string(dt_s) + " s");
      t_prev = row[0];
    }
    const double a = row.back() * factor;
    if (!std::isfinite(a))
      throw InputError(path + ":" + std::to_string(i + 1) + ": value overflows once converted to m/s^2");
    r.acc.push_back(a);
  }
  if (r.acc.size() < 2) throw InputError(path + ": a record needs at least 2 values");
  return r;
}

Record read_plain_record(const std::string& path, AccelerationUnit unit) {
  // dt = the spacing of the first two times; read_plain_record(path, dt, unit)
  // then checks every later spacing against it.
  const std::string text = read_text(path);
  const std::vector<std::string> lines = split_lines(text);
  std::vector<double> t, row;
  for (std::size_t i = 0; i < lines.size() && t.size() < 2; ++i) {
    const std::string s = trim(lines[i]);
    if (s.empty() || s[0] == '#') continue;
    row.clear();
    parse_numbers(s, path, i + 1, row, 1.0);
    if (row.size() != 2)
      throw InputError(path + ":" + std::to_string(i + 1) + ": found " + std::to_string(row.size()) +
                       " column(s); without a time step (dt, s) a plain record needs two columns: time (s) and "
                       "acceleration");
    t.push_back(row[0]);
  }
  if (t.size() < 2) throw InputError(path + ": a record needs at least 2 values");
  const double dt = t[1] - t[0];
  if (!(std::isfinite(dt) && dt > 0.0))
    throw InputError(path + ": the time column must increase: the first two times give dt = " + show(dt) + " s");
  check_dt_range(dt, path, "the first two times give the time step");
  return parse_plain_record_text(text, path, dt, unit);
}

Record make_plain_record(const double* values, std::size_t n, double dt_s, AccelerationUnit unit,
                         const std::string& name) {
  check_dt_range(dt_s, name, "time step");
  if (n < 2) throw InputError(name + ": a record needs at least 2 values");
  Record r;
  r.format = "plain";
  r.dt = dt_s;
  r.name = name;
  const double factor = to_m_s2(unit);
  r.acc.reserve(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double a = values[i] * factor;
    if (!std::isfinite(a))
      throw InputError(name + ": value " + std::to_string(i) + " is " + show(values[i]) +
                       (std::isfinite(values[i]) ? ", which overflows once converted to m/s^2" : "") +
                       " (expected a finite acceleration)");
    r.acc.push_back(a);
  }
  return r;
}

double scale_factor_to_pga(const Record& record, double target_pga_m_s2) {
  if (!(std::isfinite(target_pga_m_s2) && target_pga_m_s2 > 0.0))
    throw InputError("target PGA must be positive (m/s^2)");
  const double pga = record.pga();
  if (!(pga > 0.0)) throw InputError("record '" + record.name + "' has zero PGA: it cannot be scaled");
  return target_pga_m_s2 / pga;
}

}  // namespace assess
