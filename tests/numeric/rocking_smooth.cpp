// Smooth block on a no-tension Winkler foundation (seed paper Eq. 1):
// continuity at theta_cr, theta_u, peak moment and capacity (rocking.md §2.7),
// energy demand/capacity (§2.8), free-oscillation period, convergence to the
// rigid block as k grows, invalid models, and the equation of motion as coded
// (angular_acceleration, sin_cos) against Eq. 1 with the library functions.
// Block of rocking.md §2.7: b = 0.2 m, h = 1.0 m, gamma = 18 kN/m^3 (W = 14.4 kN/m).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/support/error.hpp>
#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/support/units.hpp>

#include <algorithm>
#include <cmath>
#include <vector>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

// theta_u (rad): 6 decimals in the reference table.
constexpr double kThetaUTol = 1e-6;
// capacity and demand (J/m): 4 and 3 decimals in the reference tables.
constexpr double kCapacityTol = 1e-4;
constexpr double kDemandTol = 1e-3;
// D/C (dimensionless): 5 decimals in the reference table.
constexpr double kDcTol = 1e-5;
// peak moment (N m/m): 1 decimal in the reference table.
constexpr double kMomentTol = 0.05;
// free period (s): 6 significant digits in the reference (2.03772, 1.98443).
constexpr double kPeriodTol = 1e-5;
// moment continuity at theta_cr (N m/m): rounding of terms of size W b = 2880 N m/m.
constexpr double kContinuityTol = 1e-9;
// theta'' (rad/s^2): rounding of rearranged sums of terms of size W R / I0 = 7.2 rad/s^2
// and larger (observed below 1e-12; a wrong term or sign would be >= 1e-3).
constexpr double kAccelerationTol = 1e-12;
// sin and cos (relative): 2 ulp, the Taylor remainders being below 1e-20.
constexpr double kSinCosRelTol = 4.5e-16;

const RockingBody kBlock = RockingBody::rectangle(0.4, 2.0, 18.0 * units::kN);

RockingModel smooth(double k, Restitution e = Restitution::none()) {
  return RockingModel(kBlock, Foundation::winkler(k), Sidedness::two_sided, e);
}

/// Times of the theta = 0 crossings of a free run (history rows repeated at an event).
std::vector<double> crossings(const RockingResult& r) {
  std::vector<double> t;
  for (std::size_t i = 1; i < r.history.t.size(); ++i)
    if (r.history.t[i] == r.history.t[i - 1] && r.history.theta[i] == 0.0) t.push_back(r.history.t[i]);
  return t;
}

double free_period(const RockingModel& m, double theta0) {
  RockingOptions o;
  o.rel_tol = 1e-12;
  o.abs_tol = 1e-14;
  o.record_history = true;
  const RockingResult r = analyse_free(m, {theta0, 0.0}, 3.0, o);
  const auto t = crossings(r);
  REQUIRE(t.size() >= 2);
  return 2.0 * (t[1] - t[0]);
}

}  // namespace

TEST_CASE("restoring moment and its slope are continuous at theta_cr; theta_cr = W/(2 b^2 k)") {
  for (double k : {1e7, 1e8, 1e9}) {
    const RockingModel m = smooth(k);
    const double tc = m.theta_cr();
    CHECK_CLOSE(tc, kBlock.W / (2.0 * kBlock.b * kBlock.b * k), rel_tol(1e-15));
    CHECK_CLOSE(m.restoring_moment(tc, +1, false), m.restoring_moment(tc, +1, true), abs_tol(kContinuityTol));
    CHECK_CLOSE(m.restoring_moment(-tc, -1, false), m.restoring_moment(-tc, -1, true), abs_tol(kContinuityTol));
    // reaction moment (2/3) W b at theta_cr (rocking.md §1.4)
    CHECK_CLOSE(kBlock.W * kBlock.R * std::sin(kBlock.alpha - tc) - m.restoring_moment(tc),
                2.0 / 3.0 * kBlock.W * kBlock.b, rel_tol(1e-12));
    // slopes of the two branches by central differences (N m/m per rad)
    const double d = 1e-6 * tc;
    const double s_full = (m.restoring_moment(tc + d, +1, false) - m.restoring_moment(tc - d, +1, false)) / (2 * d);
    const double s_part = (m.restoring_moment(tc + d, +1, true) - m.restoring_moment(tc - d, +1, true)) / (2 * d);
    CHECK_CLOSE(s_full, s_part, rel_tol(1e-6));
    CHECK_CLOSE(m.restoring_moment(0.0), 0.0, abs_tol(kContinuityTol));  // no impact at theta = 0
  }
}

TEST_CASE("theta_u, capacity and peak moment for each k match rocking.md §2.7") {
  struct Row {
    double k, theta_u, capacity, m_max, theta_at_max;
  };
  const Row rows[] = {{1e7, 0.152456, 95.1107, 1016.1, 4.29e-2},  {1e8, 0.184481, 216.5685, 2015.4, 1.995e-2},
                      {1e9, 0.193407, 262.6615, 2478.8, 9.27e-3}, {1e10, 0.196143, 277.9753, 2693.8, 4.31e-3},
                      {1e11, 0.197000, 282.8910, 2793.6, 2.00e-3}};
  for (const Row& r : rows) {
    CAPTURE(r.k);
    const RockingModel m = smooth(r.k);
    CHECK_CLOSE(m.theta_u(), r.theta_u, abs_tol(kThetaUTol));
    CHECK(std::fabs(m.restoring_moment(m.theta_u())) < 1e-9);
    CHECK_CLOSE(m.capacity(), r.capacity, abs_tol(kCapacityTol));
    CHECK_CLOSE(m.peak_moment(), r.m_max, abs_tol(kMomentTol));
    CHECK_CLOSE(m.theta_peak(), r.theta_at_max, rel_tol(3e-3));  // 3 significant digits in the table
    // The closed-form capacity equals a numerical quadrature of M: Simpson on
    // [0, theta_cr] and, in u = sqrt(theta), on [theta_cr, theta_u] (smooth integrand).
    auto simpson = [](auto f, double lo, double hi, int n) {
      const double h = (hi - lo) / n;
      double q = f(lo) + f(hi);
      for (int i = 1; i < n; ++i) q += (i % 2 ? 4.0 : 2.0) * f(lo + i * h);
      return q * h / 3.0;
    };
    const double tc = m.theta_cr(), tu = m.theta_u();
    const double q = simpson([&](double x) { return m.restoring_moment(x); }, 0.0, tc, 200) +
                     simpson([&](double u) { return 2.0 * u * m.restoring_moment(u * u); }, std::sqrt(tc),
                             std::sqrt(tu), 2000);
    CHECK_CLOSE(m.capacity(), q, rel_tol(1e-10));
    CHECK_CLOSE(m.theta_u(-1), m.theta_u(+1), abs_tol(1e-15));  // symmetric body
  }
}

TEST_CASE("the moment-rotation curve runs from 0 to theta_u through theta_cr and the peak") {
  const RockingModel m = smooth(1e8);
  const auto c = m.moment_rotation_curve(101);
  REQUIRE(c.theta.size() == c.moment.size());
  CHECK(c.theta.front() == 0.0);
  CHECK(c.theta.back() == m.theta_u());
  CHECK(std::count(c.theta.begin(), c.theta.end(), m.theta_cr()) == 1);
  CHECK_CLOSE(*std::max_element(c.moment.begin(), c.moment.end()), m.peak_moment(), abs_tol(1e-9));
  CHECK_CLOSE(c.moment.back(), 0.0, abs_tol(1e-9));
}

TEST_CASE("energy demand and D/C for a peak rotation match rocking.md §2.8") {
  const RockingModel rigid(kBlock, Foundation::rigid(), Sidedness::two_sided, Restitution::housner());
  const double f[] = {0.25, 0.50, 0.75, 0.90}, dc[] = {0.43670, 0.74939, 0.93731, 0.98997};
  for (int i = 0; i < 4; ++i)
    CHECK_CLOSE(rigid.energy_demand(f[i] * kBlock.alpha) / rigid.capacity(), dc[i], abs_tol(kDcTol));
  const RockingModel m8 = smooth(1e8), m9 = smooth(1e9);
  CHECK_CLOSE(m8.energy_demand(0.5 * m8.theta_u()), 157.172, abs_tol(kDemandTol));
  CHECK_CLOSE(m8.energy_demand(0.5 * m8.theta_u()) / m8.capacity(), 0.72574, abs_tol(kDcTol));
  CHECK_CLOSE(m9.energy_demand(0.5 * m9.theta_u()), 195.032, abs_tol(kDemandTol));
  CHECK_CLOSE(m9.energy_demand(0.5 * m9.theta_u()) / m9.capacity(), 0.74252, abs_tol(kDcTol));
}

TEST_CASE("free oscillation period of the smooth block for k = 1e8 and 1e9 N/m^3 (theta0 = 0.5 theta_u)") {
  CHECK_CLOSE(free_period(smooth(1e8), 0.092240), 2.03772, abs_tol(kPeriodTol));
  CHECK_CLOSE(free_period(smooth(1e9), 0.096703), 1.98443, abs_tol(kPeriodTol));
  // rigid periods at the same amplitudes (rocking.md §2.7): 1.85331 s and 1.92895 s
  const RockingModel rigid(kBlock, Foundation::rigid(), Sidedness::two_sided, Restitution::given(1.0));
  CHECK_CLOSE(free_period(rigid, 0.092240), 1.85331, abs_tol(kPeriodTol));
  CHECK_CLOSE(free_period(rigid, 0.096703), 1.92895, abs_tol(kPeriodTol));
}

TEST_CASE("the smooth block converges to the rigid block as k grows") {
  const RockingModel rigid(kBlock, Foundation::rigid(), Sidedness::two_sided, Restitution::given(1.0));
  const double theta0 = 0.09;  // rad
  const double t_rigid = free_period(rigid, theta0);
  double prev_dt = 1e300, prev_du = 1e300, prev_dc = 1e300;
  for (double k : {1e8, 1e9, 1e10, 1e11, 1e12}) {
    CAPTURE(k);
    const RockingModel m = smooth(k);
    const double dt = std::fabs(free_period(m, theta0) - t_rigid);
    const double du = kBlock.alpha - m.theta_u();
    const double dc = rigid.capacity() - m.capacity();
    CHECK(dt < prev_dt);
    CHECK(du > 0.0);
    CHECK(du < prev_du);
    CHECK(dc > 0.0);
    CHECK(dc < prev_dc);
    prev_dt = dt, prev_du = du, prev_dc = dc;
  }
  CHECK(prev_dt < 2e-3);       // s, at k = 1e12 N/m^3
  CHECK(prev_du < 2e-4);                     // rad; the deficit decays like k^-1/2
  CHECK(prev_dc < 3e-3 * rigid.capacity());
}

TEST_CASE("invalid models are refused with a clear message") {
  // no restoring branch: k <= 3 W h / (2 b^3) = 2.7e6 N/m^3 for this block
  CHECK_THROWS_WITH_AS(smooth(2.69e6), doctest::Contains("too small"), InputError);
  CHECK_NOTHROW(smooth(2.8e6));
  CHECK_THROWS_WITH_AS(smooth(1e9, Restitution::given(2.0)), doctest::Contains("[-1, 1]"), InputError);
  CHECK_THROWS_WITH_AS(smooth(1e9, Restitution::given(-1.5)), doctest::Contains("[-1, 1]"), InputError);
  CHECK_THROWS_AS(RockingModel(kBlock, Foundation::rigid(), Sidedness::two_sided, Restitution::none()), InputError);
  CHECK_THROWS_AS(RockingModel(kBlock, Foundation::rigid(), Sidedness::one_sided, Restitution::housner()), InputError);
  CHECK_THROWS_AS(RockingModel(kBlock, Foundation::rigid(), Sidedness::one_sided, Restitution::given(0.5)), InputError);
  CHECK_THROWS_AS(RockingBody::rectangle(0.0, 2.0, 18e3), InputError);
  CHECK_THROWS_AS(RockingBody::rectangle(0.4, -1.0, 18e3), InputError);
}

TEST_CASE("sin_cos matches the library sin and cos to 2 ulp on each branch") {
  for (double x = -0.3; x <= 0.3; x += 1e-4) {
    double sn = 0.0, cs = 0.0;
    detail::sin_cos(x, sn, cs);
    CAPTURE(x);
    CHECK_CLOSE(sn, std::sin(x), rel_tol(kSinCosRelTol));
    CHECK_CLOSE(cs, std::cos(x), rel_tol(kSinCosRelTol));
  }
}

TEST_CASE("angular_acceleration is seed Eq. 1 with the restoring moment and library cos, rigid and smooth") {
  const double m = kBlock.W / units::g;
  for (const RockingModel& model : {smooth(1e9), RockingModel(kBlock, Foundation::rigid(), Sidedness::two_sided,
                                                              Restitution::housner())}) {
    for (int s : {+1, -1})
      for (bool partial : {false, true})
        for (double a : {1e-5, 3e-4, 0.01, 0.1, 0.2, 0.3})
          for (double ug : {0.0, 2.5, -4.0}) {
            if (partial && model.foundation().is_rigid()) continue;
            const double theta = s * a;
            // seed Eq. 1: I0 theta'' = -M(theta) + M_ext - (W/g) ug R cos(alpha s - theta)
            const double expected = (kBlock.M_ext - model.restoring_moment(theta, s, partial) -
                                     m * ug * kBlock.R * std::cos(kBlock.alpha * s - theta)) /
                                    kBlock.I0;
            CAPTURE(s);
            CAPTURE(partial);
            CAPTURE(theta);
            CAPTURE(ug);
            CHECK_CLOSE(model.angular_acceleration(theta, s, partial, ug), expected, abs_tol(kAccelerationTol));
          }
  }
}
