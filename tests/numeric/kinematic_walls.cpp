// alpha0 of catalogue mechanisms against hand virtual-work formulas:
// a wall with a floor load at the top and with a tie, vertical flexure with a
// given hinge height and the searched minimum, a gable and a composite wedge.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>
#include <assess/support/units.hpp>

#include <cmath>

using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {
// Hand formulas vs the chain: SVD and sums round-off only (the issue asks 1e-9).
constexpr double tol_alpha = 1e-9;  // (-)
// The searched vertical-flexure hinge: golden section stops at 1e-6 * height.
constexpr double tol_hinge = 1e-5;  // m
// Gable of n slices vs the continuous triangle: slice centroids at mid-slice
// raise the centroid by O(1/n^2): 24 slices give 8.7e-4 relative in alpha0.
constexpr double tol_gable = 1e-3;  // relative

constexpr double kN = assess::units::kN;
constexpr double gam = 18.0 * kN;  // N/m^3
}  // namespace

TEST_CASE("wall with a floor load at the top: alpha0 by hand") {
  // Wall t x h, hinge at the outer edge; floor weight N at distance d from the
  // inner face. Moments about the hinge, rotation theta = 1:
  // alpha0 (W h/2 + N h) = W t/2 + N (t - d).
  const double t = 0.45, h = 5.0, L = 4.0, N = 30.0 * kN, d = 0.15;
  assess::SimpleOverturningParams p;
  assess::Storey s;
  s.height = h;
  s.thickness = t;
  s.floor_weight = N;
  s.floor_distance_from_inner_face = d;
  p.storeys = {s};
  p.unit_weight = gam;
  p.length = L;
  p.hinge_level = 0;
  const auto set = assess::simple_overturning(p);
  REQUIRE(set.candidates.size() == 1);
  const double W = gam * t * h * L;
  const double expected = (W * t / 2 + N * (t - d)) / (W * h / 2 + N * h);
  CHECK_CLOSE(assess::activation_multiplier(set.candidates[0].chain), expected, abs_tol(tol_alpha));

  SUBCASE("and a tie T at the top: + T h in the resisting work") {
    const double T = 20.0 * kN;
    p.storeys[0].tie = T;
    const auto set_t = assess::simple_overturning(p);
    const double expected_t = (W * t / 2 + N * (t - d) + T * h) / (W * h / 2 + N * h);
    CHECK_CLOSE(assess::activation_multiplier(set_t.candidates[0].chain), expected_t, abs_tol(tol_alpha));
  }
  SUBCASE("and an outward roof thrust H at the top: - H h") {
    const double H = 5.0 * kN;
    p.storeys[0].thrust = H;
    const auto set_h = assess::simple_overturning(p);
    const double expected_h = (W * t / 2 + N * (t - d) - H * h) / (W * h / 2 + N * h);
    CHECK_CLOSE(assess::activation_multiplier(set_h.candidates[0].chain), expected_h, abs_tol(tol_alpha));
  }
}

TEST_CASE("two-storey façade: each hinge level is a candidate, alpha0 by hand") {
  // Storey 0: t0 = 0.6, h0 = 4; storey 1: t1 = 0.45, h1 = 3.5 (outer faces
  // aligned). Floors N1 at the top of storey 0, N2 at the top (roof).
  const double t0 = 0.6, h0 = 4.0, t1 = 0.45, h1 = 3.5, L = 1.0;
  const double N1 = 25.0 * kN, d1 = 0.2, N2 = 15.0 * kN, d2 = 0.15;
  assess::SimpleOverturningParams p;
  assess::Storey s0, s1;
  s0.height = h0; s0.thickness = t0; s0.floor_weight = N1; s0.floor_distance_from_inner_face = d1;
  s1.height = h1; s1.thickness = t1; s1.floor_weight = N2; s1.floor_distance_from_inner_face = d2;
  p.storeys = {s0, s1};
  p.unit_weight = gam;
  p.length = L;
  const auto set = assess::simple_overturning(p);
  REQUIRE(set.searched);
  REQUIRE(set.candidates.size() == 2);
  const double W0 = gam * t0 * h0 * L, W1 = gam * t1 * h1 * L;
  // Hinge at ground.
  const double a_ground = (W0 * t0 / 2 + W1 * t1 / 2 + N1 * (t0 - d1) + N2 * (t1 - d2)) /
                          (W0 * h0 / 2 + W1 * (h0 + h1 / 2) + N1 * h0 + N2 * (h0 + h1));
  // Hinge at level 1.
  const double a_upper = (W1 * t1 / 2 + N2 * (t1 - d2)) / (W1 * h1 / 2 + N2 * h1);
  CHECK_CLOSE(assess::activation_multiplier(set.candidates[0].chain), a_ground, abs_tol(tol_alpha));
  CHECK_CLOSE(assess::activation_multiplier(set.candidates[1].chain), a_upper, abs_tol(tol_alpha));
  CHECK_CLOSE(set.candidates[1].Z, h0, abs_tol(1e-12));
  CHECK(assess::governing_candidate(set) == (a_ground < a_upper ? 0u : 1u));
}

namespace {
// Vertical flexure, hand virtual work with theta1 = 1 of the lower block
// (hinges: outer base edge, inner edge at h1, outer top edge sliding):
//   lower centroid: dx = h1/2, dz = t/2; upper centroid: dx = h1/2,
//   dz = t + h1 t / (2 h2); top load at distance e from the inner face:
//   dz = t + h1 e / h2.   alpha0 = sum W dz / sum W dx.
double flexure_alpha0(double t, double H, double h1, double w, double N, double e) {
  const double h2 = H - h1, W1 = w * h1, W2 = w * h2;
  return (W1 * t / 2 + W2 * (t + h1 * t / (2 * h2)) + N * (t + h1 * e / h2)) / ((W1 + W2) * h1 / 2);
}
}  // namespace

TEST_CASE("vertical flexure: alpha0 by hand for a given hinge height, and the searched minimum") {
  const double t = 0.4, H = 4.0, L = 1.0, N = 60.0 * kN, e = 0.2;
  assess::VerticalFlexureParams p;
  p.height = H;
  p.thickness = t;
  p.unit_weight = gam;
  p.length = L;
  p.base_z = 3.0;
  p.top_load = N;
  p.top_load_distance_from_inner_face = e;
  const double w = gam * t * L;  // weight per metre of height
  for (double h1 : {1.0, 2.0, 2.7}) {
    p.hinge_height = h1;
    const auto set = assess::vertical_flexure(p);
    CHECK_CLOSE(assess::activation_multiplier(set.candidates[0].chain), flexure_alpha0(t, H, h1, w, N, e),
                abs_tol(tol_alpha));
    CHECK_CLOSE(set.candidates[0].Z, 3.0 + H / 2, abs_tol(1e-12));
  }
  p.hinge_height.reset();
  const auto set = assess::vertical_flexure(p);
  REQUIRE(set.searched);
  const auto& best = set.candidates[assess::governing_candidate(set)];
  // Minimum of the hand formula by a fine scan plus golden refinement.
  double lo = 0.01, hi = H - 0.01;
  for (int i = 0; i < 200; ++i) {
    const double a = lo + (hi - lo) * 0.382, b = lo + (hi - lo) * 0.618;
    (flexure_alpha0(t, H, a, w, N, e) < flexure_alpha0(t, H, b, w, N, e) ? hi : lo) = (flexure_alpha0(t, H, a, w, N, e) < flexure_alpha0(t, H, b, w, N, e) ? b : a);
  }
  const double h_min = 0.5 * (lo + hi);
  CHECK_CLOSE(best.parameter, h_min, abs_tol(tol_hinge));
  CHECK_CLOSE(assess::activation_multiplier(best.chain), flexure_alpha0(t, H, h_min, w, N, e), abs_tol(tol_alpha));
}

TEST_CASE("gable: alpha0 of the slices by hand, close to 3t / (2 h) of the continuous triangle") {
  assess::GableParams p;
  p.width = 8.0;
  p.height = 3.0;
  p.thickness = 0.4;
  p.unit_weight = gam;
  p.base_z = 7.0;
  const auto set = assess::gable_overturning(p);
  // Slice i: weight ~ 1 - (i + 1/2)/n at height (i + 1/2) h/n; alpha0 = (t/2) / z_bar.
  double sw = 0.0, swz = 0.0;
  for (int i = 0; i < p.slices; ++i) {
    const double w = 1.0 - (i + 0.5) / p.slices;
    sw += w;
    swz += w * (i + 0.5) * p.height / p.slices;
  }
  const double a0 = assess::activation_multiplier(set.candidates[0].chain);
  CHECK_CLOSE(a0, 0.5 * p.thickness / (swz / sw), abs_tol(tol_alpha));
  CHECK_CLOSE(a0, 3 * p.thickness / (2 * p.height), rel_tol(tol_gable));
  CHECK(set.candidates[0].Z == 7.0);
}

TEST_CASE("composite overturning: the wedge's moments add to the façade's, alpha0 by hand") {
  // Façade t x h x L; triangular wedge of two side walls (thickness ts) with
  // vertices (-t, 0), (-t, h), (-t - h tan b, h): area h^2 tan b / 2, centroid
  // x = -t - h tan b / 3 (distance from the hinge t + h tan b / 3), z = 2h/3.
  const double t = 0.5, h = 6.0, L = 5.0, ts = 0.4, beta = 30.0;
  assess::CompositeOverturningParams p;
  p.height = h;
  p.thickness = t;
  p.length = L;
  p.unit_weight = gam;
  p.side_thickness = ts;
  p.side_walls = 2;
  p.side_length = 10.0;
  p.beta_deg = beta;
  const auto set = assess::composite_overturning(p);
  const double tb = std::tan(beta * assess::units::deg);
  const double Wf = gam * t * h * L, Ww = gam * 0.5 * h * h * tb * 2 * ts;
  const double expected = (Wf * t / 2 + Ww * (t + h * tb / 3)) / (Wf * h / 2 + Ww * 2 * h / 3);
  CHECK_CLOSE(assess::activation_multiplier(set.candidates[0].chain), expected, abs_tol(tol_alpha));
}

TEST_CASE("corner overturning: alpha0 and e* of the 3-D wedge by hand, about the axis normal to the bisector") {
  // Symmetric corner, walls of thickness t, wedge height h, cracks at beta from
  // the vertical starting at the other wall's inner face. Rotation theta = 1
  // about the horizontal axis through the outer corner edge, normal to the
  // bisector; a plan point at depths (u, v) from the outer faces has lever arm
  // (u + v)/sqrt(2) about that axis (3-D moments, not the planar chain):
  //   pillar (t x t x h): W_p = g t^2 h,        arm (t/2 + t/2)/sqrt2 = t/sqrt2, height h/2;
  //   two arms (triangles of legs h, h tan b):  W_a = g t h^2 tan b,
  //            arm (t + h tan b / 3 + t/2)/sqrt2, height 2h/3;
  //   top weight N on the pillar's centre: arm t/sqrt2, height h;
  //   thrust H along the bisector and two ties T along the walls (resultant
  //   sqrt2 T along the bisector, inward) at height h.
  // alpha0 = (sum W arm - H h + sqrt2 T h) / (sum W height)   [C8.7.1.1]
  const double t = 0.5, h = 7.0, beta = 35.0, N = 20.0 * kN, H = 4.0 * kN, T = 6.0 * kN;
  const double r = 1.0 / std::sqrt(2.0), tb = std::tan(beta * assess::units::deg);
  const double Wp = gam * t * t * h, Wa = gam * t * h * h * tb;
  assess::CornerOverturningParams p;
  p.height = h;
  p.thickness = t;
  p.unit_weight = gam;
  p.wall_length = 20.0;  // longer than h tan(beta): triangular arms
  p.base_z = 2.0;
  p.beta_deg = beta;
  p.axis_deg = 45.0;  // the axis normal to the bisector (issue 33: scanned by default)
  {
    const auto set = assess::corner_overturning(p);
    REQUIRE(set.candidates.size() == 1);
    const double expected = (Wp * t * r + Wa * (1.5 * t + h * tb / 3) * r) / (Wp * h / 2 + Wa * 2 * h / 3);
    CHECK_CLOSE(assess::activation_multiplier(set.candidates[0].chain), expected, abs_tol(tol_alpha));
    CHECK(set.candidates[0].Z == 2.0);
    // e* = (sum W dx)^2 / (sum W  sum W dx^2) [C8.7.1.5], dx = height above the
    // axis: integral of z^2 dW = g t^2 h^3/3 (pillar) + g t tan b h^4/2 (arms).
    const double sWdx = Wp * h / 2 + Wa * 2 * h / 3;
    const double sWdx2 = gam * t * t * h * h * h / 3 + gam * t * tb * h * h * h * h / 2;
    const auto res = assess::analyse_kinematic(set.candidates[0].chain);
    CHECK_CLOSE(res.sum_W, Wp + Wa, rel_tol(tol_alpha));
    CHECK_CLOSE(res.e_star, sWdx * sWdx / ((Wp + Wa) * sWdx2), abs_tol(tol_alpha));
  }
  SUBCASE("with a top weight, a hip-rafter thrust and two corner ties") {
    p.top_weight = N;
    p.thrust = H;
    p.tie = T;
    const auto set = assess::corner_overturning(p);
    const double expected = (Wp * t * r + Wa * (1.5 * t + h * tb / 3) * r + N * t * r - H * h + std::sqrt(2.0) * T * h) /
                            (Wp * h / 2 + Wa * 2 * h / 3 + N * h);
    CHECK_CLOSE(assess::activation_multiplier(set.candidates[0].chain), expected, abs_tol(tol_alpha));
  }
  SUBCASE("walls shorter than h tan(beta): trapezoidal arms") {
    // Arm of reach L < h tan b: triangle of legs L/tan b, L (apex at the
    // bottom) plus the rectangle L x (h - L/tan b) above it.
    const double L = 2.0, zc = L / tb;
    p.wall_length = L;
    const auto set = assess::corner_overturning(p);
    const double Wtri = gam * t * zc * L, Wrect = gam * 2 * t * L * (h - zc);
    const double resisting = Wp * t * r + Wtri * (1.5 * t + L / 3) * r + Wrect * (1.5 * t + L / 2) * r;
    const double overturning = Wp * h / 2 + Wtri * 2 * zc / 3 + Wrect * (zc + h) / 2;
    CHECK_CLOSE(assess::activation_multiplier(set.candidates[0].chain), resisting / overturning, abs_tol(tol_alpha));
  }
}
