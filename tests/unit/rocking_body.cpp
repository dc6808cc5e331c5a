// RockingBody factories and the external moment M_ext: the general factory
// reproduces the rectangle; a constant outward moment shifts theta_u, the
// capacity and the uplift threshold as the closed forms say.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/support/error.hpp>
#include <assess/dynamics/rocking_model.hpp>
#include <assess/support/units.hpp>

#include <cmath>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {
// Geometry and closed forms evaluated in double precision (dimensionless).
constexpr double kRel = 1e-13;
// Rotations from the bracketing root finder (rad).
constexpr double kThetaTol = 1e-14;
}  // namespace

TEST_CASE("from_centroid with the centroid of a rectangle reproduces rectangle()") {
  const RockingBody r = RockingBody::rectangle(0.4, 2.0, 18e3);
  const RockingBody g = RockingBody::from_centroid(r.W, 0.2, 1.0, r.I0, 0.2);
  CHECK_CLOSE(g.R, r.R, rel_tol(kRel));
  CHECK_CLOSE(g.alpha, r.alpha, rel_tol(kRel));
  CHECK_CLOSE(g.x_G(), 0.2, rel_tol(kRel));
  CHECK_CLOSE(g.z_G(), 1.0, rel_tol(kRel));
  CHECK_CLOSE(r.W, 18e3 * 0.4 * 2.0, rel_tol(kRel));
  CHECK_CLOSE(r.I0, 4.0 / 3.0 * r.W / units::g * (0.04 + 1.0), rel_tol(kRel));
  CHECK_THROWS_WITH_AS(RockingBody::from_centroid(r.W, 0.2, 1.0, 0.5 * r.I0, 0.2), doctest::Contains("I0"),
                       InputError);
  CHECK_THROWS_WITH_AS(RockingBody::from_centroid(-1.0, 0.2, 1.0, r.I0, 0.2), doctest::Contains("weight W"),
                       InputError);
}

TEST_CASE("a constant outward moment shifts theta_u, capacity and uplift (rigid block)") {
  const RockingBody r = RockingBody::rectangle(0.4, 2.0, 18e3);
  const double M = 0.3 * r.W * r.b;  // N m/m, below the restoring moment W b
  const RockingBody g = RockingBody::from_centroid(r.W, r.b, r.z_G(), r.I0, r.b, M);
  const RockingModel m(g, Foundation::rigid(), Sidedness::two_sided, Restitution::housner());
  const double shift = std::asin(M / (r.W * r.R));
  CHECK_CLOSE(m.theta_u(+1), r.alpha - shift, abs_tol(kThetaTol));
  CHECK_CLOSE(m.theta_u(-1), r.alpha + shift, abs_tol(kThetaTol));
  const double a = m.theta_u(+1);
  CHECK_CLOSE(m.capacity(), r.W * r.R * (std::cos(r.alpha - a) - std::cos(r.alpha)) - M * a, rel_tol(kRel));
  // outward lift-off when -ug m R cos(alpha) + M > W R sin(alpha), i.e. -ug > g (W b - M)/(W z_G)
  const double ug_lift = units::g * (r.W * r.b - M) / (r.W * r.z_G());
  CHECK_FALSE(m.lifts(+1, -ug_lift * (1.0 - 1e-9)));
  CHECK(m.lifts(+1, -ug_lift * (1.0 + 1e-9)));
  // a moment at or above W b: the body cannot stand
  const RockingBody h = RockingBody::from_centroid(r.W, r.b, r.z_G(), r.I0, r.b, 1.01 * r.W * r.b);
  CHECK_THROWS_WITH_AS(RockingModel(h, Foundation::rigid(), Sidedness::one_sided, Restitution::given(-0.5)),
                       doctest::Contains("cannot stand"), InputError);
}

TEST_CASE("an off-centre centroid is refused for two-sided rocking, accepted one-sided") {
  const RockingBody r = RockingBody::rectangle(0.4, 2.0, 18e3);
  const RockingBody g = RockingBody::from_centroid(r.W, 0.15, 1.0, r.I0, 0.2);
  CHECK_THROWS_WITH_AS(RockingModel(g, Foundation::rigid(), Sidedness::two_sided, Restitution::given(0.9)),
                       doctest::Contains("centreline"), InputError);
  const RockingModel m(g, Foundation::rigid(), Sidedness::one_sided, Restitution::one_sided_theory());
  CHECK_CLOSE(m.theta_u(), std::atan2(0.15, 1.0), abs_tol(kThetaTol));
  CHECK_CLOSE(m.restitution(), 1.0 - 2.0 * g.mass() * 1.0 / g.I0, rel_tol(kRel));
}
