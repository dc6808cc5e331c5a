// Fig. 2 of the seed paper (Lipo & de Felice 2017): block 2b = 0.25 m,
// 2h = 3 m, 12.06 kN/m^3. The model's moment-rotation curve, theta_u,
// capacity and free-rocking period are checked against an independent
// implementation written here from the seed's Eq. 1 (bisection, Simpson
// quadrature, and the energy integral of the period).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/support/units.hpp>

#include <cmath>
#include <functional>

using namespace assess;
using assess::test::rel_tol;

// theta_u by bisection to 1e-14 rad: agreement limited by the model's root finder.
constexpr double tol_theta_u_rel = 1e-9;
// Closed-form capacity vs composite Simpson with 20000 panels: 1e-7 relative.
constexpr double tol_capacity_rel = 1e-7;
// Periods (s): event-driven integration (rel_tol 1e-10) vs Simpson quadrature
// of the energy integral (20000 panels, exact potential): 1e-5 relative.
constexpr double tol_period_rel = 1e-5;

namespace {
constexpr double b = 0.125, h = 1.5, unit_weight = 12.06e3;  // m, m, N/m^3
const double W = unit_weight * 2 * b * 2 * h;                 // N/m
const double R = std::hypot(b, h), alpha = std::atan(b / h);
const double I0 = 4.0 / 3.0 * W / units::g * R * R;

// Seed Eq. 1, restoring moment for theta >= 0.
double moment(double th, double k) {
  const double tcr = W / (2 * b * b * k);
  if (th <= tcr) return W * R * std::sin(alpha - th) - W * b + 2.0 / 3.0 * k * b * b * b * th;
  return W * R * std::sin(alpha - th) - W / 3.0 * std::sqrt(2 * W / (k * th));
}

double bisect(const std::function<double(double)>& f, double lo, double hi) {
  for (int i = 0; i < 200 && hi - lo > 1e-15; ++i) {
    const double mid = 0.5 * (lo + hi);
    (f(lo) > 0) == (f(mid) > 0) ? lo = mid : hi = mid;
  }
  return 0.5 * (lo + hi);
}

double simpson(const std::function<double(double)>& f, double a, double c, int n) {
  const double dx = (c - a) / n;
  double s = f(a) + f(c);
  for (int i = 1; i < n; ++i) s += f(a + i * dx) * (i % 2 ? 4 : 2);
  return s * dx / 3;
}

// V(theta) = int_0^theta M, integrated by hand from seed Eq. 1.
double potential(double th, double k) {
  const double tcr = W / (2 * b * b * k);
  auto full = [&](double x) {
    return W * R * (std::cos(alpha - x) - std::cos(alpha)) - W * b * x + k * b * b * b * x * x / 3.0;
  };
  if (th <= tcr) return full(th);
  return full(tcr) + W * R * (std::cos(alpha - th) - std::cos(alpha - tcr)) -
         2.0 / 3.0 * W * std::sqrt(2 * W / k) * (std::sqrt(th) - std::sqrt(tcr));
}

// Free two-sided period from theta0: T = 4 int_0^theta0 dtheta / omega(theta),
// omega^2 = 2 (V(theta0) - V(theta)) / I0. With theta = theta0 sin(phi) the
// integrand is regular.
double period_quadrature(double k, double theta0) {
  auto V = [&](double th) { return potential(th, k); };
  const double V0 = V(theta0);
  auto integrand = [&](double phi) {
    const double th = theta0 * std::sin(phi);
    const double dV = V0 - V(th);
    return theta0 * std::cos(phi) / std::sqrt(2.0 * dV / I0);
  };
  // The integrand tends to sqrt(theta0 I0 / M(theta0)) at phi = pi/2, where
  // V0 - V cancels: integrate to just short of it and add the tail with the limit.
  const double phi_max = 0.5 * units::pi * (1 - 1e-4);
  const double tail = std::sqrt(theta0 * I0 / moment(theta0, k)) * (0.5 * units::pi - phi_max);
  return 4.0 * (simpson(integrand, 0.0, phi_max, 20000) + tail);
}

double period_model(const RockingModel& m, double theta0) {
  RockingOptions o;
  o.record_history = true;
  o.rel_tol = 1e-10;
  o.abs_tol = 1e-13;
  const RockingResult r = analyse_free(m, {theta0, 0.0}, 30.0, o);
  for (std::size_t i = 1; i < r.history.t.size(); ++i)
    if (r.history.theta[i] <= 0.0) {  // first crossing of theta = 0, interpolated
      const double t0 = r.history.t[i - 1], t1 = r.history.t[i], y0 = r.history.theta[i - 1], y1 = r.history.theta[i];
      return 4.0 * (t0 + (t1 - t0) * y0 / (y0 - y1));
    }
  return NAN;
}
}  // namespace

TEST_CASE("seed Fig. 2a: theta_cr, theta_u, moment and capacity for several k") {
  const RockingBody body = RockingBody::rectangle(2 * b, 2 * h, unit_weight);
  for (double k : {5e7, 1e8, 1e9, 1e10}) {
    CAPTURE(k);
    const RockingModel m(body, Foundation::winkler(k), Sidedness::two_sided, Restitution::none());
    CHECK_CLOSE(m.theta_cr(), W / (2 * b * b * k), rel_tol(1e-14));
    const double tu = bisect([&](double th) { return moment(th, k); }, 1e-6, alpha);
    CHECK_CLOSE(m.theta_u(+1), tu, rel_tol(tol_theta_u_rel));
    for (double f : {0.1, 0.5, 0.9}) CHECK_CLOSE(m.restoring_moment(f * tu), moment(f * tu, k), rel_tol(1e-12));
    const double tcr = W / (2 * b * b * k);
    const double C = simpson([&](double x) { return moment(x, k); }, 0.0, tcr, 20000) +
                     simpson([&](double x) { return moment(x, k); }, tcr, tu, 20000);
    CHECK_CLOSE(m.capacity(), C, rel_tol(tol_capacity_rel));
  }
  // k -> infinity: the capacity tends to Housner's W R (1 - cos alpha), the
  // gap shrinking like k^(-1/2) (rocking.md §2.7): 100 x k, gap / 10.
  const double C_rigid = W * R * (1 - std::cos(alpha));
  auto gap = [&](double k) {
    return C_rigid - RockingModel(body, Foundation::winkler(k), Sidedness::two_sided, Restitution::none()).capacity();
  };
  CHECK(gap(1e10) > 0.0);
  CHECK(gap(1e12) > 0.0);
  CHECK_CLOSE(gap(1e10) / gap(1e12), 10.0, rel_tol(0.1));
}

TEST_CASE("seed Fig. 2b: free-rocking period against amplitude") {
  const RockingBody body = RockingBody::rectangle(2 * b, 2 * h, unit_weight);
  for (double k : {1e8, 1e9}) {
    CAPTURE(k);
    const RockingModel m(body, Foundation::winkler(k), Sidedness::two_sided, Restitution::none());
    // Below theta_cr the oscillation is linear: T = 2 pi / omega0.
    const double omega0 = std::sqrt((2.0 / 3.0 * k * b * b * b - W * h) / I0);
    CHECK_CLOSE(period_model(m, 0.5 * m.theta_cr()), 2 * units::pi / omega0, rel_tol(tol_period_rel));
    for (double f : {0.3, 0.6, 0.9}) {
      CAPTURE(f);
      const double th0 = f * m.theta_u(+1);
      CHECK_CLOSE(period_model(m, th0), period_quadrature(k, th0), rel_tol(tol_period_rel));
    }
  }
}
