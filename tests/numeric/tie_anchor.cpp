// The anchor where it is (issue 37): the punched wedge cut by the wall's
// crown, its ends, its openings and the neighbouring wedges, integrated over
// the masonry that exists; the sliding of the masonry above the anchor; the
// anchor within the wall; the temperature action, the corrosion allowance
// and the elongation a ductile rod delivers. Against closed forms derived
// here and, for the general cuts, a brute-force integration written here
// independently of the library (sampling the wedge's boundary).
//
// The wedge at depth y (0 <= y <= s) is the rectangle [x - w/2 - y, x + w/2 +
// y] x [z - h/2 - y, z + h/2 + y]; with only the crown at distance c (>= h/2)
// above the anchor's centre, y1 = min(s, c - h/2) and
//   A_p = 2 (w + h) y1 + 4 y1^2 + [w (s - y1) + (s^2 - y1^2)] + [2 (c + h/2)(s - y1) + (s^2 - y1^2)]
// (the whole boundary up to y1; beyond it the bottom edge w + 2y and two sides
// from z - h/2 - y up to the crown, c + h/2 + y).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/kinematic/tie.hpp>
#include <assess/kinematic/tie_catalogue.hpp>
#include <assess/kinematic/tie_checks.hpp>
#include <assess/support/error.hpp>
#include <assess/support/units.hpp>

#include <cmath>
#include <string>
#include <vector>

using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

constexpr double tol_exact = 1e-12;  // relative: the wedge's piecewise-linear integral (two-point Gauss is exact)
constexpr double tol_brute = 2e-3;   // relative: the brute-force sampling below (400 depths x 4000 points per edge)
constexpr double tol_force = 1e-9;   // relative: forces from the exact areas

// A tie with an anchor of footprint w x h at height z on a wall of thickness
// s, its crown at `crown`; `count` ties on `L` m of wall.
assess::Tie tie(double w, double h, double s, double z, double crown, double tau, double FC, int count = 1,
                double L = 12.0) {
  assess::Tie t;
  t.name = "t";
  t.point = {0.0, z};
  t.rod.diameter = 0.016;
  t.rod.area = assess::units::pi * 0.016 * 0.016 / 4;
  t.rod.fyk = 275e6;
  t.rod.ftk = 430e6;
  t.rod.thread_diameter = 0.016;
  t.rod.thread_area = 157e-6;
  t.rod.nut_width = 0.024;
  t.free_length = 12.0;
  t.anchor.a = w;
  t.anchor.b = h;
  t.anchor.t = 0.02;
  t.masonry.fm = 5.8e6;
  t.masonry.tau = tau;
  t.masonry.thickness = s;
  t.masonry.FC = FC;
  t.masonry.gamma_M = 2.0;
  t.masonry.unit_weight = 20e3;
  t.layout.wall_length = L;
  t.layout.count = count;
  t.layout.edge_distance = L / (2.0 * count);
  t.layout.crown = crown;
  t.spacing = L / count;
  return t;
}

// The closed form under the crown only.
double area_under_crown(double w, double h, double s, double c) {
  const double y1 = std::max(0.0, std::min(s, c - h / 2));
  double A = 2 * (w + h) * y1 + 4 * y1 * y1;
  if (y1 < s) A += w * (s - y1) + (s * s - y1 * y1) + 2 * (c + h / 2) * (s - y1) + (s * s - y1 * y1);
  return A;
}

struct Rect {
  double x0, x1, z0, z1;
};

// Brute force: the length in masonry of the wedge's boundary at each of N
// depths (midpoints), each edge sampled at M midpoints; masonry = the strip
// (x_lo, x_hi), between the base and the crown, off every opening.
double brute_area(double x, double z, double w, double h, double s, double x_lo, double x_hi, double base, double crown,
                  const std::vector<Rect>& openings) {
  auto masonry = [&](double px, double pz) {
    if (!(px > x_lo && px < x_hi && pz > base && pz < crown)) return false;
    for (const Rect& o : openings)
      if (px > o.x0 && px < o.x1 && pz > o.z0 && pz < o.z1) return false;
    return true;
  };
  const int N = 400, M = 4000;
  double A = 0.0;
  for (int i = 0; i < N; ++i) {
    const double y = (i + 0.5) * s / N;
    const double xa = x - w / 2 - y, xb = x + w / 2 + y, za = z - h / 2 - y, zb = z + h / 2 + y;
    double len = 0.0;
    for (int j = 0; j < M; ++j) {
      const double u = (j + 0.5) / M;
      const double px = xa + u * (xb - xa), pz = za + u * (zb - za);
      // Top and bottom edges, then the two sides (a point on a side exactly on
      // the strip's line is not in it: the library's rule, strict inequalities).
      len += ((masonry(px, zb) ? 1 : 0) + (masonry(px, za) ? 1 : 0)) * (xb - xa) / M;
      len += ((masonry(xa, pz) ? 1 : 0) + (masonry(xb, pz) ? 1 : 0)) * (zb - za) / M;
    }
    A += len * s / N;
  }
  return A;
}

}  // namespace

TEST_CASE("issue 37: the punched wedge cut by the crown: the issue's figures 78.0 -> 67.4, 39.0 -> 24.6, 31.7 -> 21.3 kN") {
  // Church: 250 x 250 plate at 14.0 m on the 14.57 m façade, s = 0.65 m, tau 0.09 MPa, LC1 (FC 1.35).
  {
    const assess::Tie t = tie(0.25, 0.25, 0.65, 14.0, 14.57, 0.09e6, 1.35, 4, 12.0);
    const double fvd = 0.09e6 / (1.35 * 2.0);
    const auto r = assess::tie_resistance(t);
    CHECK_CLOSE(r.wedge.full_area, 0.65 * (2 * 0.5 + 4 * 0.65), rel_tol(tol_exact));  // 2.340 m^2
    CHECK_CLOSE(fvd * r.wedge.full_area, 78000.0, rel_tol(tol_force));
    CHECK_CLOSE(r.wedge.area, area_under_crown(0.25, 0.25, 0.65, 0.57), rel_tol(tol_exact));
    CHECK_CLOSE(r.wedge.area, 1.2371 + 0.78515, rel_tol(1e-12));  // y1 = 0.445 m
    CHECK_CLOSE(r.punching, fvd * (1.2371 + 0.78515), rel_tol(tol_force));
    CHECK_CLOSE(r.punching, 67408.3, rel_tol(1e-5));
  }
  // House: 350 x 350 plate at 7.3 m on the 7.5 m façade, s = 0.45 m, tau 0.065 MPa, LC2 (FC 1.2).
  {
    const assess::Tie t = tie(0.35, 0.35, 0.45, 7.3, 7.5, 0.065e6, 1.2, 6, 8.0);
    const double fvd = 0.065e6 / 2.4;
    const auto r = assess::tie_resistance(t);
    CHECK_CLOSE(fvd * r.wedge.full_area, 39000.0, rel_tol(tol_force));
    CHECK_CLOSE(r.wedge.area, area_under_crown(0.35, 0.35, 0.45, 0.2), rel_tol(tol_exact));
    CHECK_CLOSE(r.punching, fvd * 0.90875, rel_tol(tol_force));  // y1 = 0.025 m: 0.0375 + 0.87125 m^2
    CHECK_CLOSE(r.punching, 24612.0, rel_tol(1e-5));
  }
  // M2's existing tie: 200 x 200 plate at 7.3 m, three ties on 8 m.
  {
    const assess::Tie t = tie(0.20, 0.20, 0.45, 7.3, 7.5, 0.065e6, 1.2, 3, 8.0);
    const auto r = assess::tie_resistance(t);
    CHECK_CLOSE(0.065e6 / 2.4 * r.wedge.full_area, 31687.5, rel_tol(tol_force));
    CHECK_CLOSE(r.punching, 0.065e6 / 2.4 * 0.785, rel_tol(tol_force));  // y1 = 0.10 m: 0.12 + 0.665 m^2
    CHECK_CLOSE(r.punching, 21260.4, rel_tol(1e-5));
  }
}

TEST_CASE("issue 37: anchors 0.2 to 0.6 m below the crown: the wedge and the sliding block by their closed forms") {
  // A 300 x 300 plate in the house's wall (s 0.45 m, tau 0.065 MPa, FC 1.2, gamma_M 2, 20 kN/m^3), one tie on
  // 8 m (no neighbour, the ends far): A_p(c) as above; the sliding block from the bed joint at z - h/2 up to the
  // crown, H = c + h/2: sides 2 H s, base s (w + s), sigma_n = 20 kN/m^3 H + q / s.
  const double w = 0.3, h = 0.3, s = 0.45, fvd = 0.065e6 / 2.4, mu = 0.4, q = 3.1e3;
  const double expected[] = {0.870, 0.990, 1.110, 1.230, 1.350};
  for (int i = 0; i < 5; ++i) {
    const double c = 0.2 + 0.1 * i;
    assess::Tie t = tie(w, h, s, 7.5 - c, 7.5, 0.065e6, 1.2, 1, 8.0);
    t.layout.crown_load = q;
    const auto r = assess::tie_resistance(t);
    CAPTURE(c);
    CHECK_CLOSE(r.wedge.area, area_under_crown(w, h, s, c), rel_tol(tol_exact));
    CHECK_CLOSE(r.wedge.area, expected[i], rel_tol(1e-12));
    const double H = c + h / 2, sigma = 20e3 * H + q / s;
    CHECK_CLOSE(r.slide.side_area, 2 * H * s, rel_tol(tol_exact));
    CHECK_CLOSE(r.slide.base_area, s * (w + s), rel_tol(tol_exact));
    CHECK_CLOSE(r.slide.sigma_n, sigma, rel_tol(tol_exact));
    CHECK_CLOSE(r.sliding, fvd * 2 * H * s + (fvd + mu * sigma / 2.0) * s * (w + s), rel_tol(tol_force));
    CHECK(r.sliding < r.punching);  // near the crown the masonry above slides before the wedge is pulled out
  }
  // 0.6 m = h/2 + s below the crown the wedge is whole; far below, the sliding block's sides are long.
  const auto far = assess::tie_resistance(tie(w, h, s, 5.0, 7.5, 0.065e6, 1.2, 1, 8.0));
  CHECK_CLOSE(far.wedge.area, far.wedge.full_area, rel_tol(tol_exact));
  CHECK(far.sliding > far.punching);
  CHECK(far.governing != "sliding");
}

TEST_CASE("issue 37: wedges cut by the neighbours, the wall's ends and the openings, against a brute-force integration") {
  struct Case {
    const char* what;
    int count;
    double L;
    std::vector<Rect> openings;
    double z, crown;
  };
  const double w = 0.3, h = 0.3, s = 0.45;
  const std::vector<Case> cases{
      {"neighbours 1.0 m apart (wedges 1.2 m wide overlap)", 8, 8.0, {}, 5.0, 7.5},
      {"the wall's ends 0.4 m from the end ties", 5, 4.0, {}, 5.0, 7.5},
      {"a window beside the anchors and the crown", 4, 8.0, {{1.3, 2.5, 6.0, 7.3}}, 7.0, 7.5},
      {"a window above the anchors", 2, 8.0, {{1.7, 2.3, 5.4, 6.6}}, 5.0, 7.5},
  };
  for (const Case& k : cases) {
    assess::Tie t = tie(w, h, s, k.z, k.crown, 0.065e6, 1.2, k.count, k.L);
    for (const Rect& o : k.openings) t.layout.openings.push_back({o.x0, o.x1, o.z0, o.z1});
    CAPTURE(k.what);
    double smallest = 1e300;
    for (int j = 0; j < k.count; ++j) {
      const auto W = assess::anchor_wedge(t, j);
      const double half = k.count > 1 ? t.layout.centre_spacing() / 2 : 1e300;
      const double x = t.layout.position(j);
      const double x_lo = j == 0 ? 0.0 : x - half, x_hi = j == k.count - 1 ? k.L : x + half;
      CHECK_CLOSE(W.x_lo, x_lo, abs_tol(1e-12));
      CHECK_CLOSE(W.x_hi, x_hi, abs_tol(1e-12));
      const double brute = brute_area(x, k.z, w, h, s, x_lo, x_hi, 0.0, k.crown, k.openings);
      CAPTURE(j);
      CHECK_CLOSE(W.area, brute, rel_tol(tol_brute));
      smallest = std::min(smallest, W.area);
    }
    // The weakest tie governs the level.
    CHECK_CLOSE(assess::tie_resistance(t).wedge.area, smallest, rel_tol(1e-12));
  }
  // The overlap by hand: inner ties 1.0 m apart, far from the crown (c = 2.5 m): the strip is 1.0 m wide; the
  // top and bottom edges are min(w + 2y, 1.0) long, the sides count while w/2 + y < 0.5 (y < 0.35 m).
  {
    const assess::Tie t = tie(w, h, s, 5.0, 7.5, 0.065e6, 1.2, 8, 8.0);
    const auto W = assess::anchor_wedge(t, 3);
    const double edges = 2 * (0.3 * 0.35 + 0.35 * 0.35 + 1.0 * (0.45 - 0.35));  // top + bottom
    const double sides = 2 * (0.3 * 0.35 + 0.35 * 0.35);                        // the two sides up to y = 0.35
    CHECK_CLOSE(W.area, edges + sides, rel_tol(tol_exact));
  }
}

TEST_CASE("issue 37: every anchor lies within the wall (an input that breaks it is refused, naming it)") {
  auto refused = [](const assess::Tie& t, const std::string& part) {
    try {
      t.validate();
    } catch (const assess::InputError& e) {
      const std::string m = e.what();
      CAPTURE(m);
      CHECK(m.find(part) != std::string::npos);
      return true;
    }
    return false;
  };
  CHECK_FALSE(refused(tie(0.4, 0.4, 0.45, 7.3, 7.5, 0.065e6, 1.2, 6, 8.0), ""));  // top at 7.5 m = the crown: in
  CHECK(refused(tie(0.5, 0.5, 0.45, 7.3, 7.5, 0.065e6, 1.2, 6, 8.0), "above the wall's crown at z = 7.5 m"));
  assess::Tie t = tie(0.3, 0.3, 0.45, 5.0, 7.5, 0.065e6, 1.2, 2, 8.0);
  t.layout.openings.push_back({1.9, 2.1, 4.9, 6.0});
  CHECK(refused(t, "lies over opening 1"));
  t = tie(0.3, 0.3, 0.45, 5.0, 7.5, 0.065e6, 1.2, 2, 8.0);
  t.layout.edge_distance = 0.1;
  CHECK(refused(t, "beyond the wall's ends"));
  t = tie(0.3, 0.3, 0.45, 5.0, 7.5, 0.065e6, 1.2, 40, 8.0);
  t.layout.edge_distance = 0.3;  // 40 ties 0.19 m apart
  CHECK(refused(t, "overlap"));
}

TEST_CASE("issue 37: temperature action and corrosion allowance in the rod and thread checks") {
  assess::Tie t = tie(0.3, 0.3, 0.45, 5.0, 7.5, 0.065e6, 1.2, 4, 8.0);
  t.rod.corrosion = 0.5e-3;
  t.delta_T = 20.0;
  const auto r = assess::tie_resistance(t);
  // Corroded sections: pi/4 (16 - 1)^2 = 176.715 mm^2; the M16 thread's stress diameter sqrt(4 x 157 / pi) =
  // 14.1386 mm -> pi/4 (13.1386)^2 = 135.576 mm^2.
  const double Ac = assess::units::pi / 4 * 15e-3 * 15e-3;
  const double ds = std::sqrt(4 * 157e-6 / assess::units::pi);
  const double Arc = assess::units::pi / 4 * (ds - 1e-3) * (ds - 1e-3);
  CHECK_CLOSE(r.area_c, Ac, rel_tol(1e-12));
  CHECK_CLOSE(r.thread_area_c, Arc, rel_tol(1e-12));
  CHECK_CLOSE(r.rod, Ac * 275e6 / 1.05, rel_tol(1e-12));          // 46.28 kN
  CHECK_CLOSE(r.thread, 0.9 * 430e6 * Arc / 1.25, rel_tol(1e-12)); // 41.97 kN
  CHECK_CLOSE(r.thread, 41974.5, rel_tol(1e-5));
  // The capacity design compares the corroded thread with the intact rod: 1.375 x 201.06 x 275 = 76.03 kN.
  CHECK_CLOSE(r.hierarchy_demand, 1.375 * assess::units::pi * 0.016 * 0.016 / 4 * 275e6, rel_tol(1e-12));
  // A Ø16 restrained and cooled by 20 K: E A alpha_T dT = 210e9 x 201.06e-6 x 12e-6 x 20 = 10.13 kN ("about
  // 10 kN on a Ø16"); the fundamental combination 1.0 P0 + 1.5 N_T on the rod and the thread.
  CHECK_CLOSE(r.thermal_force, 10133.5, rel_tol(1e-5));
  t.pretension = 12e3;
  const auto rows = assess::tie_checks(t, assess::TieDemand{});
  int found = 0;
  for (const auto& row : rows) {
    if (row.check == "temperature rod") {
      ++found;
      CHECK_CLOSE(row.demand, 12e3 + 1.5 * r.thermal_force, rel_tol(1e-12));
      CHECK_CLOSE(row.capacity, r.rod, rel_tol(1e-12));
    }
    if (row.check == "temperature thread") {
      ++found;
      CHECK_CLOSE(row.capacity, r.thread, rel_tol(1e-12));
    }
    if (row.check == "pretension") {  // a new tie: P0 = 12 kN >= 10.13 kN takes up the range
      ++found;
      CHECK(row.satisfied);
      CHECK_CLOSE(row.dc, r.thermal_force / 12e3, rel_tol(1e-12));
    }
  }
  CHECK(found == 3);
  // The pretension a new tie gets by default: E A alpha_T dT rounded up to 0.1 kN (15 K, A = 201.06 mm^2:
  // 7 600.1 N -> 7.7 kN; never below the force, or its own check would fail).
  t.delta_T = 15.0;
  CHECK_CLOSE(assess::thermal_pretension(t), 7700.0, rel_tol(1e-12));
  // An existing tie keeps its pretension: no pretension row.
  t.existing = true;
  for (const auto& row : assess::tie_checks(t, assess::TieDemand{})) CHECK(row.check != "pretension");
}

TEST_CASE("issue 37: the elongation a ductile rod delivers: 0.9 x the uniform elongation, over its free length") {
  // Upset ends M22 on a Ø16 S275, the masonry strong (far from the crown): ductile; eps_ud = 0.9 x 15 x 275 /
  // 210 000 = 1.768 %, e_u = eps_ud L = 0.2121 m on 12 m.
  assess::Tie t = tie(0.35, 0.35, 0.65, 10.0, 14.57, 0.2e6, 1.35, 4, 12.0);
  t.rod.eps_uk = assess::tie_catalogue::find_grade("S275")->eps_uk;
  t.rod.ends = assess::TieEnds::Upset;
  t.rod.thread_diameter = 0.022;
  t.rod.thread_area = 303e-6;
  t.rod.nut_width = 0.034;
  const auto r = assess::tie_resistance(t);
  REQUIRE(r.ductile);
  CHECK_CLOSE(r.eps_ud, 0.9 * 15.0 * 275e6 / 210e9, rel_tol(1e-12));
  CHECK_CLOSE(r.ultimate_elongation, r.eps_ud * 12.0, rel_tol(1e-12));
  // The same rod threaded on itself: never ductile, whatever the masonry (no elongation credited).
  t.rod.ends = assess::TieEnds::Threaded;
  t.rod.thread_diameter = 0.016;
  t.rod.thread_area = 157e-6;
  t.rod.nut_width = 0.024;
  const auto rt = assess::tie_resistance(t);
  CHECK_FALSE(rt.ductile);
  CHECK(rt.eps_ud == 0.0);
  CHECK_CLOSE(rt.ultimate_elongation, rt.yield_elongation, rel_tol(0.0));
  // B450C: (Agt)k = 7.5 %, eps_ud = 6.75 %.
  CHECK_CLOSE(assess::tie_catalogue::eps_ud_over_eps_uk * assess::tie_catalogue::find_grade("B450C")->eps_uk, 0.0675,
              rel_tol(1e-12));
}
