// Private helpers of the CSV files written by campaign jobs (campaign_runner,
// risk/fragility_job): one number format, RFC 4180 quoting and splitting, and
// a strict number parse. One place, so every results file reads back the same.
#pragma once

#include <cstdio>
#include <stdexcept>
#include <string>
#include <vector>

namespace assess::csv {

/// A double with 10 significant digits (the format of every results column).
inline std::string num(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.10g", v);
  return buf;
}

/// A text field, quoted when it holds a comma, a quote or a line break
/// (line breaks become blanks: one row per line).
inline std::string quoted(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string out = "\"";
  for (char c : s) {
    if (c == '"') out += "\"\"";
    else if (c == '\n' || c == '\r') out += ' ';
    else out += c;
  }
  return out + "\"";
}

/// The fields of one line, quotes removed.
inline std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> f(1);
  bool q = false;
  for (std::size_t i = 0; i < line.size(); ++i) {
    const char c = line[i];
    if (q) {
      if (c == '"' && i + 1 < line.size() && line[i + 1] == '"') f.back() += '"', ++i;
      else if (c == '"') q = false;
      else f.back() += c;
    } else if (c == '"') {
      q = true;
    } else if (c == ',') {
      f.emplace_back();
    } else {
      f.back() += c;
    }
  }
  return f;
}

/// The whole field as a double; throws std::invalid_argument otherwise.
inline double to_double(const std::string& s) {
  std::size_t n = 0;
  const double v = std::stod(s, &n);
  if (n != s.size()) throw std::invalid_argument(s);
  return v;
}

}  // namespace assess::csv
