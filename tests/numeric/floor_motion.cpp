// First-mode floor-motion filter a_Z = ug'' + gamma psi ur'' (Circ. 2019
// §C7.2.3 model; docs/theory/chain-dynamics.md §4) against the closed-form
// steady state of a linear oscillator under a harmonic ground acceleration:
//   ur'' = A r^2 / (1 - r^2 + 2 i xi r) e^{i w t}, r = w / w1,
//   |a_Z| = A |1 + gamma psi r^2 / (1 - r^2 + 2 i xi r)|,
// at resonance (r = 1) A sqrt(1 + (gamma psi)^2 / (4 xi^2)); with gamma psi = 1
// that is the transmissibility sqrt(1 + 4 xi^2) / (2 xi) behind [C7.2.7]'s
// factor sqrt(1 + 0.0004 xi%^2).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/records/floor_motion.hpp>
#include <assess/support/units.hpp>

#include <algorithm>
#include <cmath>
#include <complex>

using namespace assess;
using assess::test::rel_tol;

namespace {

// Steady-state amplitude (relative): the sampled sine is piecewise linear
// (fundamental amplitude 1 - (w dt)^2/12 ~ 1.3e-5 low at dt = 1 ms, T = 0.5 s)
// and the peak is read at the samples ((w dt)^2/2 ~ 8e-5 low): 2e-4.
constexpr double kAmplitudeTol = 2e-4;

Record harmonic(double A, double T, double dt, double duration) {
  Record r;
  r.name = "harmonic";
  r.dt = dt;
  const std::size_t n = std::size_t(duration / dt) + 1;
  for (std::size_t i = 0; i < n; ++i) r.acc.push_back(A * std::sin(2 * units::pi / T * double(i) * dt));
  return r;
}

double steady_peak(const Record& r, double last_s) {
  double m = 0.0;
  const std::size_t from = r.acc.size() - std::size_t(last_s / r.dt);
  for (std::size_t i = from; i < r.acc.size(); ++i) m = std::max(m, std::fabs(r.acc[i]));
  return m;
}

}  // namespace

TEST_CASE("floor filter: resonance amplification of a linear oscillator against its closed form") {
  const double T1 = 0.5, A = 1.0;
  for (double xi : {0.05, 0.02}) {
    for (double gp : {1.0, 1.2}) {
      CAPTURE(xi);
      CAPTURE(gp);
      // 40 s: transients decay as exp(-xi w1 t) < 1e-10 for xi = 5 % ... use 90 s for 2 %.
      const Record g = harmonic(A, T1, 1e-3, xi < 0.04 ? 90.0 : 40.0);
      const Record z = floor_motion(g, FloorFilter{T1, xi, gp});
      const double expected = A * std::sqrt(1.0 + gp * gp / (4 * xi * xi));
      MESSAGE("xi " << xi << ", gamma psi " << gp << ": steady peak " << steady_peak(z, 2.0) << ", closed form "
                    << expected);
      CHECK_CLOSE(steady_peak(z, 2.0), expected, rel_tol(kAmplitudeTol));
    }
  }
}

TEST_CASE("floor filter: off-resonance steady state and the relative acceleration alone") {
  const double T1 = 0.4, xi = 0.05, gp = 1.3;
  for (double r : {0.5, 2.0}) {
    CAPTURE(r);
    const double T = T1 / r;
    const Record g = harmonic(1.0, T, 5e-4, 40.0);
    const std::complex<double> H = r * r / std::complex<double>(1 - r * r, 2 * xi * r);
    const Record z = floor_motion(g, FloorFilter{T1, xi, gp});
    CHECK_CLOSE(steady_peak(z, 2.0), std::abs(1.0 + gp * H), rel_tol(kAmplitudeTol));
    Record ur = g;
    ur.acc = oscillator_relative_acceleration(g, T1, xi);
    CHECK_CLOSE(steady_peak(ur, 2.0), std::abs(H), rel_tol(kAmplitudeTol));
  }
  // gamma psi = 0 (the ground floor): the floor motion is the ground motion.
  const Record g = harmonic(2.0, 0.3, 1e-3, 2.0);
  const Record z = floor_motion(g, FloorFilter{T1, xi, 0.0});
  CHECK(z.acc == g.acc);
}

TEST_CASE("floor filter: bad parameters name the field and unit") {
  const Record g = harmonic(1.0, 0.3, 1e-2, 1.0);
  CHECK_THROWS_WITH(floor_motion(g, FloorFilter{0.0, 0.05, 1.0}), doctest::Contains("T1 must be > 0 s"));
  CHECK_THROWS_WITH(floor_motion(g, FloorFilter{0.5, 1.5, 1.0}), doctest::Contains("damping ratio"));
  CHECK_THROWS_WITH(floor_motion(g, FloorFilter{0.5, 0.05, -1.0}), doctest::Contains("gamma psi"));
}
