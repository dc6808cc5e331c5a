// Issue 38: the mechanisms' numbers as an independent derivation gives them.
//  1. Every load the case gives moves with the block it rests on, in the
//     horizontal forces as in the vertical ones, unless the case holds it
//     (Circ. 2019 [C8.7.1.1]: the carried weights Q push with the blocks):
//     one case per mechanism type against closed forms written here.
//  2. The corner: alpha0(psi) = alpha0(90) sin psi + alpha0(0) cos psi, so
//     the two axes along the walls are the candidates (docs/theory/mechanisms.md §4.2).
//  3. The displacement bound of the wedge mechanisms: the bearing part's own
//     overturning (§5), the house's composite wedge by hand.
//  4. The ring beam's force on the beam's axis at u_m: the capacity curve
//     against its closed form (§1.2).
// Every expected number is derived in this file from the geometry (virtual
// work of rigid bodies, written out), independently of the library's chains.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/kinematic/friction_overturning.hpp>
#include <assess/kinematic/horizontal_flexure.hpp>
#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>
#include <assess/kinematic/roof_thrust.hpp>
#include <assess/support/error.hpp>
#include <assess/support/units.hpp>

#include <algorithm>
#include <cmath>

using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {
// Closed forms vs the chains: linear algebra and sums, round-off only.
constexpr double tol_alpha = 1e-9;   // (-), alpha0 ~ 0.05-0.7
constexpr double tol_ratio = 1e-9;   // (-), e*, d*/d_k
constexpr double tol_rad = 1e-12;    // rad, rotation bounds
constexpr double tol_disp = 1e-9;    // m, displacements d_k, d*
// Capacity curve points against the closed-form alpha(theta): Brent/Newton
// at 1e-13 of the chain's size, theta by bisection here.
constexpr double tol_curve = 1e-8;   // (-)

constexpr double kN = assess::units::kN;
constexpr double deg = assess::units::deg;

double a0(const assess::Chain& c) { return assess::activation_multiplier(c); }
assess::KinematicResult analyse(const assess::Chain& c) { return assess::analyse_kinematic(c); }

// The seismic weight of a load of the chain by name (0 if it is held or absent).
bool pushes(const assess::Chain& c, const std::string& name) {
  for (const assess::Load& l : c.loads())
    if (l.name == name) return l.seismic;
  FAIL("no load named " << name);
  return false;
}
}  // namespace

// ------------------------------------------------------------ 1. loads move with their block
TEST_CASE("loads move with their block: simple overturning, a floor at the top (C8.7.1.1)") {
  // One storey h = 4 m, t = 0.5 m, 1 m long, 18 kN/m^3: W = 36 kN at (t/2, h/2)
  // from the outer toe. A floor N = 20 kN at 0.1 m from the inner face, at the top:
  // lever t - 0.1 = 0.4 m. Rotation theta about the toe: dx = z theta, dz = x theta.
  //   moving: alpha0 = (W t/2 + N 0.4)/(W h/2 + N h) = (9 + 8)/(72 + 80) = 0.111842
  //   held:   alpha0 = (9 + 8)/72 = 0.236111
  // e* = (sum W dx)^2/(sum W sum W dx^2), int z^2 dW = W h^2/3 for the wall.
  const double W = 36.0 * kN, N = 20.0 * kN, h = 4.0;
  assess::SimpleOverturningParams p;
  assess::Storey s;
  s.height = h;
  s.thickness = 0.5;
  s.floor_weight = N;
  s.floor_distance_from_inner_face = 0.1;
  p.storeys = {s};
  p.unit_weight = 18.0 * kN;
  p.length = 1.0;
  const auto moving = assess::simple_overturning(p).candidates[0].chain;
  CHECK(pushes(moving, "floor level 1"));
  CHECK_CLOSE(a0(moving), (W * 0.25 + N * 0.4) / (W * h / 2 + N * h), abs_tol(tol_alpha));
  const double Wx = W * h / 2 + N * h, Wx2 = W * h * h / 3 + N * h * h;
  CHECK_CLOSE(analyse(moving).e_star, Wx * Wx / ((W + N) * Wx2), abs_tol(tol_ratio));
  p.storeys[0].floor_held = true;
  const auto held = assess::simple_overturning(p).candidates[0].chain;
  CHECK_CLOSE(a0(held), (W * 0.25 + N * 0.4) / (W * h / 2), abs_tol(tol_alpha));
  CHECK_CLOSE(analyse(held).e_star, 0.75, abs_tol(tol_ratio));  // the wall alone
  // A floor that neither bears nor pushes is refused.
  p.storeys[0].floor_bears = false;
  CHECK_THROWS_AS(assess::simple_overturning(p), assess::InputError);
}

TEST_CASE("loads move with their block: the roof on a roof-thrust wall, moving or held") {
  // The notes' wall (h 4, t 0.6, W = 43.2 kN/m) under the A-frame roof (V = 4.5 kN/m
  // at e = 0.4 m, H = V/(2 tan 35)): moving, (W t/2 + V e - H h)/(W h/2 + V h) =
  // 0.018263 (issue 33); held, the roof's mass does not push: /(W h/2).
  assess::RoofSpec roof;
  roof.load = 1.5 * kN;
  roof.span = 3.0;
  roof.pitch_deg = 35.0;
  roof.seat_from_inner_face = 0.2;
  assess::SimpleOverturningParams p;
  assess::Storey s;
  s.height = 4.0;
  s.thickness = 0.6;
  p.storeys = {s};
  p.unit_weight = 18.0 * kN;
  p.length = 1.0;
  p.roof = roof;
  const double W = 43.2 * kN, V = 4.5 * kN, H = V / (2.0 * std::tan(35.0 * deg));
  const double num = W * 0.3 + V * 0.4 - H * 4.0;
  CHECK_CLOSE(a0(assess::roof_thrust_overturning(p).candidates[0].chain), num / (W * 2.0 + V * 4.0), abs_tol(tol_alpha));
  p.roof->held = true;
  const auto held = assess::roof_thrust_overturning(p).candidates[0].chain;
  CHECK_FALSE(pushes(held, "roof weight"));
  CHECK_CLOSE(a0(held), num / (W * 2.0), abs_tol(tol_alpha));
}

TEST_CASE("loads move with their block: vertical flexure, the top load at the top restraint does not move") {
  // h = 3.5 m between the restraints, t = 0.4 m, middle hinge at hh = 2 m
  // (upper block h2 = 1.5 m), 1 m long, 20 kN/m^3; N = 6 kN at d = 0.15 m from
  // the inner face. Lower block turns by theta about the outer base edge; the
  // middle hinge (-t, hh) moves by (hh, t) theta; the upper block turns back by
  // omega = theta hh/h2 so that its outer top edge stays on the restraint. The
  // top load's point then moves by (0, t + hh d/h2) theta: it bears, it does
  // not move horizontally, so the restraint takes its horizontal force:
  //   alpha0 = [W1 t/2 + W2 (t + hh t/(2 h2)) + N (t + hh d/h2)] / [(W1 + W2) hh/2]
  // and e* = 3/4 (both blocks' dx linear in z from 0 to hh theta to 0); N in
  // sum W would only lower e* (issue 38: its mass is the building's).
  const double t = 0.4, hh = 2.0, h2 = 1.5, d = 0.15, N = 6.0 * kN, g = 20.0 * kN;
  const double W1 = g * t * hh, W2 = g * t * h2;
  assess::VerticalFlexureParams p;
  p.height = hh + h2;
  p.thickness = t;
  p.unit_weight = g;
  p.length = 1.0;
  p.top_load = N;
  p.top_load_distance_from_inner_face = d;
  p.hinge_height = hh;
  const auto c = assess::vertical_flexure(p).candidates[0].chain;
  const double expected = (W1 * t / 2 + W2 * (t + hh * t / (2 * h2)) + N * (t + hh * d / h2)) / ((W1 + W2) * hh / 2);
  CHECK_CLOSE(a0(c), expected, abs_tol(tol_alpha));
  const assess::KinematicResult r = analyse(c);
  CHECK_CLOSE(r.e_star, 0.75, abs_tol(tol_ratio));
  CHECK_CLOSE(r.sum_W, W1 + W2, rel_tol(1e-12));
  for (const assess::LoadWork& w : r.loads)
    if (w.load.name == "top load") CHECK(std::fabs(w.dx) < 1e-12);
}

namespace {
// The composite wedge: façade h x t x L, wedges of 2 side walls b thick,
// crack at 45 deg (texture 0.4 x 0.2), reach = h.
assess::CompositeOverturningParams composite(double h, double t, double L, double gamma, double b, double side_length) {
  assess::CompositeOverturningParams p;
  p.height = h;
  p.thickness = t;
  p.length = L;
  p.unit_weight = gamma;
  p.side_thickness = b;
  p.side_walls = 2;
  p.side_length = side_length;
  p.unit_length = 0.4;
  p.course_height = 0.2;
  return p;
}
}  // namespace

TEST_CASE("loads move with their block: composite overturning, a weight on the façade's top") {
  // h 6, t 0.5, L 5, 18 kN/m^3: W_f = 270 kN at (t/2, h/2); wedges 2 x 0.4 m,
  // reach 6 m: W_w = 18 * 0.8 * 36/2 = 259.2 kN at (t + reach/3, 2h/3) = (2.5, 4);
  // N = 30 kN at (t/2, h).
  //   moving: (67.5 + 648 + 7.5)/(810 + 1036.8 + 180) = 0.356719
  //   held:   723/1846.8 = 0.391488
  auto p = composite(6.0, 0.5, 5.0, 18.0 * kN, 0.4, 8.0);
  p.top_weight = 30.0 * kN;
  const double num = (67.5 + 259.2 * 2.5 + 30.0 * 0.25) * kN;
  CHECK_CLOSE(a0(assess::composite_overturning(p).candidates[0].chain), num / ((810.0 + 259.2 * 4.0 + 30.0 * 6.0) * kN),
              abs_tol(tol_alpha));
  p.top_weight_held = true;
  CHECK_CLOSE(a0(assess::composite_overturning(p).candidates[0].chain), num / ((810.0 + 259.2 * 4.0) * kN),
              abs_tol(tol_alpha));
}

TEST_CASE("loads move with their block: gable, the ridge beam's weight") {
  // Triangle b = 9 m, h_g = 2.8 m, t = 0.45 m, 20 kN/m^3 on 24 slices (the
  // generator's model: slice i of height dz carries the triangle's weight over
  // it, gamma t b (1 - (i + 1/2)/n) dz, at its mid-height). Ridge R = 12 kN at the
  // apex, (t/2, h_g). alpha0 = (sum W_i + R) (t/2) / (sum W_i z_i + R h_g) moving,
  // / sum W_i z_i held.
  assess::GableParams p;
  p.width = 9.0;
  p.height = 2.8;
  p.thickness = 0.45;
  p.unit_weight = 20.0 * kN;
  p.ridge_weight = 12.0 * kN;
  const int n = p.slices;
  const double dz = p.height / n;
  double W = 0.0, Wz = 0.0;
  for (int i = 0; i < n; ++i) {
    const double Wi = p.unit_weight * p.thickness * p.width * (1.0 - (i + 0.5) / n) * dz;
    W += Wi;
    Wz += Wi * (i + 0.5) * dz;
  }
  const double R = p.ridge_weight, num = (W + R) * p.thickness / 2;
  CHECK_CLOSE(a0(assess::gable_overturning(p).candidates[0].chain), num / (Wz + R * p.height), abs_tol(tol_alpha));
  p.ridge_weight_held = true;
  CHECK_CLOSE(a0(assess::gable_overturning(p).candidates[0].chain), num / Wz, abs_tol(tol_alpha));
}

namespace {
// The corner by hand about the axes along the walls (no openings, reaches
// below the walls' lengths): pier t_B x t_A x h, arm A a triangle of wall A
// (x from t_B to t_B + z tan beta_A, through t_A), arm B of wall B (y from
// t_A to t_A + z tan beta_B, through t_B); top load N on the pier's centre;
// hip thrust P along the bisector at the top. About the axis along wall A
// (psi = 0) s = y; along wall B (psi = 90) s = x; every point's dx = z.
struct CornerHand {
  double tA, tB, tanA, tanB, h, g, N, P;
  bool N_moves = true;
  double alpha(double psi) const {
    const double Wp = g * tA * tB * h, WA = g * tA * h * h * tanA / 2, WB = g * tB * h * h * tanB / 2;
    const bool along_a = psi == 0.0;
    // Lever arms s about the axis: the pier and the top load at the pier's centre.
    const double sp = along_a ? tA / 2 : tB / 2;
    const double sA = along_a ? tA / 2 : tB + h * tanA / 3;  // a triangle with its apex at the base: 1/3 of the reach
    const double sB = along_a ? tA + h * tanB / 3 : tB / 2;
    const double num = Wp * sp + WA * sA + WB * sB + N * sp - P * std::cos(45.0 * deg) * h;
    const double den = Wp * h / 2 + (WA + WB) * 2 * h / 3 + (N_moves ? N * h : 0.0);
    return num / den;
  }
};
assess::CornerOverturningParams corner_params(const CornerHand& c) {
  assess::CornerOverturningParams p;
  p.height = c.h;
  p.unit_weight = c.g;
  p.wall_a.thickness = c.tA;
  p.wall_a.length = 20.0;
  p.wall_a.crack_reach = c.h * c.tanA;
  p.wall_b.thickness = c.tB;
  p.wall_b.length = 20.0;
  p.wall_b.crack_reach = c.h * c.tanB;
  p.top_weight = c.N;
  p.thrust = c.P;
  return p;
}
}  // namespace

TEST_CASE("loads move with their block: the corner's top load, moving or held") {
  CornerHand hand{0.6, 0.45, 0.4, 0.25, 6.0, 18.0 * kN, 20.0 * kN, 0.0};
  auto p = corner_params(hand);
  p.axis_deg = 0.0;
  CHECK_CLOSE(a0(assess::corner_overturning(p).candidates[0].chain), hand.alpha(0.0), abs_tol(tol_alpha));
  p.top_weight_held = true;
  hand.N_moves = false;
  CHECK_CLOSE(a0(assess::corner_overturning(p).candidates[0].chain), hand.alpha(0.0), abs_tol(tol_alpha));
}

TEST_CASE("loads move with their block: the side walls' load on the wedges, the floors on the façade") {
  // The façade of issue 33's friction example (h 6, t 0.5, L 5, 18 kN/m^3; side
  // walls 0.4 m, crack at 45 deg reaching 6 m): W = 270 kN, the wedges 2 x 129.6 kN
  // at (t + 2, 4). q = 10 kN/m on each side wall over the reach: Q = 2 * 10 * 6 =
  // 120 kN on the wedges' top at (t + reach/2, h) = (3.5, 6). The wedge candidate:
  //   moving (the load rests on the wedges): (67.5 + 648 + 420)/(810 + 1036.8 + 720) = 0.442380
  //   held:                                  1135.5/1846.8 = 0.614847
  // (issue 33's tool gave the held value without being told: 39 % on the unsafe side).
  assess::FrictionOverturningParams p;
  p.height = 6.0;
  p.thickness = 0.5;
  p.length = 5.0;
  p.unit_weight = 18.0 * kN;
  p.side_thickness = 0.4;
  p.side_length = 6.0;
  p.unit_length = 0.4;
  p.course_height = 0.2;
  p.friction = 0.6;
  p.side_load = 10.0 * kN;
  const double num = 67.5 + 2 * 129.6 * 2.5 + 120.0 * 3.5;
  auto set = assess::friction_overturning(p);
  REQUIRE(set.candidates.size() == 2);
  CHECK(pushes(set.candidates[1].chain, "side walls' load on the wedges"));
  CHECK_CLOSE(a0(set.candidates[1].chain), num / (810.0 + 2 * 129.6 * 4.0 + 120.0 * 6.0), abs_tol(tol_alpha));
  CHECK_CLOSE(a0(set.candidates[1].chain), 0.442380, abs_tol(5e-7));
  p.side_load_held = true;
  CHECK_CLOSE(a0(assess::friction_overturning(p).candidates[1].chain), num / (810.0 + 2 * 129.6 * 4.0), abs_tol(tol_alpha));
  // The frictional candidate: the side walls stay, the load only presses their steps
  // (F_q = f q tan h = 36 kN each at h/2): no mass of it moves.
  p.side_load_held = false;
  CHECK_CLOSE(a0(assess::friction_overturning(p).candidates[0].chain), (67.5 + 311.04 + 2 * 36.0 * 3.0) / 810.0,
              abs_tol(tol_alpha));
  // A floor on the façade and a top weight move by default (their masses push).
  p.side_load = 0.0;
  p.friction = 1e-12;
  assess::SupportedFloor fl;
  fl.weight = 50.0 * kN;
  fl.z = 6.0;
  fl.distance_from_inner_face = 0.25;
  p.floors = {fl};
  p.top_weight = 10.0 * kN;
  // Bare façade with the floor (0.25 m lever) and the top weight (0.25 m): both at h.
  CHECK_CLOSE(a0(assess::friction_overturning(p).candidates[0].chain), (67.5 + 12.5 + 2.5) / (810.0 + 300.0 + 60.0),
              abs_tol(tol_alpha));
  p.top_weight_held = true;
  CHECK_CLOSE(a0(assess::friction_overturning(p).candidates[0].chain), (67.5 + 12.5 + 2.5) / (810.0 + 300.0),
              abs_tol(tol_alpha));
}

// ------------------------------------------------------------ 2. the corner: two axes
TEST_CASE("corner: alpha0(psi) = alpha0(90) sin psi + alpha0(0) cos psi; the two axes along the walls are the candidates") {
  // Unequal walls, a top load and a hip thrust along the bisector. Every term
  // of the virtual work about an axis at psi through the outer corner is the
  // work of a point or a force with s = x sin psi + y cos psi, and sum W z does
  // not depend on psi: alpha0(psi) D = a sin psi + b cos psi. With a, b > 0,
  // a sin + b cos >= min(a, b) (sin + cos) >= min(a, b): no axis between the
  // walls governs (docs/theory/mechanisms.md §4.2).
  const CornerHand hand{0.6, 0.45, 0.4, 0.25, 6.0, 18.0 * kN, 20.0 * kN, 8.0 * kN};
  const auto p = corner_params(hand);
  const auto set = assess::corner_overturning(p);
  REQUIRE(set.candidates.size() == 2);
  CHECK(set.candidates[0].parameter == 0.0);
  CHECK(set.candidates[1].parameter == 90.0);
  const double a_0 = a0(set.candidates[0].chain), a_90 = a0(set.candidates[1].chain);
  CHECK_CLOSE(a_0, hand.alpha(0.0), abs_tol(tol_alpha));
  CHECK_CLOSE(a_90, hand.alpha(90.0), abs_tol(tol_alpha));
  const std::size_t gi = assess::governing_candidate(set);
  CHECK(a0(set.candidates[gi].chain) == std::min(a_0, a_90));
  for (int i = 0; i <= 90; ++i) {
    auto q = p;
    q.axis_deg = double(i);
    const double a = a0(assess::corner_overturning(q).candidates[0].chain);
    INFO("axis at " << i << " deg");
    CHECK_CLOSE(a, a_90 * std::sin(i * deg) + a_0 * std::cos(i * deg), abs_tol(tol_alpha));
    CHECK(a >= std::min(a_0, a_90) - tol_alpha);
  }
  // The 45 deg reduction is reported beside them, for comparison.
  bool found = false;
  for (const auto& q : set.candidates[0].quantities)
    if (q.label.rfind("α0 about the axis at 45°", 0) == 0) {
      found = true;
      CHECK_CLOSE(q.value, (a_90 + a_0) * std::cos(45.0 * deg), abs_tol(tol_alpha));
    }
  CHECK(found);
}

// ------------------------------------------------------------ 3. the displacement bound
TEST_CASE("the composite wedge is bounded by the façade's own overturning: the house's M3 by hand") {
  // mechanisms/building-house.json M3: façade h 7.5, t 0.5, L 8, 20 kN/m^3, two
  // side walls 0.45 m, crack at 45 deg (units 0.4 x 0.2), reach 7.5 m.
  // W_f = 600 kN at (t/2, h/2), W_w = 20 * 0.9 * 7.5^2/2 = 506.25 kN at (t + 2.5, 5).
  // theta_b = atan((t/2)/(h/2)) = atan(1/15): the façade's weight over its hinge.
  const double h = 7.5, t = 0.5, Wf = 600.0 * kN, Ww = 506.25 * kN;
  const auto set = assess::composite_overturning(composite(h, t, 8.0, 20.0 * kN, 0.45, 9.0));
  REQUIRE(set.candidates.size() == 1);
  const auto& m = set.candidates[0];
  const double thb = std::atan(0.25 / 3.75);
  CHECK_CLOSE(m.rotation_bound, thb, abs_tol(tol_rad));
  CHECK(m.rotation_bound_reason == "the façade's own overturning about its hinge");
  assess::KinematicOptions opt;
  opt.rotation_cap = m.rotation_bound;
  const assess::KinematicResult r = assess::analyse_kinematic(m.chain, opt);
  REQUIRE(r.curve_complete());
  // The control point: the centroid of the seismic weights (x inward < 0).
  const double xc = -(Wf * t / 2 + Ww * (t + 2.5)) / (Wf + Ww), zc = (Wf * h / 2 + Ww * 5.0) / (Wf + Ww);
  CHECK_CLOSE(r.control_point.x(), xc, abs_tol(1e-12));
  CHECK_CLOSE(r.control_point.y(), zc, abs_tol(1e-12));
  // d*/d_k = int dx^2 dW / (dx_k int dx dW), dx = z: the façade W h^2/3, the
  // triangle with its apex at the base W h^2/2.
  const double Wz = Wf * h / 2 + Ww * 2 * h / 3, Wz2 = Wf * h * h / 3 + Ww * h * h / 2;
  CHECK_CLOSE(r.d_star_per_dk, Wz2 / (zc * Wz), abs_tol(tol_ratio));
  const double dkb = xc * (std::cos(thb) - 1.0) + zc * std::sin(thb);
  CHECK_CLOSE(r.dk0_bound, dkb, abs_tol(tol_disp));
  const double d0b = Wz2 / (zc * Wz) * dkb;
  CHECK(r.d0_star > 1.0);  // the rigid chain: metres
  CHECK_CLOSE(r.d_SLV, 0.4 * d0b, abs_tol(tol_disp));
  CHECK_CLOSE(r.d_SLC, 0.6 * d0b, abs_tol(tol_disp));
  CHECK_CLOSE(r.du_star, 0.4 * d0b, abs_tol(tol_disp));
  CHECK(r.d_SLV < 0.5 * t);
}

TEST_CASE("the bound counts the weights bearing on the part, held or moving; the frictional wedge alike") {
  // A top weight N = 100 kN at (t/2, h) on the façade of h 6, t 0.5 (W_f = 270 kN):
  // theta_b = atan((W_f + N) (t/2) / (W_f h/2 + N h)) whether or not its mass pushes.
  auto p = composite(6.0, 0.5, 5.0, 18.0 * kN, 0.4, 8.0);
  p.top_weight = 100.0 * kN;
  const double expected = std::atan((270.0 + 100.0) * 0.25 / (270.0 * 3.0 + 100.0 * 6.0));
  CHECK_CLOSE(assess::composite_overturning(p).candidates[0].rotation_bound, expected, abs_tol(tol_rad));
  p.top_weight_held = true;
  CHECK_CLOSE(assess::composite_overturning(p).candidates[0].rotation_bound, expected, abs_tol(tol_rad));
  // The friction set's wedge candidate has the same bound; its frictional one
  // ends where the steps disengage (its own chain) and has none.
  assess::FrictionOverturningParams f;
  f.height = 6.0;
  f.thickness = 0.5;
  f.length = 5.0;
  f.unit_weight = 18.0 * kN;
  f.side_thickness = 0.4;
  f.side_length = 6.0;
  f.unit_length = 0.4;
  f.course_height = 0.2;
  f.friction = 0.6;
  f.top_weight = 100.0 * kN;
  const auto set = assess::friction_overturning(f);
  CHECK_FALSE(std::isfinite(set.candidates[0].rotation_bound));
  CHECK_CLOSE(set.candidates[1].rotation_bound, expected, abs_tol(tol_rad));
}

// ------------------------------------------------------------ 4. the ring beam
TEST_CASE("ring beam: the force M_Rd L/(u_m (L - u_m)) at u_m on the wall's centre line, along the capacity curve") {
  // The strip of issue 33 (L 5, t 0.5, h 1, 18 kN/m^3, H = 20 kN, rectangular
  // block at f = 1.5 MPa: e = H/(2 f h) from the faces, z = t - 2e) with a ring
  // beam M_Rd = 10 kN m: F = 4 M/L at (-t/2, L/2) on the first half. Each half
  // turns by theta about its support hinge (-e, 0): the centre line's point at
  // mid-span moves outward at (t/2 - e) sin + L/2 cos, the masses at
  // W_A (L/4 cos + (t/2 - e) sin), the supports separate at 2 (z cos - L/2 sin):
  //   alpha(theta) = [2 H (z cos - L/2 sin) + F ((t/2 - e) sin + L/2 cos)]
  //                  / [2 W_A (L/4 cos + (t/2 - e) sin)].
  assess::HorizontalFlexureParams p;
  p.span = 5.0;
  p.thickness = 0.5;
  p.unit_weight = 18.0 * kN;
  p.strength = 1.5e6;
  p.restraint = 20.0 * kN;
  p.ring_beam_moment = 10.0 * kN;
  assess::HorizontalStrip s;
  s.base_z = 6.5;
  s.height = 1.0;
  p.strips = {s};
  const auto set = assess::horizontal_flexure(p);
  const assess::KinematicResult r = analyse(set.candidates[0].chain);
  REQUIRE(r.curve_complete());
  const double L = 5.0, t = 0.5, H = 20.0 * kN, e = H / (2.0 * 1.5e6), z = t - 2.0 * e, F = 4.0 * 10.0 * kN / L;
  const double WA = 18.0 * kN * t * 1.0 * L / 2.0;
  auto alpha = [&](double th) {
    const double c = std::cos(th), sn = std::sin(th);
    return (2 * H * (z * c - L / 2 * sn) + F * ((t / 2 - e) * sn + L / 2 * c)) / (2 * WA * (L / 4 * c + (t / 2 - e) * sn));
  };
  CHECK_CLOSE(r.alpha0, alpha(0.0), abs_tol(tol_alpha));
  for (const assess::CapacityPoint& pt : r.curve) {
    double lo = 0.0, hi = 0.5;  // the control point (-t/2, L/2): d_k = (e - t/2)(cos - 1) + L/2 sin
    for (int i = 0; i < 200; ++i) {
      const double th = 0.5 * (lo + hi);
      ((e - t / 2) * (std::cos(th) - 1.0) + L / 2 * std::sin(th) < pt.dk ? lo : hi) = th;
    }
    INFO("d_k = " << pt.dk);
    CHECK_CLOSE(pt.alpha, alpha(0.5 * (lo + hi)), abs_tol(tol_curve));
  }
  // The reading's reason: the exact plastic work M_Rd (theta_A + theta_B) is
  // 2 M per unit theta; the force's work on the centre line stays within 0.5 %
  // of it up to the curve's end (at the middle hinge, (t - e) for (t/2 - e): 1.9 %).
  const double th0 = std::atan(2.0 * z / L);
  double worst_centre = 0.0, worst_hinge = 0.0;
  for (int i = 0; i <= 1000; ++i) {
    const double th = th0 * i / 1000;
    worst_centre = std::max(worst_centre, std::fabs(F * ((t / 2 - e) * std::sin(th) + L / 2 * std::cos(th)) / (2 * 10.0 * kN) - 1));
    worst_hinge = std::max(worst_hinge, std::fabs(F * (z * std::sin(th) + L / 2 * std::cos(th)) / (2 * 10.0 * kN) - 1));
  }
  CHECK(worst_centre < 0.005);
  CHECK(worst_hinge > 0.018);
}
