// The rocking body built from a one-block kinematic chain (façade
// assessment): a bare rectangle must equal RockingBody::rectangle; carried
// weights and forces enter W, the centroid, I0 and M_ext as derived by hand.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/kinematic/chain.hpp>
#include <assess/support/error.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>
#include <assess/dynamics/rocking_from_chain.hpp>
#include <assess/support/units.hpp>

#include <cmath>

using namespace assess;
using assess::test::rel_tol;
using assess::test::abs_tol;

// Closed forms of a rectangle: round-off only.
constexpr double tol_body_rel = 1e-12;
// Displacements of material points (m): round-off only.
constexpr double tol_disp_m = 1e-12;

namespace {
// Wall of thickness s (x from -s to 0, outer face at x = 0), height h, unit
// weight gamma (N/m^3), length L (m), rocking about the outer toe (0, 0).
Block wall(double s, double h, double gamma, double L) {
  return Block{"wall", {{-s, 0.0}, {0.0, 0.0}, {0.0, h}, {-s, h}}, gamma, L};
}
Constraint toe() {
  Constraint c;
  c.type = ConstraintType::GroundHinge;
  c.name = "toe";
  c.block = 0;
  c.point = {0.0, 0.0};
  return c;
}
}  // namespace

TEST_CASE("a bare rectangular wall gives Housner's rectangle per unit depth") {
  const double s = 0.65, h = 14.57, gamma = 18e3, L = 3.0;
  const Chain chain({wall(s, h, gamma, L)}, {toe()}, {});
  const ChainRockingBody cb = rocking_body_from_chain(chain);
  const RockingBody ref = RockingBody::rectangle(s, h, gamma);
  CHECK_CLOSE(cb.body.W, ref.W, rel_tol(tol_body_rel));
  CHECK_CLOSE(cb.body.R, ref.R, rel_tol(tol_body_rel));
  CHECK_CLOSE(cb.body.alpha, ref.alpha, rel_tol(tol_body_rel));
  CHECK_CLOSE(cb.body.I0, ref.I0, rel_tol(tol_body_rel));
  CHECK_CLOSE(cb.body.b, s / 2, rel_tol(tol_body_rel));
  CHECK(cb.body.M_ext == 0.0);
  CHECK_CLOSE(cb.total_weight, gamma * s * h * L, rel_tol(tol_body_rel));
  // Centroid (-s/2, h/2): rotated by alpha it sits above the toe, x displacement s/2.
  CHECK_CLOSE(cb.horizontal_displacement({-s / 2, h / 2}, ref.alpha), s / 2, abs_tol(tol_disp_m));
  CHECK_CLOSE(cb.horizontal_displacement({0.0, h}, 0.01), h * std::sin(0.01), abs_tol(tol_disp_m));
}

TEST_CASE("a carried weight and a thrust enter W, the centroid, I0 and M_ext") {
  const double s = 0.5, h = 6.0, gamma = 18e3, L = 2.0;
  const double Q = 20e3;      // N, floor load on the top, 0.1 m from the inner face
  const double xq = -s + 0.1, zq = h;
  const double T = 5e3;       // N, outward thrust at the top
  Load floor;
  floor.type = LoadType::Weight;
  floor.name = "floor";
  floor.block = 0;
  floor.point = {xq, zq};
  floor.weight = Q;
  Load thrust;
  thrust.type = LoadType::Force;
  thrust.name = "thrust";
  thrust.block = 0;
  thrust.point = {0.0, h};
  thrust.force = {T, 0.0};
  const Chain chain({wall(s, h, gamma, L)}, {toe()}, {floor, thrust});
  const ChainRockingBody cb = rocking_body_from_chain(chain);
  const double P = gamma * s * h * L, g = units::g;
  const double W = P + Q;
  const double xG = (P * s / 2 + Q * (-xq)) / W, zG = (P * h / 2 + Q * zq) / W;  // from the toe, x inward
  const double I0 = P / g * (s * s + h * h) / 3.0 + Q / g * (xq * xq + zq * zq);
  CHECK_CLOSE(cb.body.W, W / L, rel_tol(tol_body_rel));
  CHECK_CLOSE(cb.body.R, std::hypot(xG, zG), rel_tol(tol_body_rel));
  CHECK_CLOSE(cb.body.alpha, std::atan2(xG, zG), rel_tol(tol_body_rel));
  CHECK_CLOSE(cb.body.I0, I0 / L, rel_tol(tol_body_rel));
  CHECK_CLOSE(cb.body.M_ext, T * h / L, rel_tol(tol_body_rel));  // outward moment about the toe
}

TEST_CASE("multi-block chains and friction are refused with a clear message") {
  const double s = 0.5, h = 3.0;
  Block lower = wall(s, h, 18e3, 1.0), upper{"upper", {{-s, h}, {0.0, h}, {0.0, 2 * h}, {-s, 2 * h}}, 18e3, 1.0};
  Constraint hinge;
  hinge.type = ConstraintType::Hinge;
  hinge.name = "mid";
  hinge.block = 0;
  hinge.other = 1;
  hinge.point = {-s, h};
  Constraint slider;
  slider.type = ConstraintType::Slider;
  slider.name = "top";
  slider.block = 1;
  slider.point = {-s, 2 * h};
  slider.direction = {0.0, 1.0};
  const Chain two({lower, upper}, {toe(), hinge, slider}, {});
  CHECK_THROWS_WITH_AS(rocking_body_from_chain(two), doctest::Contains("multi-block"), InputError);
}

TEST_CASE("a gable of welded slices rocks as one body: W and centroid of the triangle") {
  // Triangle of base B, height H, thickness t: W = gamma t B H / 2 over the
  // whole gable, centroid H/3 above the base. The catalogue slices the gable
  // into 24 prisms (docs/catalogue.md), which moves the centroid by ~0.1 %.
  constexpr double tol_slicing_rel = 5e-3;
  GableParams p;
  p.width = 8.0;
  p.height = 3.0;
  p.thickness = 0.4;
  p.unit_weight = 18e3;
  p.base_z = 7.0;
  const MechanismSet set = gable_overturning(p);
  REQUIRE(set.candidates.size() == 1);
  const ChainRockingBody cb = rocking_body_from_chain(set.candidates[0].chain);
  CHECK_CLOSE(cb.total_weight, p.unit_weight * p.thickness * p.width * p.height / 2, rel_tol(tol_slicing_rel));
  CHECK_CLOSE(cb.centroid.y() - cb.hinge.y(), p.height / 3, rel_tol(tol_slicing_rel));
  CHECK_CLOSE(cb.body.b, p.thickness / 2, rel_tol(1e-12));
}
