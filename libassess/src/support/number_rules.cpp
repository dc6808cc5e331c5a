// number_rules.cpp: the rule set for numbers of input files (number_rules.hpp).
#include "assess/support/number_rules.hpp"

#include <cerrno>
#include <cfloat>
#include <cmath>
#include <cstdio>
#include <cstdlib>

namespace assess {

bool is_subnormal(double v) { return v != 0.0 && std::isfinite(v) && std::fabs(v) < DBL_MIN; }

std::string number_for_message(double v) {
  if (std::isnan(v)) return "not a number";
  if (std::isinf(v)) return v > 0 ? "infinite" : "minus infinite";
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
}

std::string decimal_number_violation(const std::string& text, double& v) {
  const std::string got = "got '" + (text.size() > 40 ? text.substr(0, 40) + "..." : text) + "'";
  // Only the characters of a decimal number: digits, a sign, a point, an
  // exponent (strtod alone also reads "0x1p3", "inf", "nan" and " 6.5").
  bool other = text.empty();
  for (char c : text)
    if (!((c >= '0' && c <= '9') || c == '+' || c == '-' || c == '.' || c == 'e' || c == 'E')) {
      if (c == 'x' || c == 'X') return "must be a decimal number, " + got + " (a hexadecimal number)";
      other = true;
    }
  if (other) {
    std::string lower;
    for (char d : text) lower += static_cast<char>(d >= 'A' && d <= 'Z' ? d - 'A' + 'a' : d);
    if (lower.find("inf") != std::string::npos || lower.find("nan") != std::string::npos)
      return "must be a finite number, " + got;
    return "expected a number, " + got;
  }
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(text.c_str(), &end);
  if (end == text.c_str() || *end != '\0') return "expected a number, " + got;
  if (!std::isfinite(x)) return "must be a finite number, " + got + " (beyond the range of a double, 1.8e308)";
  const std::size_t exp = text.find_first_of("eE");
  const bool underflow = errno == ERANGE && x == 0.0 && text.find_first_of("123456789") < exp;
  if (is_subnormal(x) || underflow)
    return "must be a number of normal size, " + got + " (a subnormal number, |x| < 2.2e-308)";
  v = x;
  return "";
}

namespace {

// The length of the UTF-8 sequence starting at s[i] (RFC 3629: no overlong
// forms, no surrogates, at most U+10FFFF), or 0 when it is not valid.
std::size_t utf8_length(const std::string& s, std::size_t i) {
  const auto at = [&](std::size_t k) { return i + k < s.size() ? static_cast<unsigned char>(s[i + k]) : 0u; };
  const unsigned c = at(0);
  const auto cont = [&](std::size_t k) { return (at(k) & 0xC0u) == 0x80u; };
  if (c < 0x80) return 1;
  if (c >= 0xC2 && c <= 0xDF) return cont(1) ? 2 : 0;
  if (c >= 0xE0 && c <= 0xEF) {
    const unsigned c1 = at(1);
    if ((c == 0xE0 && c1 < 0xA0) || (c == 0xED && c1 > 0x9F)) return 0;
    return cont(1) && cont(2) ? 3 : 0;
  }
  if (c >= 0xF0 && c <= 0xF4) {
    const unsigned c1 = at(1);
    if ((c == 0xF0 && c1 < 0x90) || (c == 0xF4 && c1 > 0x8F)) return 0;
    return cont(1) && cont(2) && cont(3) ? 4 : 0;
  }
  return 0;
}

}  // namespace

std::string control_character_violation(const std::string& s) {
  for (std::size_t i = 0; i < s.size(); ++i) {
    // Not UTF-8 (issue 39's fuzzer: a catalogue written from such a text
    // could not be written as JSON): named by its byte.
    const std::size_t n = utf8_length(s, i);
    if (n == 0) {
      char code[8];
      std::snprintf(code, sizeof code, "0x%02X", static_cast<unsigned char>(s[i]));
      return std::string("the text is not valid UTF-8 (byte ") + code + " at character " + std::to_string(i + 1) + ")";
    }
    const unsigned char c = static_cast<unsigned char>(s[i]);
    const bool c1 = c == 0xC2 && i + 1 < s.size() && static_cast<unsigned char>(s[i + 1]) >= 0x80 &&
                    static_cast<unsigned char>(s[i + 1]) <= 0x9F;
    if (c < 0x20 || c == 0x7F || c1) {
      char code[16];
      std::snprintf(code, sizeof code, "U+%04X", c1 ? static_cast<unsigned char>(s[i + 1]) : c);
      return std::string("the text holds a control character (") + code + ") at character " + std::to_string(i + 1);
    }
    i += n - 1;  // the rest of the sequence
  }
  return "";
}

std::string number_rule_violation(double v, const NumberRule& r) {
  const std::string range = std::string(r.zero_ok ? "0 or " : "") + (r.lo_open ? "in (" : "in [") +
                            number_for_message(r.lo) + ", " + number_for_message(r.hi) + "] " + r.unit +
                            (r.why && *r.why ? std::string(" (") + r.why + ")" : std::string());
  if (std::isnan(v)) return "not a number: expected a finite number " + range;
  if (std::isinf(v)) return "value " + number_for_message(v) + ": expected a finite number " + range;
  if (is_subnormal(v)) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", v);
    return std::string("value ") + b + " is a subnormal number (|x| < 2.2e-308), not a physical value: expected " + range;
  }
  if (r.zero_ok && v == 0.0) return "";
  const bool below = r.lo_open ? !(v > r.lo) : !(v >= r.lo);
  if (below || !(v <= r.hi)) return "value " + number_for_message(v) + " out of range: expected " + range;
  return "";
}

}  // namespace assess
