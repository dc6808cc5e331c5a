// Closed forms of a free-standing wall (rigid block overturning about its
// outer base edge): alpha0 = s/h, e* = 0.75, d0* = 2s/3 (centroid control
// point), the exact finite-displacement alpha(theta), and the regression
// numbers of the 0.5 m x 6 m wall (docs/theory/kinematic.md, worked example).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/kinematic/chain.hpp>
#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/support/units.hpp>

#include <cmath>

using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

// alpha0, e*, d0* from closed forms: round-off of the SVD and the sums only.
constexpr double tol_alpha = 1e-12;      // (-)
constexpr double tol_ratio = 1e-12;      // e*, relative
constexpr double tol_disp = 1e-10;       // m: Brent refinement of d_k0 to 1e-13 * size
// ntc.md §6b prints 5 decimals: half a unit of the last digit (plus round-off),
// in the unit of each quantity (t, m, m/s^2, s).
constexpr double tol_printed = 5.0e-6 + 1e-12;
// Exact alpha(theta) vs the chain: Newton converges to 1e-13 m.
constexpr double tol_alpha_curve = 1e-10;  // (-)

constexpr double s = 0.5, h = 6.0, gamma_kN = 18.0;

assess::Chain wall(double s_, double h_) {
  assess::Block b;
  b.name = "wall";
  b.polygon = {{0.0, 0.0}, {s_, 0.0}, {s_, h_}, {0.0, h_}};
  b.unit_weight = gamma_kN * assess::units::kN;
  b.length = 1.0;
  assess::Constraint hinge;
  hinge.type = assess::ConstraintType::GroundHinge;
  hinge.name = "base edge";
  hinge.block = 0;
  hinge.point = {s_, 0.0};
  return assess::Chain({b}, {hinge}, {});
}

}  // namespace

TEST_CASE("single block: alpha0 = s/h, e* = 0.75, d0* = 2s/3 and dk0 = s/2 at the centroid") {
  const auto chain = wall(s, h);
  assess::KinematicOptions opt;
  opt.FC = 1.35;
  const auto r = assess::analyse_kinematic(chain, opt);
  REQUIRE(r.curve_complete());
  CHECK_CLOSE(r.alpha0, s / h, abs_tol(tol_alpha));
  CHECK_CLOSE(r.e_star, 0.75, rel_tol(tol_ratio));
  CHECK_CLOSE(r.control_point.x(), s / 2, abs_tol(tol_disp));
  CHECK_CLOSE(r.control_point.y(), h / 2, abs_tol(tol_disp));
  CHECK_CLOSE(r.dk0, s / 2, abs_tol(tol_disp));
  CHECK_CLOSE(r.d0_star, 2 * s / 3, abs_tol(tol_disp));
  // W = 54 kN/m, M* = 0.75 W / g.
  CHECK_CLOSE(r.sum_W, s * h * gamma_kN * 1000.0, rel_tol(tol_ratio));
  CHECK_CLOSE(r.M_star / 1000.0, 4.12844, abs_tol(tol_printed));
  CHECK_CLOSE(r.a0_star, 0.80741, abs_tol(tol_printed));
}

TEST_CASE("single block: the linearised curve reproduces the 0.5 m x 6 m wall numbers") {
  const auto chain = wall(s, h);
  assess::KinematicOptions opt;
  opt.FC = 1.35;
  opt.curve_model = assess::CurveModel::Linearised;
  const auto r = assess::analyse_kinematic(chain, opt);
  REQUIRE(r.curve_complete());
  CHECK_CLOSE(r.d0_star, 0.33333, abs_tol(tol_printed));
  CHECK_CLOSE(r.du_star, 0.13333, abs_tol(tol_printed));
  CHECK_CLOSE(r.ds_star, 0.05333, abs_tol(tol_printed));
  CHECK_CLOSE(r.as_star, 0.67822, abs_tol(tol_printed));
  CHECK_CLOSE(r.Ts, 1.76195, abs_tol(tol_printed));
  CHECK_CLOSE(r.d_SLV, 0.13333, abs_tol(tol_printed));
  CHECK_CLOSE(r.a_SLV, 0.48444, abs_tol(tol_printed));
  CHECK_CLOSE(r.T_SLV, 2.76890, abs_tol(tol_printed));
  CHECK_CLOSE(r.d_SLC, 0.20000, abs_tol(tol_printed));
  CHECK_CLOSE(r.a_SLC, 0.32296, abs_tol(tol_printed));
  CHECK_CLOSE(r.T_SLC, 3.85668, abs_tol(tol_printed));
}

TEST_CASE("single block: finite-displacement alpha(theta) is the exact rigid-body expression") {
  // Rotation theta about the outer edge: the centroid, at (-s/2, h/2) from the
  // hinge, moves by d_k = s/2 (1 - cos t) + h/2 sin t and
  // alpha = (s cos t - h sin t) / (h cos t + s sin t).
  const auto chain = wall(s, h);
  assess::KinematicOptions opt;
  opt.curve_points = 21;
  const auto r = assess::analyse_kinematic(chain, opt);
  REQUIRE(r.curve_complete());
  for (const auto& p : r.curve) {
    // Invert d_k(theta) by bisection (monotone on [0, atan(s/h)]).
    double lo = 0.0, hi = std::atan(s / h) * 1.5;
    for (int i = 0; i < 200; ++i) {
      const double t = 0.5 * (lo + hi);
      ((s / 2) * (1 - std::cos(t)) + (h / 2) * std::sin(t) < p.dk ? lo : hi) = t;
    }
    const double t = 0.5 * (lo + hi);
    const double exact = (s * std::cos(t) - h * std::sin(t)) / (h * std::cos(t) + s * std::sin(t));
    CHECK_CLOSE(p.alpha, exact, abs_tol(tol_alpha_curve));
  }
}
