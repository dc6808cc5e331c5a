// collapse_rate.cpp: the risk integral (docs/theory/fragility.md §3).
#include "assess/risk/collapse_rate.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <cmath>

namespace assess {

double collapse_rate(const LognormalFragility& f, const HazardCurve& hazard) {
  if (!(f.theta > 0.0) || !(f.beta >= 0.0) || !std::isfinite(f.theta) || !std::isfinite(f.beta))
    throw InputError("risk integral: the fragility needs theta > 0 and beta >= 0");
  if (f.beta == 0.0) return hazard.lambda(f.theta);
  constexpr double z_max = 12.0;
  constexpr int n = 4800;
  const double h = 2.0 * z_max / n;
  double sum = 0.0;
  for (int i = 0; i <= n; ++i) {
    const double z = -z_max + i * h;
    const double w = (i == 0 || i == n) ? 0.5 : 1.0;
    sum += w * std::exp(-0.5 * z * z) * hazard.lambda(f.theta * std::exp(f.beta * z));
  }
  return sum * h / std::sqrt(2.0 * units::pi);
}

std::vector<double> risk_integrand(const LognormalFragility& f, const HazardCurve& hazard,
                                   const std::vector<double>& im) {
  std::vector<double> out;
  out.reserve(im.size());
  for (double x : im) out.push_back(f.probability(x) * hazard.density(x));
  return out;
}

double collapse_rate_power_law(double k0, double k, const LognormalFragility& f) {
  return k0 * std::pow(f.theta, -k) * std::exp(0.5 * k * k * f.beta * f.beta);
}

double probability_in(double lambda, double t) { return -std::expm1(-lambda * t); }

}  // namespace assess
