// lognormal_fragility.cpp: lognormal fragility fits (Baker 2015).
//
// Notation: x = ln im, probit model P = Phi(eta), eta = a + b x with
// b = 1/beta and a = -ln(theta)/beta (Baker 2015 Eq. 1 rewritten); mu =
// Phi(eta), phi = standard normal density.
#include "assess/risk/lognormal_fragility.hpp"

#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

namespace assess {

namespace {

constexpr double kSqrt2 = 1.41421356237309504880;

double normal_pdf(double x) { return std::exp(-0.5 * x * x) / std::sqrt(2.0 * units::pi); }

// ln Phi(x), accurate in the lower tail (asymptotic series below -30, where
// erfc underflows: Abramowitz & Stegun 26.2.12).
double log_normal_cdf(double x) {
  if (x > -30.0) return std::log(0.5 * std::erfc(-x / kSqrt2));
  const double x2 = x * x;
  return -0.5 * x2 - std::log(-x) - 0.5 * std::log(2.0 * units::pi) + std::log1p(-1.0 / x2 + 3.0 / (x2 * x2));
}

// phi(eta)^2 / (Phi(eta) Phi(-eta)), the probit weight, stable in the tails
// (tends to |eta| phi(eta) as |eta| grows).
double probit_weight(double eta) {
  const double e = std::fabs(eta);
  if (e > 30.0) return 0.0;
  const double lo = 0.5 * std::erfc(e / kSqrt2);  // Phi(-|eta|)
  const double f = normal_pdf(e);
  return f * f / (lo * (1.0 - lo));
}

// d mu / d eta divided by mu (1 - mu), times (k - n mu): the score term,
// stable in the tails.
double score_term(double eta, double n, double k) {
  // (k - n mu) phi / (mu (1 - mu)) = k phi/mu - (n - k) phi/(1 - mu)
  const double f = normal_pdf(eta);
  const double lo = 0.5 * std::erfc(-eta / kSqrt2), up = 0.5 * std::erfc(eta / kSqrt2);
  // Mills ratios phi/Phi; for large |eta| use the asymptote |eta|.
  const double r_lo = lo > 1e-300 ? f / lo : -eta;
  const double r_up = up > 1e-300 ? f / up : eta;
  return k * r_lo - (n - k) * r_up;
}

double log_likelihood(const std::vector<StripeCount>& s, double a, double b) {
  double L = 0.0;
  for (const StripeCount& c : s) {
    const double eta = a + b * std::log(c.im);
    if (c.k > 0) L += c.k * log_normal_cdf(eta);
    if (c.n - c.k > 0) L += (c.n - c.k) * log_normal_cdf(-eta);
  }
  return L;
}

std::string fmt(double v) {
  char buf[32];
  std::snprintf(buf, sizeof buf, "%.4g", v);
  return buf;
}

}  // namespace

double normal_cdf(double x) { return 0.5 * std::erfc(-x / kSqrt2); }

double LognormalFragility::probability(double im) const {
  if (!(im > 0.0)) return 0.0;
  if (beta <= 0.0) return im >= theta ? 1.0 : 0.0;
  return normal_cdf(std::log(im / theta) / beta);
}

std::string to_string(FragilityFit::Status s) {
  switch (s) {
    case FragilityFit::Status::ok: return "ok";
    case FragilityFit::Status::no_exceedance: return "no_exceedance";
    case FragilityFit::Status::all_exceedance: return "all_exceedance";
    case FragilityFit::Status::separated: return "separated";
    case FragilityFit::Status::too_few: return "too_few";
    case FragilityFit::Status::not_converged: return "not_converged";
    case FragilityFit::Status::no_trend: return "no_trend";
  }
  return "?";
}

FragilityFit fit_lognormal_mle(const std::vector<StripeCount>& input) {
  std::vector<StripeCount> s;
  for (std::size_t i = 0; i < input.size(); ++i) {
    const StripeCount& c = input[i];
    if (!(c.im > 0.0) || !std::isfinite(c.im) || !(c.n >= 0.0) || !std::isfinite(c.n) || !(c.k >= 0.0) ||
        !(c.k <= c.n))
      throw InputError("fragility fit: stripe " + std::to_string(i) + " needs im > 0, n >= 0 and 0 <= k <= n (im " +
                       fmt(c.im) + ", n " + fmt(c.n) + ", k " + fmt(c.k) + ")");
    if (c.n > 0.0) s.push_back(c);
  }
  FragilityFit fit;
  double n_tot = 0, k_tot = 0;
  for (const auto& c : s) n_tot += c.n, k_tot += c.k;
  std::sort(s.begin(), s.end(), [](const StripeCount& x, const StripeCount& y) { return x.im < y.im; });
  if (s.size() < 2 || s.front().im == s.back().im) {
    fit.status = FragilityFit::Status::too_few;
    fit.message = "at least 2 stripes at different intensities are needed";
    return fit;
  }
  if (k_tot == 0.0) {
    fit.status = FragilityFit::Status::no_exceedance;
    fit.message = "no analysis reached the limit state: the median lies above the highest stripe (" +
                  fmt(s.back().im) + ")";
    return fit;
  }
  if (k_tot == n_tot) {
    fit.status = FragilityFit::Status::all_exceedance;
    fit.message = "every analysis reached the limit state: the median lies below the lowest stripe (" +
                  fmt(s.front().im) + ")";
    return fit;
  }
  // Start: median at the geometric mean of the stripes weighted by how close
  // each stripe's fraction is to 1/2, beta = 0.4.
  double wsum = 0, xsum = 0;
  for (const auto& c : s) {
    const double w = 0.5 - std::fabs(c.k / c.n - 0.5) + 1e-3;
    wsum += w, xsum += w * std::log(c.im);
  }
  double b = 1.0 / 0.4, a = -b * xsum / wsum;
  double L = log_likelihood(s, a, b);
  constexpr int max_iter = 200;
  constexpr double b_max = 1e3;  // beta < 1e-3: treated as separated data
  bool converged = false;
  double i11 = 0, i12 = 0, i22 = 0;
  int it = 0;
  for (; it < max_iter; ++it) {
    double u1 = 0, u2 = 0;
    i11 = i12 = i22 = 0;
    for (const auto& c : s) {
      const double x = std::log(c.im), eta = a + b * x;
      const double sc = score_term(eta, c.n, c.k), w = c.n * probit_weight(eta);
      u1 += sc, u2 += sc * x;
      i11 += w, i12 += w * x, i22 += w * x * x;
    }
    const double det = i11 * i22 - i12 * i12;
    if (!(det > 0.0) || !std::isfinite(det)) break;
    double da = (i22 * u1 - i12 * u2) / det, db = (i11 * u2 - i12 * u1) / det;
    // Step halving: the log-likelihood must not decrease (and b stays > 0).
    double t = 1.0, La = L;
    for (int h = 0; h < 60; ++h, t *= 0.5) {
      if (b + t * db <= 0.0) continue;
      La = log_likelihood(s, a + t * da, b + t * db);
      if (La >= L - 1e-12 * std::fabs(L)) break;
    }
    a += t * da, b += t * db;
    const double change = std::fabs(t * da) + std::fabs(t * db) * (1.0 + std::fabs(std::log(s.back().im)));
    L = La;
    if (b > b_max) break;
    if (change < 1e-11 * (1.0 + std::fabs(a) + std::fabs(b))) {
      converged = true;
      ++it;
      break;
    }
  }
  fit.iterations = it;
  fit.log_likelihood = L;
  if (b > b_max || (!converged && b > 50.0)) {
    // Find the gap between the last stripe without and the first with exceedances.
    double lo = s.front().im, hi = s.back().im;
    for (const auto& c : s)
      if (c.k < c.n) lo = std::max(lo, c.im);
    for (auto it2 = s.rbegin(); it2 != s.rend(); ++it2)
      if (it2->k > 0) hi = std::min(hi, it2->im);
    fit.status = FragilityFit::Status::separated;
    fit.message = "the counts separate (beta -> 0): the median is only bracketed near [" + fmt(std::min(lo, hi)) +
                  ", " + fmt(std::max(lo, hi)) + "]; more records or stripes in between are needed";
    return fit;
  }
  if (!converged) {
    fit.status = FragilityFit::Status::not_converged;
    fit.message = "Fisher scoring did not converge in " + std::to_string(max_iter) + " iterations";
    return fit;
  }
  constexpr double beta_max = 20.0;
  if (!(b > 1.0 / beta_max) || !std::isfinite(std::exp(-a / b)) || !(std::exp(-a / b) > 0.0)) {
    fit.status = FragilityFit::Status::no_trend;
    fit.message = "the fraction reaching the limit state does not grow with the intensity (beta = " + fmt(1.0 / b) +
                  "): no lognormal fragility";
    return fit;
  }
  fit.status = FragilityFit::Status::ok;
  fit.fragility.beta = 1.0 / b;
  fit.fragility.theta = std::exp(-a / b);
  // Covariance of (a, b): inverse Fisher information; delta method for
  // ln theta = -a/b (gradient (-1/b, a/b^2)) and beta = 1/b (gradient (0, -1/b^2)).
  const double det = i11 * i22 - i12 * i12;
  const double caa = i22 / det, cbb = i11 / det, cab = -i12 / det;
  const double ga = -1.0 / b, gb = a / (b * b);
  fit.se_ln_theta = std::sqrt(std::max(0.0, ga * ga * caa + 2 * ga * gb * cab + gb * gb * cbb));
  fit.se_beta = std::sqrt(std::max(0.0, cbb)) / (b * b);
  return fit;
}

FragilityFit fit_lognormal_ida(const std::vector<double>& im_c) {
  FragilityFit fit;
  for (std::size_t i = 0; i < im_c.size(); ++i)
    if (!(im_c[i] > 0.0) || !std::isfinite(im_c[i]))
      throw InputError("IDA fit: collapse intensity " + std::to_string(i) + " must be > 0 and finite (got " +
                       fmt(im_c[i]) + ")");
  if (im_c.size() < 2) {
    fit.message = "at least 2 collapse intensities are needed";
    return fit;
  }
  double m = 0;
  for (double v : im_c) m += std::log(v);
  m /= double(im_c.size());
  double ss = 0;
  for (double v : im_c) ss += (std::log(v) - m) * (std::log(v) - m);
  const double n = double(im_c.size());
  const double beta = std::sqrt(ss / (n - 1.0));
  if (!(beta > 0.0)) {
    fit.status = FragilityFit::Status::separated;
    fit.message = "every record collapses at the same intensity: beta = 0";
    return fit;
  }
  fit.status = FragilityFit::Status::ok;
  fit.fragility = {std::exp(m), beta};
  fit.se_ln_theta = beta / std::sqrt(n);
  fit.se_beta = beta / std::sqrt(2.0 * (n - 1.0));
  return fit;
}

}  // namespace assess
