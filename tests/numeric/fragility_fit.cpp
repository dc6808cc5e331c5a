// Lognormal fragility fits (Baker 2015): the MLE on binomial stripe counts
// recovers the generating lognormal within its computed sampling error, and
// exactly from expected counts; the IDA moment fit against hand-computed
// moments; degenerate data are reported, not fitted.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/risk/lognormal_fragility.hpp>
#include <assess/support/error.hpp>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

// Expected counts n P(im) are fitted exactly by the MLE (the score vanishes
// at the true parameters): only the scoring's convergence tolerance remains.
constexpr double tol_exact_ln_theta = 1e-8;  // - (ln of m/s^2)
constexpr double tol_exact_beta = 1e-8;      // -
// Coverage of the nominal 95 % interval (+-1.96 SE) over 400 replicates:
// binomial sampling error of the coverage itself is sqrt(.95*.05/400) = 0.011,
// so [0.91, 0.99] is +-3.6 of its standard errors.
constexpr double coverage_min = 0.91, coverage_max = 0.99;

namespace {

std::uint64_t splitmix64(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
double uniform(std::uint64_t& s) { return double(splitmix64(s) >> 11) * 0x1.0p-53; }

// Synthetic MSA: n Bernoulli(P(im_j)) draws per stripe.
std::vector<StripeCount> synthetic(const LognormalFragility& f, const std::vector<double>& ims, int n,
                                   std::uint64_t& state) {
  std::vector<StripeCount> s;
  for (double im : ims) {
    const double p = f.probability(im);
    int k = 0;
    for (int i = 0; i < n; ++i) k += uniform(state) < p ? 1 : 0;
    s.push_back({im, double(n), double(k)});
  }
  return s;
}

const std::vector<double> stripe_ims{0.5, 0.8, 1.2, 1.6, 2.0, 2.5, 3.2, 4.0, 5.0, 6.5};  // m/s^2

}  // namespace

TEST_CASE("MLE from expected counts returns the generating theta and beta") {
  for (double theta : {1.5, 2.5, 4.0})
    for (double beta : {0.2, 0.35, 0.6}) {
      CAPTURE(theta);
      CAPTURE(beta);
      const LognormalFragility f{theta, beta};
      std::vector<StripeCount> s;
      for (double im : stripe_ims) s.push_back({im, 40.0, 40.0 * f.probability(im)});
      const FragilityFit fit = fit_lognormal_mle(s);
      REQUIRE(fit.ok());
      CHECK_CLOSE(std::log(fit.fragility.theta), std::log(theta), abs_tol(tol_exact_ln_theta));
      CHECK_CLOSE(fit.fragility.beta, beta, abs_tol(tol_exact_beta));
      CHECK(fit.se_ln_theta > 0.0);
      CHECK(fit.se_beta > 0.0);
    }
}

TEST_CASE("MLE from binomial draws: within the computed sampling error, with the nominal coverage") {
  const LognormalFragility truth{2.4, 0.4};  // m/s^2, -
  std::uint64_t state = 20150101;
  int replicates = 400, in_theta = 0, in_beta = 0, fitted = 0;
  for (int r = 0; r < replicates; ++r) {
    const FragilityFit fit = fit_lognormal_mle(synthetic(truth, stripe_ims, 20, state));
    if (!fit.ok()) continue;
    ++fitted;
    in_theta += std::fabs(std::log(fit.fragility.theta / truth.theta)) <= 1.96 * fit.se_ln_theta ? 1 : 0;
    in_beta += std::fabs(fit.fragility.beta - truth.beta) <= 1.96 * fit.se_beta ? 1 : 0;
  }
  CHECK(fitted == replicates);
  const double cov_theta = double(in_theta) / fitted, cov_beta = double(in_beta) / fitted;
  CAPTURE(cov_theta);
  CAPTURE(cov_beta);
  CHECK(cov_theta >= coverage_min);
  CHECK(cov_theta <= coverage_max);
  CHECK(cov_beta >= coverage_min);
  CHECK(cov_beta <= coverage_max);

  // One large sample: within 3 standard errors (the error is ~1/sqrt(n) smaller).
  const FragilityFit big = fit_lognormal_mle(synthetic(truth, stripe_ims, 2000, state));
  REQUIRE(big.ok());
  CHECK(std::fabs(std::log(big.fragility.theta / truth.theta)) <= 3 * big.se_ln_theta);
  CHECK(std::fabs(big.fragility.beta - truth.beta) <= 3 * big.se_beta);
  CHECK(big.se_ln_theta < 0.02);
}

TEST_CASE("MLE: degenerate counts are reported, not fitted") {
  std::vector<StripeCount> none{{1.0, 10, 0}, {2.0, 10, 0}, {3.0, 10, 0}};
  CHECK(fit_lognormal_mle(none).status == FragilityFit::Status::no_exceedance);
  std::vector<StripeCount> all{{1.0, 10, 10}, {2.0, 10, 10}};
  CHECK(fit_lognormal_mle(all).status == FragilityFit::Status::all_exceedance);
  std::vector<StripeCount> sep{{1.0, 10, 0}, {2.0, 10, 0}, {3.0, 10, 10}, {4.0, 10, 10}};
  const FragilityFit f = fit_lognormal_mle(sep);
  CHECK(f.status == FragilityFit::Status::separated);
  CHECK(f.message.find("[2, 3]") != std::string::npos);
  // Quasi-complete separation (Albert & Anderson 1984): exceedances only at
  // the highest stripe, mixed there: the likelihood's supremum is at beta -> 0.
  std::vector<StripeCount> quasi{{1.0, 6, 0}, {2.0, 6, 0}, {3.0, 6, 2}};
  const FragilityFit q = fit_lognormal_mle(quasi);
  CHECK(q.status == FragilityFit::Status::separated);
  CHECK(q.message.find("[3, 3]") != std::string::npos);
  // ... and at a middle stripe between all-free and all-reaching ones.
  std::vector<StripeCount> quasi_mid{{1.0, 6, 0}, {2.0, 6, 3}, {3.0, 6, 6}};
  CHECK(fit_lognormal_mle(quasi_mid).status == FragilityFit::Status::separated);
  // Two mixed stripes: the MLE exists (not separated).
  std::vector<StripeCount> two_mixed{{1.0, 6, 0}, {2.0, 6, 1}, {3.0, 6, 4}};
  CHECK(fit_lognormal_mle(two_mixed).status == FragilityFit::Status::ok);
  CHECK(fit_lognormal_mle({{1.0, 10, 3}}).status == FragilityFit::Status::too_few);
  // A fraction that falls with the intensity has no lognormal fit.
  std::vector<StripeCount> down{{1.0, 10, 6}, {2.0, 10, 5}, {3.0, 10, 4}};
  CHECK(fit_lognormal_mle(down).status == FragilityFit::Status::no_trend);
  CHECK_THROWS_AS(fit_lognormal_mle({{1.0, 10, 11}, {2.0, 10, 3}}), InputError);
  CHECK_THROWS_AS(fit_lognormal_mle({{0.0, 10, 1}, {2.0, 10, 3}}), InputError);
  CHECK_THROWS_AS(fit_lognormal_mle({{NAN, 10, 1}, {2.0, 10, 3}}), InputError);
}

TEST_CASE("IDA fit: moments of ln im_c (Baker 2015 Eqs. 2-3)") {
  // ln im_c = {0, ln 2, ln 4}: mean ln 2, sample variance (ln 2)^2 (n - 1 = 2).
  const FragilityFit f = fit_lognormal_ida({1.0, 2.0, 4.0});
  REQUIRE(f.ok());
  CHECK_CLOSE(f.fragility.theta, 2.0, rel_tol(1e-14));
  CHECK_CLOSE(f.fragility.beta, std::log(2.0), rel_tol(1e-14));
  CHECK_CLOSE(f.se_ln_theta, std::log(2.0) / std::sqrt(3.0), rel_tol(1e-14));
  CHECK(fit_lognormal_ida({2.0, 2.0}).status == FragilityFit::Status::separated);
  CHECK(fit_lognormal_ida({2.0}).status == FragilityFit::Status::too_few);
  CHECK_THROWS_AS(fit_lognormal_ida({2.0, -1.0}), InputError);
}

TEST_CASE("censored IDA fit: narrow intervals give the lognormal MLE; censoring is used, not dropped") {
  // Intervals of +-0.1 % about {1, 2, 4}: the MLE of a lognormal sample is
  // theta = geometric mean, beta = sqrt(sum ln^2 / n) (divisor n, not n - 1).
  std::vector<CensoredIntensity> v;
  for (double x : {1.0, 2.0, 4.0}) v.push_back({x / 1.001, x * 1.001});
  const FragilityFit f = fit_lognormal_censored(v);
  REQUIRE(f.ok());
  const double tol_interval = 2e-3;  // - : the intervals' half-width in ln units, 1e-3, twice
  CHECK_CLOSE(std::log(f.fragility.theta), std::log(2.0), abs_tol(tol_interval));
  CHECK_CLOSE(f.fragility.beta, std::log(2.0) * std::sqrt(2.0 / 3.0), abs_tol(tol_interval));
  // Observed information of a complete normal sample: SE(mu) = beta/sqrt(n).
  CHECK_CLOSE(f.se_ln_theta, f.fragility.beta / std::sqrt(3.0), rel_tol(0.01));
  // A record that never collapses up to 4 pulls the median up (dropping it would not).
  std::vector<CensoredIntensity> c = v;
  c.push_back({4.0, std::numeric_limits<double>::infinity()});
  const FragilityFit fc = fit_lognormal_censored(c);
  REQUIRE(fc.ok());
  CHECK(fc.fragility.theta > f.fragility.theta * 1.2);
  CHECK(fit_lognormal_censored({{1.0, INFINITY}, {2.0, INFINITY}}).status == FragilityFit::Status::no_exceedance);
  CHECK(fit_lognormal_censored({{0.0, 1.0}, {0.0, 1.0}}).status == FragilityFit::Status::all_exceedance);
  CHECK_THROWS_AS(fit_lognormal_censored({{2.0, 1.0}, {1.0, 2.0}}), InputError);
}

TEST_CASE("probability: Phi(ln(im/theta)/beta) at the median and one beta above") {
  const LognormalFragility f{2.0, 0.5};
  CHECK_CLOSE(f.probability(2.0), 0.5, abs_tol(1e-15));
  // Phi(1) = 0.841344746068543 (tables).
  CHECK_CLOSE(f.probability(2.0 * std::exp(0.5)), 0.841344746068543, abs_tol(1e-14));
  CHECK(f.probability(0.0) == 0.0);
}
