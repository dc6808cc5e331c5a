// plot_axis.cpp: ranges, ticks and tick labels of the plot axes
// (plot_layout.hpp). Tick values are integers times a power of ten and are
// printed from those integers, so labels are exact ("0.3", not
// "0.30000000000000004") and identical on every run.
#include "assess/report/plot_layout.hpp"

#include "report/svg_text.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <limits>

namespace assess {

namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kEps = 1e-9;

/// 10^e for an integer e, exact where 10^|e| is (|e| <= 22).
double pow10i(int e) {
  if (e >= 0 && e <= 22) {
    double p = 1.0;
    for (int i = 0; i < e; ++i) p *= 10.0;
    return p;
  }
  if (e < 0 && e >= -22) return 1.0 / pow10i(-e);
  return std::pow(10.0, double(e));
}

/// n x 10^e as a double (division for e < 0: exact ties with decimal input).
double value_of(long long n, int e) { return e >= 0 ? double(n) * pow10i(e) : double(n) / pow10i(-e); }

std::string superscript(int k) {
  static const char* digits[] = {"⁰", "¹", "²", "³", "⁴", "⁵", "⁶", "⁷", "⁸", "⁹"};
  std::string out = k < 0 ? "⁻" : "";
  const std::string d = std::to_string(std::abs(k));
  for (char c : d) out += digits[c - '0'];
  return out;
}

/// Label of n x 10^e with `decimals` digits after the point (plain), or
/// mantissa x 10^k (scientific).
std::string label_of(long long n, int e, int decimals, bool scientific) {
  if (n == 0) return "0";
  std::string sign = n < 0 ? "−" : "";  // U+2212 MINUS SIGN
  std::string digits = std::to_string(n < 0 ? -n : n);
  if (scientific) {
    const int k = e + int(digits.size()) - 1;
    std::string rest = digits.substr(1);
    while (!rest.empty() && rest.back() == '0') rest.pop_back();
    const std::string mantissa = digits.substr(0, 1) + (rest.empty() ? "" : "." + rest);
    return sign + (mantissa == "1" ? "" : mantissa + "×") + "10" + superscript(k);
  }
  if (e >= 0) return sign + digits + std::string(std::size_t(e), '0');
  // n x 10^e with -e digits after the point, then padded or cut to `decimals`
  // (cutting only drops zeros: decimals >= the step's own).
  const std::size_t frac = std::size_t(-e);
  if (digits.size() <= frac) digits = std::string(frac + 1 - digits.size(), '0') + digits;
  std::string whole = digits.substr(0, digits.size() - frac), part = digits.substr(digits.size() - frac);
  if (int(part.size()) > decimals) part.resize(std::size_t(std::max(decimals, 0)));
  while (int(part.size()) < decimals) part += '0';
  return sign + whole + (part.empty() ? "" : "." + part);
}

/// A step of 1, 2 or 5 x 10^e.
struct Step {
  int m = 1, e = 0;
  double value() const { return value_of(m, e); }
  Step next() const { return m == 1 ? Step{2, e} : m == 2 ? Step{5, e} : Step{1, e + 1}; }
};

/// The smallest nice step >= raw (raw > 0, finite).
Step nice_at_least(double raw) {
  int e = int(std::floor(std::log10(raw)));
  const double f = raw / pow10i(e);
  if (f <= 1.0 + kEps) return {1, e};
  if (f <= 2.0 + kEps) return {2, e};
  if (f <= 5.0 + kEps) return {5, e};
  return {1, e + 1};
}

/// Candidate labelled ticks: values n x 10^e.
struct Candidate {
  std::vector<long long> n;
  int e = 0;
};

/// True if labels at these SVG positions keep clear of each other.
bool labels_fit(const std::vector<double>& px, const std::vector<std::string>& labels, double fs, bool vertical) {
  for (std::size_t i = 1; i < px.size(); ++i) {
    const double gap = std::fabs(px[i] - px[i - 1]);
    if (vertical) {
      if (gap < 3.0 * fs) return false;
    } else {
      const double need = 0.5 * (detail::text_width(labels[i], fs) + detail::text_width(labels[i - 1], fs)) + fs;
      if (gap < std::max(4.5 * fs, need)) return false;
    }
  }
  return true;
}

struct Mapper {
  double lo, hi, px_lo, px_hi;
  bool log;
  double operator()(double v) const {
    if (log) return px_lo + (std::log10(v) - std::log10(lo)) / (std::log10(hi) - std::log10(lo)) * (px_hi - px_lo);
    return px_lo + (v - lo) / (hi - lo) * (px_hi - px_lo);
  }
};

/// Labelled ticks n x 10^e over [lo, hi] for a step; decimals from the step.
std::vector<AxisTick> linear_ticks(double lo, double hi, Step s, const Mapper& map, bool force_scientific,
                                   std::vector<double>* px) {
  const double st = s.value();
  std::vector<AxisTick> ticks;
  // Ticks are integers k x step: beyond 1e15 steps from 0 they are not exact
  // (a range far narrower than its distance from 0; the caller labels its ends).
  if (!(std::fabs(lo / st) < 1e15 && std::fabs(hi / st) < 1e15)) return ticks;
  const long long k0 = (long long)std::ceil(lo / st - kEps), k1 = (long long)std::floor(hi / st + kEps);
  if (k1 - k0 > 10000) return ticks;
  double top = 0.0;
  for (long long k = k0; k <= k1; ++k) top = std::max(top, std::fabs(value_of(k * s.m, s.e)));
  const bool sci = force_scientific || s.e < -4 || top >= 1e7;
  for (long long k = k0; k <= k1; ++k) {
    const long long n = k * s.m;
    AxisTick t;
    t.value = value_of(n, s.e);
    t.label = label_of(n, s.e, std::max(0, -s.e), sci);
    ticks.push_back(t);
    if (px) px->push_back(map(t.value));
  }
  return ticks;
}

std::vector<std::string> labels(const std::vector<AxisTick>& ticks) {
  std::vector<std::string> out;
  for (const auto& t : ticks) out.push_back(t.label);
  return out;
}

/// The smallest nice step over [lo, hi] whose labels fit (at least two
/// ticks where the axis allows), and its ticks.
std::pair<Step, std::vector<AxisTick>> fitting_step(double lo, double hi, const Mapper& map, double fs, bool vertical) {
  const double length = std::fabs(map.px_hi - map.px_lo);
  const double min_gap = vertical ? 3.0 * fs : 4.5 * fs;
  const double max_intervals = std::max(1.0, length / min_gap);
  Step s = nice_at_least((hi - lo) / max_intervals);
  std::pair<Step, std::vector<AxisTick>> best{s, {}};
  for (int guard = 0; guard < 40; ++guard, s = s.next()) {
    std::vector<double> px;
    std::vector<AxisTick> ticks = linear_ticks(lo, hi, s, map, false, &px);
    if (ticks.empty()) break;  // steps beyond the range
    best = {s, ticks};
    if (labels_fit(px, labels(ticks), fs, vertical)) break;  // (a single label always fits)
  }
  return best;
}

PlotAxis linear_axis(double lo, double hi, bool fixed, double px_lo, double px_hi, double fs, bool vertical) {
  PlotAxis a;
  a.px_lo = px_lo, a.px_hi = px_hi;
  if (!fixed) {
    const double mag = std::max(std::fabs(lo), std::fabs(hi));
    if (!(hi - lo > 1e-9 * mag) || mag == 0.0) {  // degenerate extent
      const double mid = 0.5 * (lo + hi), d = mid == 0.0 ? 1.0 : 0.1 * std::fabs(mid);
      lo = mid - d, hi = mid + d;
    }
    // Widen to multiples of the step; the step of the widened range may
    // differ, so repeat until it settles.
    double dlo = lo, dhi = hi;
    for (int it = 0; it < 4; ++it) {
      const Step s = fitting_step(lo, hi, Mapper{lo, hi, px_lo, px_hi, false}, fs, vertical).first;
      const double st = s.value();
      const double nlo = std::floor(dlo / st + kEps) * st, nhi = std::ceil(dhi / st - kEps) * st;
      const bool same = nlo == lo && nhi == hi;
      lo = nlo, hi = nhi > nlo ? nhi : nlo + st;
      if (same) break;
    }
  }
  a.lo = lo, a.hi = hi;
  const Mapper map{lo, hi, px_lo, px_hi, false};
  a.ticks = fitting_step(lo, hi, map, fs, vertical).second;
  if (a.ticks.empty()) {  // a tiny axis: its two ends
    for (double v : {lo, hi}) {
      char b[32];
      std::snprintf(b, sizeof b, "%.4g", v);
      a.ticks.push_back({v, b});
    }
  }
  return a;
}

PlotAxis log_axis(double lo, double hi, bool fixed, double px_lo, double px_hi, double fs, bool vertical) {
  PlotAxis a;
  a.log = true;
  a.px_lo = px_lo, a.px_hi = px_hi;
  if (!fixed) {
    int k0 = int(std::floor(std::log10(lo) + kEps)), k1 = int(std::ceil(std::log10(hi) - kEps));
    if (k1 <= k0) k1 = k0 + 1;
    lo = pow10i(k0), hi = pow10i(k1);
  }
  a.lo = lo, a.hi = hi;
  const Mapper map{lo, hi, px_lo, px_hi, true};
  const double la = std::log10(lo), lb = std::log10(hi), decades = lb - la;
  const double per_decade = std::fabs(px_hi - px_lo) / decades;
  const int d0 = int(std::ceil(la - kEps)), d1 = int(std::floor(lb + kEps));
  const bool sci = d0 < -4 || d1 > 5;
  const auto label = [&](int j, int k) { return label_of(j, k, std::max(0, -k), sci); };
  const auto inside = [&](double v) { return v >= lo * (1 - kEps) && v <= hi * (1 + kEps); };
  const auto add_minor = [&](std::vector<AxisTick>& ticks, const std::vector<int>& js) {
    for (int k = d0 - 1; k <= d1; ++k)
      for (int j : js) {
        const double v = value_of(j, k);
        if (inside(v)) ticks.push_back({v, ""});
      }
  };
  const auto finish = [&](std::vector<AxisTick> ticks) {
    std::stable_sort(ticks.begin(), ticks.end(), [](const AxisTick& p, const AxisTick& q) { return p.value < q.value; });
    a.ticks = std::move(ticks);
    return a;
  };
  // Few decades: 1, 2 and 5 of each decade labelled.
  if (decades <= 2.5) {
    std::vector<AxisTick> ticks;
    std::vector<double> px;
    for (int k = d0 - 1; k <= d1; ++k)
      for (int j : {1, 2, 5}) {
        const double v = value_of(j, k);
        if (inside(v)) ticks.push_back({v, label(j, k)}), px.push_back(map(v));
      }
    if (ticks.size() >= 3 && labels_fit(px, labels(ticks), fs, vertical)) {
      if (per_decade >= 30.0) add_minor(ticks, {3, 4, 6, 7, 8, 9});
      return finish(ticks);
    }
  }
  // Decades, every `stride`-th labelled.
  if (d1 - d0 >= 1) {
    for (int stride : {1, 2, 3, 5, 10, 20, 50, 100}) {
      std::vector<AxisTick> ticks;
      std::vector<double> px;
      const auto labelled = [stride](int k) { return ((k % stride) + stride) % stride == 0; };
      for (int k = d0; k <= d1; ++k)
        if (labelled(k)) ticks.push_back({value_of(1, k), label(1, k)}), px.push_back(map(value_of(1, k)));
      if (ticks.empty() || !labels_fit(px, labels(ticks), fs, vertical)) continue;
      if (stride == 1 && per_decade >= 30.0) {
        add_minor(ticks, {2, 3, 4, 5, 6, 7, 8, 9});
      } else if (stride > 1 && per_decade >= 6.0) {
        for (int k = d0; k <= d1; ++k)
          if (!labelled(k)) ticks.push_back({value_of(1, k), ""});
      }
      return finish(ticks);
    }
  }
  // Within about a decade: linear steps at their log positions.
  std::vector<AxisTick> ticks = fitting_step(lo, hi, map, fs, vertical).second;
  if (ticks.empty())
    for (double v : {lo, hi}) {
      char b[32];
      std::snprintf(b, sizeof b, "%.4g", v);
      ticks.push_back({v, b});
    }
  return finish(ticks);
}

}  // namespace

double PlotAxis::to_px(double v) const {
  if (!std::isfinite(v) || (log && !(v > 0.0))) return kNaN;
  return Mapper{lo, hi, px_lo, px_hi, log}(v);
}

PlotAxis make_plot_axis(double lo, double hi, bool fixed, bool log, double px_lo, double px_hi, double font_size,
                        bool vertical) {
  // Defensive defaults: an empty or invalid extent (all data non-finite).
  if (!(std::isfinite(lo) && std::isfinite(hi)) || lo > hi || (log && !(lo > 0.0))) {
    lo = log ? 1.0 : 0.0, hi = log ? 10.0 : 1.0;
    fixed = false;
  }
  if (log) lo = std::max(lo, 1e-300), hi = std::min(std::max(hi, lo), 1e300);  // whole decades stay normal doubles
  if (fixed && !(lo < hi)) fixed = false;
  // A range wider than doubles can difference is narrowed (never in practice).
  if (!log && !std::isfinite(hi - lo)) lo = -1e300, hi = 1e300;
  return log ? log_axis(lo, hi, fixed, px_lo, px_hi, font_size, vertical)
             : linear_axis(lo, hi, fixed, px_lo, px_hi, font_size, vertical);
}

}  // namespace assess
