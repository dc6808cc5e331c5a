// number_rules.cpp: the rule set for numbers of input files (number_rules.hpp).
#include "assess/support/number_rules.hpp"

#include <cfloat>
#include <cmath>
#include <cstdio>

namespace assess {

bool is_subnormal(double v) { return v != 0.0 && std::isfinite(v) && std::fabs(v) < DBL_MIN; }

std::string number_for_message(double v) {
  if (std::isnan(v)) return "not a number";
  if (std::isinf(v)) return v > 0 ? "infinite" : "minus infinite";
  char b[32];
  std::snprintf(b, sizeof b, "%g", v);
  return b;
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
