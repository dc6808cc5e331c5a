// The risk integral lambda_c = int P(C|im) |d lambda| against the closed form
// of Cornell et al. (2002) for a power-law hazard and a lognormal fragility,
// and the hazard curve's log-log interpolation/extrapolation.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/hazard/hazard_curve.hpp>
#include <assess/risk/collapse_rate.hpp>
#include <assess/support/error.hpp>
#include <assess/support/units.hpp>

#include <cmath>
#include <vector>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

// The trapezoidal rule on z in [-12, 12] with h = 0.005 is spectrally
// accurate for a Gaussian times an exponential in z: 1e-9 relative (-).
constexpr double tol_rate_rel = 1e-9;
// Log-log interpolation reproduces a power law to round-off (-).
constexpr double tol_curve_rel = 1e-12;

namespace {
// lambda = k0 im^-k through the nine grid return periods.
HazardCurve power_law(double k0, double k) {
  std::vector<HazardPoint> pts;
  for (double tr : grid_return_periods) {
    const double lam = 1.0 / tr;
    pts.push_back({std::pow(k0 / lam, 1.0 / k), lam, tr});
  }
  return HazardCurve(pts);
}
}  // namespace

TEST_CASE("lambda_c = k0 theta^-k exp(k^2 beta^2 / 2) (Cornell et al. 2002)") {
  for (double k : {1.5, 2.5, 3.5})
    for (double beta : {0.0, 0.2, 0.4, 0.7})
      for (double theta : {0.5, 2.0, 8.0}) {  // m/s^2: below, inside and above the 9 points
        CAPTURE(k);
        CAPTURE(beta);
        CAPTURE(theta);
        const double k0 = 1e-3;  // 1/year at im = 1 m/s^2
        const HazardCurve h = power_law(k0, k);
        const LognormalFragility f{theta, beta};
        CHECK_CLOSE(collapse_rate(f, h), collapse_rate_power_law(k0, k, f), rel_tol(tol_rate_rel));
      }
}

TEST_CASE("the integrand P |d lambda/d im| integrates to lambda_c") {
  const HazardCurve h = power_law(2e-3, 2.2);
  const LognormalFragility f{3.0, 0.45};
  std::vector<double> im;
  for (int i = 0; i <= 20000; ++i) im.push_back(0.05 * std::pow(1000.0, i / 20000.0));
  const std::vector<double> y = risk_integrand(f, h, im);
  double sum = 0;
  for (std::size_t i = 1; i < im.size(); ++i) sum += 0.5 * (y[i] + y[i - 1]) * (im[i] - im[i - 1]);
  // Above 50 m/s^2 P = 1 to 1e-15, so the tail adds lambda(50); below 0.05
  // m/s^2 P < 1e-12. Trapezoid on a log grid with 20000 intervals: ~1e-7 relative.
  sum += h.lambda(im.back());
  CHECK_CLOSE(sum, collapse_rate(f, h), rel_tol(1e-6));
}

TEST_CASE("hazard curve: exact at the points, log-log between, power law beyond") {
  std::vector<HazardPoint> pts{{1.0, 1.0 / 30, 30}, {2.0, 1.0 / 475, 475}, {3.0, 1.0 / 2475, 2475}};
  const HazardCurve h(pts);
  for (const auto& p : pts) {
    CHECK_CLOSE(h.lambda(p.im), p.lambda, rel_tol(tol_curve_rel));
    CHECK_CLOSE(h.im_at_tr(p.TR), p.im, rel_tol(tol_curve_rel));
  }
  const double k1 = std::log(475.0 / 30.0) / std::log(2.0);
  CHECK_CLOSE(h.lambda(1.5), (1.0 / 30) * std::pow(1.5, -k1), rel_tol(tol_curve_rel));
  CHECK_CLOSE(h.lambda(0.5), (1.0 / 30) * std::pow(0.5, -k1), rel_tol(tol_curve_rel));
  const double k2 = std::log(2475.0 / 475.0) / std::log(1.5);
  CHECK_CLOSE(h.lambda(6.0), (1.0 / 2475) * std::pow(2.0, -k2), rel_tol(tol_curve_rel));
  CHECK_CLOSE(h.slope(6.0), k2, rel_tol(tol_curve_rel));
  CHECK_THROWS_AS(HazardCurve({{1.0, 0.1, 10}, {1.0, 0.01, 100}}), InputError);
  CHECK_THROWS_AS(HazardCurve({{1.0, 0.1, 10}}), InputError);
}

TEST_CASE("site hazard curve: points at Se(0) = ag S of the nine return periods") {
  SiteSpec spec;
  spec.lat = 42.35;
  spec.lon = 13.40;
  spec.conditions.soil = SoilClass::C;
  const Site site(spec);
  const HazardCurve h = site_pga_hazard_curve(site);
  REQUIRE(h.points().size() == 9);
  for (const auto& p : h.points()) {
    const ElasticSpectrum s(site.hazard_at_tr(p.TR), spec.conditions, 5.0);
    CHECK_CLOSE(p.im, s.ag() * s.S(), rel_tol(1e-14));
    CHECK_CLOSE(h.lambda(p.im), 1.0 / p.TR, rel_tol(tol_curve_rel));
  }
  const HazardCurve a = site_ag_hazard_curve(site);
  for (const auto& p : a.points()) CHECK_CLOSE(p.im, site.hazard_at_tr(p.TR).ag_g * units::g, rel_tol(1e-14));
  SiteSpec given;
  given.given[LimitState::SLV] = HazardParams{475, 0.25, 2.4, 0.3};
  CHECK_THROWS_AS(site_pga_hazard_curve(Site(given)), InputError);
}

TEST_CASE("probability over VN: 1 - exp(-lambda VN)") {
  CHECK_CLOSE(probability_in(1.0 / 475, 50), 1.0 - std::exp(-50.0 / 475), rel_tol(1e-14));
  CHECK_CLOSE(probability_in(1e-12, 50), 5e-11, rel_tol(1e-9));
}
