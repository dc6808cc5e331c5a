// The seed's Eq. 2-8 for a free-standing rectangular wall: closed forms
// against the paper's definitions evaluated numerically on a wall discretised
// into elementary weights (Eq. 4, 5), and the values of the seed's walls.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include "assess/support/error.hpp"
#include "assess/kinematic/free_wall_capacity.hpp"
#include "assess/support/units.hpp"

#include <cmath>

using assess::test::abs_tol;
using assess::test::rel_tol;
namespace units = assess::units;

namespace {

// Closed forms evaluated in double precision vs hand-derived values (-).
constexpr double kClosedFormRelTol = 1e-12;
// Midpoint-rule sums over n = 20000 layers vs the integrals of Eq. 4-5: the
// midpoint error of int z^2 dz is H^3/(12 n^2) relative 2.5e-9 (-).
constexpr double kDiscreteRelTol = 1e-8;

}  // namespace

TEST_CASE("free wall: alpha0 = b/h, e* = 3/4, a0* = alpha0 g/(e* FC), d0* = 2t/3, du* = 0.4 d0*") {
  const double b = 0.125, h = 1.5;  // the seed's first wall, half-dimensions (m)
  const assess::FreeWallCapacity c = assess::free_wall_capacity(b, h);
  CHECK_CLOSE(c.alpha0, 1.0 / 12.0, rel_tol(kClosedFormRelTol));
  CHECK_CLOSE(c.e_star, 0.75, rel_tol(kClosedFormRelTol));
  CHECK_CLOSE(c.a0_star, 9.81 / 12.0 / 0.75, rel_tol(kClosedFormRelTol));  // 1.09 m/s^2
  CHECK_CLOSE(c.d0_star, 2.0 * (2.0 * b) / 3.0, rel_tol(kClosedFormRelTol));  // 2t/3 = 0.1667 m
  CHECK_CLOSE(c.du_star, 0.4 * c.d0_star, rel_tol(kClosedFormRelTol));
  CHECK_CLOSE(c.ds_star, 0.16 * c.d0_star, rel_tol(kClosedFormRelTol));
  CHECK_CLOSE(c.as_star, 1.09 * 0.84, rel_tol(kClosedFormRelTol));
  CHECK_CLOSE(c.Ts, 2.0 * units::pi * std::sqrt(0.16 * c.d0_star / (1.09 * 0.84)), rel_tol(kClosedFormRelTol));
  // FC divides a0* only (Eq. 3).
  CHECK_CLOSE(assess::free_wall_capacity(b, h, 1.35).a0_star, c.a0_star / 1.35, rel_tol(kClosedFormRelTol));
}

TEST_CASE("free wall: e* and d* agree with Eq. 4-5 summed over elementary weights") {
  const double b = 0.25, h = 3.0, gamma = 12.06e3;  // (m, m, N/m^3)
  const int n = 20000;
  const double H = 2 * h, dz = H / n, t = 2 * b;
  // Virtual rotation 1 about the toe: delta_x(z) = z; control point at the centroid, delta_x,k = h.
  double sP = 0, sPd = 0, sPd2 = 0;
  for (int i = 0; i < n; ++i) {
    const double z = (i + 0.5) * dz, P = gamma * t * dz;
    sP += P, sPd += P * z, sPd2 += P * z * z;
  }
  const double M_star = sPd * sPd / (units::g * sPd2);  // Eq. 4
  const double d_over_dk = sPd2 / (h * sPd);           // Eq. 5
  const assess::FreeWallCapacity c = assess::free_wall_capacity(b, h);
  CHECK_CLOSE(c.e_star, units::g * M_star / sP, rel_tol(kDiscreteRelTol));
  // Eq. 2 linearised: alpha vanishes when the centroid is above the toe, d_k0 = b.
  CHECK_CLOSE(c.d0_star, d_over_dk * b, rel_tol(kDiscreteRelTol));
}

TEST_CASE("code ratios are the seed's Eq. 8") {
  const assess::FreeWallCapacity c = assess::free_wall_capacity(0.2, 3.0);
  const assess::CodeRatios r = assess::code_ratios(c, 2.0, 0.05);
  CHECK_CLOSE(r.strength, 2.0 / (2.0 * c.a0_star), rel_tol(kClosedFormRelTol));
  CHECK_CLOSE(r.displacement, 0.05 / c.du_star, rel_tol(kClosedFormRelTol));
}

TEST_CASE("free wall: invalid dimensions are refused") {
  CHECK_THROWS_AS(assess::free_wall_capacity(0.0, 1.0), assess::InputError);
  CHECK_THROWS_AS(assess::free_wall_capacity(1.0, 0.5), assess::InputError);
  CHECK_THROWS_AS(assess::free_wall_capacity(0.1, 1.0, 0.9), assess::InputError);
}
