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
  // (Quasi-)complete separation, read from the counts: with one covariate
  // (ln im) the MLE exists only if no threshold c has every analysis below c
  // free of the limit state and every one above c reaching it (Albert &
  // Anderson 1984, Biometrika 71(1): complete or quasi-complete separation).
  // Stripes at the same im are pooled. Then beta -> 0 and the iteration cannot
  // converge: say so instead of "not converged".
  {
    std::vector<StripeCount> pooled;
    for (const auto& c : s) {
      if (!pooled.empty() && pooled.back().im == c.im) {
        pooled.back().n += c.n, pooled.back().k += c.k;
      } else {
        pooled.push_back(c);
      }
    }
    std::size_t first_hit = pooled.size(), last_miss = 0;
    for (std::size_t i = 0; i < pooled.size(); ++i)
      if (pooled[i].k > 0.0) {
        first_hit = i;
        break;
      }
    for (std::size_t i = pooled.size(); i-- > 0;)
      if (pooled[i].k < pooled[i].n) {
        last_miss = i;
        break;
      }
    if (first_hit >= last_miss) {  // at most one mixed stripe, between the all-zero and the all-one ones
      const double lo = pooled[std::min(first_hit, last_miss)].im, hi = pooled[std::max(first_hit, last_miss)].im;
      fit.status = FragilityFit::Status::separated;
      fit.message = "the counts separate (beta -> 0, no maximum-likelihood estimate): every analysis below " +
                    fmt(lo) + " is free of the limit state and every one above " + fmt(hi) +
                    " reaches it; the median is only bracketed near [" + fmt(lo) + ", " + fmt(hi) +
                    "]; more records or stripes in between are needed";
      return fit;
    }
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

namespace {

// ln[Phi(b) - Phi(a)], a < b, accurate when both are in one tail.
double log_interval(double a, double b) {
  if (a > 0.0) return log_interval(-b, -a);  // symmetry: Phi(b) - Phi(a) = Phi(-a) - Phi(-b)
  const double pb = normal_cdf(b), pa = normal_cdf(a);
  const double d = pb - pa;
  if (d > 1e-300) return std::log(d);
  return log_normal_cdf(b);  // both far in the lower tail: Phi(b) dominates
}

double censored_loglik(const std::vector<CensoredIntensity>& v, double mu, double beta) {
  double L = 0.0;
  for (const auto& c : v) {
    const double a = c.lo > 0.0 ? (std::log(c.lo) - mu) / beta : -std::numeric_limits<double>::infinity();
    const double b = std::isfinite(c.hi) ? (std::log(c.hi) - mu) / beta : std::numeric_limits<double>::infinity();
    if (std::isinf(a) && std::isinf(b)) continue;
    if (std::isinf(a)) L += log_normal_cdf(b);
    else if (std::isinf(b)) L += log_normal_cdf(-a);
    else L += log_interval(a, b);
  }
  return L;
}

}  // namespace

FragilityFit fit_lognormal_censored(const std::vector<CensoredIntensity>& v) {
  FragilityFit fit;
  bool any_upper = false, any_lower = false;
  double mu0 = 0.0;
  int n0 = 0;
  for (std::size_t i = 0; i < v.size(); ++i) {
    const auto& c = v[i];
    if (!(c.lo >= 0.0) || !(c.hi > c.lo) || std::isnan(c.hi))
      throw InputError("censored IDA fit: interval " + std::to_string(i) + " needs 0 <= lo < hi (got " + fmt(c.lo) +
                       ", " + fmt(c.hi) + ")");
    any_upper = any_upper || std::isfinite(c.hi);  // some collapse observed
    any_lower = any_lower || c.lo > 0.0;           // some survival observed
    if (c.lo > 0.0 && std::isfinite(c.hi)) mu0 += 0.5 * (std::log(c.lo) + std::log(c.hi)), ++n0;
    else if (c.lo > 0.0) mu0 += std::log(c.lo) + 0.5, ++n0;
    else mu0 += std::log(c.hi) - 0.5, ++n0;
  }
  if (v.size() < 2) {
    fit.message = "at least 2 records are needed";
    return fit;
  }
  if (!any_upper) {
    fit.status = FragilityFit::Status::no_exceedance;
    fit.message = "no record reaches the limit state at any level";
    return fit;
  }
  if (!any_lower) {
    fit.status = FragilityFit::Status::all_exceedance;
    fit.message = "every record reaches the limit state at the lowest level";
    return fit;
  }
  mu0 /= n0;
  // Nelder-Mead (Nelder & Mead 1965; standard coefficients 1, 2, 1/2, 1/2) on
  // f(mu, ln beta) = -ln L.
  auto f = [&](double mu, double lb) {
    if (lb < std::log(1e-4) || lb > std::log(50.0)) return std::numeric_limits<double>::infinity();
    const double L = censored_loglik(v, mu, std::exp(lb));
    return std::isfinite(L) ? -L : std::numeric_limits<double>::infinity();
  };
  double x[3][2] = {{mu0, std::log(0.4)}, {mu0 + 0.2, std::log(0.4)}, {mu0, std::log(0.6)}};
  double fx[3];
  for (int i = 0; i < 3; ++i) fx[i] = f(x[i][0], x[i][1]);
  int it = 0;
  bool converged = false;
  for (; it < 5000; ++it) {
    int o[3] = {0, 1, 2};
    std::sort(o, o + 3, [&](int a, int b) { return fx[a] < fx[b]; });
    const int best = o[0], mid = o[1], worst = o[2];
    const double size = std::fabs(x[worst][0] - x[best][0]) + std::fabs(x[worst][1] - x[best][1]) +
                        std::fabs(x[mid][0] - x[best][0]) + std::fabs(x[mid][1] - x[best][1]);
    if (size < 1e-10 && std::fabs(fx[worst] - fx[best]) < 1e-12 * (1.0 + std::fabs(fx[best]))) {
      converged = true;
      break;
    }
    const double c0 = 0.5 * (x[best][0] + x[mid][0]), c1 = 0.5 * (x[best][1] + x[mid][1]);
    const double r0 = c0 + (c0 - x[worst][0]), r1 = c1 + (c1 - x[worst][1]);
    const double fr = f(r0, r1);
    if (fr < fx[best]) {
      const double e0 = c0 + 2 * (c0 - x[worst][0]), e1 = c1 + 2 * (c1 - x[worst][1]);
      const double fe = f(e0, e1);
      if (fe < fr) x[worst][0] = e0, x[worst][1] = e1, fx[worst] = fe;
      else x[worst][0] = r0, x[worst][1] = r1, fx[worst] = fr;
    } else if (fr < fx[mid]) {
      x[worst][0] = r0, x[worst][1] = r1, fx[worst] = fr;
    } else {
      const bool outside = fr < fx[worst];
      const double k0 = outside ? c0 + 0.5 * (r0 - c0) : c0 + 0.5 * (x[worst][0] - c0);
      const double k1 = outside ? c1 + 0.5 * (r1 - c1) : c1 + 0.5 * (x[worst][1] - c1);
      const double fk = f(k0, k1);
      if (fk < std::min(fr, fx[worst])) {
        x[worst][0] = k0, x[worst][1] = k1, fx[worst] = fk;
      } else {
        for (int i : {mid, worst}) {
          x[i][0] = x[best][0] + 0.5 * (x[i][0] - x[best][0]);
          x[i][1] = x[best][1] + 0.5 * (x[i][1] - x[best][1]);
          fx[i] = f(x[i][0], x[i][1]);
        }
      }
    }
  }
  fit.iterations = it;
  int b = 0;
  for (int i = 1; i < 3; ++i)
    if (fx[i] < fx[b]) b = i;
  const double mu = x[b][0], beta = std::exp(x[b][1]);
  fit.log_likelihood = -fx[b];
  if (!converged) {
    fit.status = FragilityFit::Status::not_converged;
    fit.message = "Nelder-Mead did not converge in 5000 iterations";
    return fit;
  }
  if (beta < 1.01e-4) {
    fit.status = FragilityFit::Status::separated;
    fit.message = "the intervals leave beta -> 0: the median is only bracketed";
    return fit;
  }
  if (beta > 0.99 * 50.0) {
    fit.status = FragilityFit::Status::no_trend;
    fit.message = "the intervals give no finite dispersion (beta -> infinity)";
    return fit;
  }
  // Observed information: central-difference Hessian of -ln L in (mu, beta).
  auto g = [&](double m, double s) { return -censored_loglik(v, m, s); };
  const double hm = 1e-4 * std::max(1.0, std::fabs(mu)), hs = 1e-4 * beta;
  const double f0 = g(mu, beta);
  const double hmm = (g(mu + hm, beta) - 2 * f0 + g(mu - hm, beta)) / (hm * hm);
  const double hss = (g(mu, beta + hs) - 2 * f0 + g(mu, beta - hs)) / (hs * hs);
  const double hms = (g(mu + hm, beta + hs) - g(mu + hm, beta - hs) - g(mu - hm, beta + hs) + g(mu - hm, beta - hs)) /
                     (4 * hm * hs);
  const double det = hmm * hss - hms * hms;
  fit.status = FragilityFit::Status::ok;
  fit.fragility = {std::exp(mu), beta};
  if (det > 0.0 && hmm > 0.0) {
    fit.se_ln_theta = std::sqrt(hss / det);
    fit.se_beta = std::sqrt(hmm / det);
  }
  return fit;
}

}  // namespace assess
