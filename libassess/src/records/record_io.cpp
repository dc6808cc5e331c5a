// record_io.cpp: accelerogram readers (PEER AT2, ESM/ITACA ASCII, GEM
// .cor.acc, plain text). Format notes: spectra/records/README.md §4.
//
// Notation: npts = number of samples declared by the header, dt = time step
// (s), factor = conversion of the file's unit to m/s^2 (g -> g_n = 9.80665,
// record files only; cm/s^2 -> 0.01).
#include "assess/records/record_io.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <map>
#include <regex>
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

/// Lines of a file with every '\r' removed (LF, CRLF and CR CR LF endings).
std::vector<std::string> read_lines(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("cannot open record file '" + path + "'");
  std::ostringstream ss;
  ss << in.rdbuf();
  std::string text = ss.str();
  text.erase(std::remove(text.begin(), text.end(), '\r'), text.end());
  std::vector<std::string> lines;
  std::istringstream is(text);
  for (std::string line; std::getline(is, line);) lines.push_back(line);
  return lines;
}

/// Appends the numbers of `line` to `out`. Numbers may touch (fixed-width
/// E15.7 fields with no blank before a minus sign). Throws on anything else.
void parse_numbers(const std::string& line, const std::string& path, std::size_t line_no,
                   std::vector<double>& out, double factor) {
  const char* p = line.c_str();
  while (*p) {
    while (*p == ' ' || *p == '\t' || *p == ',') ++p;
    if (!*p) break;
    char* end = nullptr;
    errno = 0;
    const double v = std::strtod(p, &end);
    if (end == p || errno == ERANGE || !std::isfinite(v)) {
      std::string tok(p);
      tok = tok.substr(0, tok.find_first_of(" \t"));
      throw InputError(path + ":" + std::to_string(line_no) + ": non-numeric value '" + tok +
                       "' (expected an acceleration value)");
    }
    out.push_back(v * factor);
    p = end;
  }
}

bool is_numeric_line(const std::string& line) {
  const std::string t = trim(line);
  if (t.empty()) return false;
  char* end = nullptr;
  std::strtod(t.c_str(), &end);
  return end != t.c_str() && (*end == '\0' || *end == ' ' || *end == '\t' || *end == '-' || *end == '+');
}

void check_dt(double dt, const std::string& path) {
  if (!(std::isfinite(dt) && dt > 0.0))
    throw InputError(path + ": time step must be positive (s), the header gives " + std::to_string(dt));
}

/// Reads data values from line index `first` to the end and checks the count.
std::vector<double> read_data(const std::vector<std::string>& lines, std::size_t first, long npts,
                              const std::string& path, double factor) {
  std::vector<double> acc;
  if (npts > 0) acc.reserve(static_cast<std::size_t>(npts));
  for (std::size_t i = first; i < lines.size(); ++i) parse_numbers(lines[i], path, i + 1, acc, factor);
  if (npts >= 0 && static_cast<long>(acc.size()) < npts)
    throw InputError(path + ": truncated record: the header declares " + std::to_string(npts) +
                     " points, the file has " + std::to_string(acc.size()));
  if (npts >= 0 && static_cast<long>(acc.size()) > npts)
    throw InputError(path + ": the file has " + std::to_string(acc.size()) + " values, more than the " +
                     std::to_string(npts) + " points its header declares");
  return acc;
}

Record read_at2(const std::vector<std::string>& lines, const std::string& path) {
  static const std::regex npts_re(R"(NPTS\s*=\s*([0-9]+))", std::regex::icase);
  static const std::regex dt_re(R"(\bDT\s*=\s*([-+0-9.eE]+))", std::regex::icase);
  static const std::regex numbers_first_re(R"(^\s*([0-9]+)\s+([-+0-9.eE]+)\s+NPTS\s*,\s*DT)", std::regex::icase);
  std::size_t k = 0;
  long npts = -1;
  double dt = 0.0;
  for (; k < lines.size() && k < 10; ++k) {
    std::smatch m1, m2;
    if (std::regex_search(lines[k], m1, npts_re) && std::regex_search(lines[k], m2, dt_re)) {
      npts = std::stol(m1[1]);
      dt = std::strtod(m2[1].str().c_str(), nullptr);
      break;
    }
    if (std::regex_search(lines[k], m1, numbers_first_re)) {
      npts = std::stol(m1[1]);
      dt = std::strtod(m1[2].str().c_str(), nullptr);
      break;
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
  const double dt = std::strtod(need("SAMPLING_INTERVAL_S").c_str(), nullptr);
  check_dt(dt, path);
  const long npts = std::stol(need("NDATA"));
  const std::string unit = need("UNITS");
  Record r;
  const std::string version = h["DATABASE_VERSION"] + h["DATA_VERSION"];
  r.format = version.find("ITACA") != std::string::npos ? "ITACA ASCII" : "ESM ASCII";
  r.dt = dt;
  r.event = h["EVENT_NAME"] + (h["EVENT_DATE_YYYYMMDD"].empty() ? "" : ", " + h["EVENT_DATE_YYYYMMDD"]);
  r.station = h["STATION_CODE"] + (h["STATION_NAME"].empty() ? "" : " " + h["STATION_NAME"]);
  r.component = !h["COMPONENT"].empty() ? h["COMPONENT"] : h["STREAM"];
  r.acc = read_data(lines, k, npts, path, to_m_s2(parse_acceleration_unit(unit)));
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
  const double dt = std::strtod(need("Time Increment (s)").c_str(), nullptr);
  check_dt(dt, path);
  const long npts = std::stol(need("Number of Data"));
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

Record read_record(const std::string& path) {
  const std::vector<std::string> lines = read_lines(path);
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
  return r;
}

Record read_plain_record(const std::string& path, double dt_s, AccelerationUnit unit) {
  if (!(std::isfinite(dt_s) && dt_s > 0.0))
    throw InputError(path + ": time step must be positive (s), got " + std::to_string(dt_s));
  const std::vector<std::string> lines = read_lines(path);
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
    if (columns == 0) columns = row.size();
    if (row.size() != columns || columns > 2)
      throw InputError(path + ":" + std::to_string(i + 1) + ": expected " +
                       std::to_string(columns > 2 ? 2 : columns) + " column(s), found " + std::to_string(row.size()));
    if (columns == 2) {
      if (!r.acc.empty() && std::fabs(row[0] - t_prev - dt_s) > 1e-6 * dt_s + 1e-9)
        throw InputError(path + ":" + std::to_string(i + 1) + ": time column spacing " +
                         std::to_string(row[0] - t_prev) + " s differs from the declared time step " +
                         std::to_string(dt_s) + " s");
      t_prev = row[0];
    }
    r.acc.push_back(row.back() * factor);
  }
  if (r.acc.size() < 2) throw InputError(path + ": a record needs at least 2 values");
  return r;
}

Record read_plain_record(const std::string& path, AccelerationUnit unit) {
  // dt = the spacing of the first two times; read_plain_record(path, dt, unit)
  // then checks every later spacing against it.
  const std::vector<std::string> lines = read_lines(path);
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
    throw InputError(path + ": the time column must increase: the first two times give dt = " + std::to_string(dt) +
                     " s");
  return read_plain_record(path, dt, unit);
}

double scale_factor_to_pga(const Record& record, double target_pga_m_s2) {
  if (!(std::isfinite(target_pga_m_s2) && target_pga_m_s2 > 0.0))
    throw InputError("target PGA must be positive (m/s^2)");
  const double pga = record.pga();
  if (!(pga > 0.0)) throw InputError("record '" + record.name + "' has zero PGA: it cannot be scaled");
  return target_pga_m_s2 / pga;
}

}  // namespace assess
