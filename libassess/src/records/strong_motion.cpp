// strong_motion.cpp: Arias intensity and Arias-based times.
//
// Notation: a_i sample i (m/s^2), h = dt (s), g_n = 9.80665 m/s^2.
// Arias (1970): I_A = pi/(2 g) * integral a(t)^2 dt. For a linear a(t) on a
// step, integral_0^h a^2 dt = h (a_0^2 + a_0 a_1 + a_1^2) / 3 (exact).
#include "assess/records/strong_motion.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>

namespace assess {

std::vector<double> cumulative_arias(const Record& r) {
  std::vector<double> I(r.acc.size(), 0.0);
  const double c = units::pi / (2.0 * units::g_n) * r.dt / 3.0;
  for (std::size_t i = 1; i < r.acc.size(); ++i) {
    const double a0 = r.acc[i - 1], a1 = r.acc[i];
    I[i] = I[i - 1] + c * (a0 * a0 + a0 * a1 + a1 * a1);
  }
  return I;
}

double arias_intensity(const Record& r) {
  const auto I = cumulative_arias(r);
  return I.empty() ? 0.0 : I.back();
}

double arias_time(const Record& r, double fraction) {
  if (!(fraction >= 0.0 && fraction <= 1.0)) throw InputError("arias_time: fraction must be in [0, 1]");
  const auto I = cumulative_arias(r);
  if (I.empty() || !(I.back() > 0.0)) return 0.0;
  const double target = fraction * I.back();
  for (std::size_t i = 1; i < I.size(); ++i)
    if (I[i] >= target) {
      const double span = I[i] - I[i - 1];
      const double x = span > 0.0 ? (target - I[i - 1]) / span : 0.0;
      return r.dt * (double(i - 1) + x);
    }
  return r.duration();
}

double significant_duration(const Record& r, double lo, double hi) {
  if (!(lo >= 0.0 && lo < hi && hi <= 1.0)) throw InputError("significant_duration: need 0 <= lo < hi <= 1");
  return arias_time(r, hi) - arias_time(r, lo);
}

}  // namespace assess

namespace assess {

Record strong_motion_part(const Record& r, double fraction) {
  Record out = r;
  if (r.acc.empty()) return out;
  const double t = arias_time(r, fraction);
  const std::size_t last = std::min(r.acc.size() - 1, static_cast<std::size_t>(std::ceil(t / r.dt - 1e-9)));
  out.acc.resize(last + 1);
  return out;
}

}  // namespace assess
