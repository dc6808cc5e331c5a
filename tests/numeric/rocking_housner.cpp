// Rigid (Housner) block in free rocking: period, impact times and velocities,
// amplitude decay by the energy law, energy conservation with e = 1, Zeno rest.
// Reference block A of rocking.md §2: b = 0.2 m, h = 1.0 m (thickness 0.4 m,
// height 2.0 m), g = 9.81 m/s^2; the unit weight does not enter the motion.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/dynamics/rocking_analysis.hpp>
#include <assess/support/units.hpp>

#include <cmath>
#include <vector>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

// Times (s): the references are given to 6 decimals (rocking.md §2.1-2.2).
constexpr double kTimeTol = 2e-6;
// Angular velocities (rad/s): 6 decimals in rocking.md §2.2.
constexpr double kOmegaTol = 2e-6;
// Amplitude ratios theta_n/alpha: 6 decimals in rocking.md §2.2.
constexpr double kPhiTol = 2e-6;
// Energy conservation with e = 1: relative drift of |omega-| over 10 impacts,
// set by the integration tolerances (1e-12) used here.
constexpr double kEnergyRelTol = 1e-8;
// Rotation of the state just past a located impact (rad): event_time_tol (1e-12 s) x |omega| (< 1 rad/s).
constexpr double kThetaEventTol = 1e-12;

const RockingBody kBlockA = RockingBody::rectangle(0.4, 2.0, 18.0 * units::kN);

RockingOptions tight() {
  RockingOptions o;
  o.rel_tol = 1e-12;
  o.abs_tol = 1e-14;
  o.record_history = true;
  return o;
}

struct Impact {
  double t, omega_minus, omega_plus;
};

// Impacts are the history rows that repeat a time (state before, after).
std::vector<Impact> impacts(const RockingResult& r) {
  std::vector<Impact> out;
  const auto& h = r.history;
  for (std::size_t i = 1; i < h.t.size(); ++i)
    if (h.t[i] == h.t[i - 1] && h.theta[i] == 0.0) out.push_back({h.t[i], h.omega[i - 1], h.omega[i]});
  return out;
}

}  // namespace

TEST_CASE("block A constants match rocking.md §2") {
  CHECK_CLOSE(kBlockA.alpha, 0.197396, abs_tol(1e-6));
  CHECK_CLOSE(kBlockA.p(), 2.686005, abs_tol(1e-6));
  const RockingModel m(kBlockA, Foundation::rigid(), Sidedness::two_sided, Restitution::housner());
  CHECK_CLOSE(m.restitution(), 0.942308, abs_tol(1e-6));
  CHECK_CLOSE(m.restitution(), 1.0 - 1.5 * std::pow(std::sin(kBlockA.alpha), 2), abs_tol(1e-15));
  CHECK_CLOSE(m.theta_u(), kBlockA.alpha, abs_tol(1e-15));
  CHECK_CLOSE(m.capacity() / kBlockA.W, 0.019804, abs_tol(1e-6));  // R (1 - cos alpha), m
  const RockingModel os(kBlockA, Foundation::rigid(), Sidedness::one_sided, Restitution::one_sided_theory());
  CHECK_CLOSE(os.restitution(), -0.442308, abs_tol(1e-6));
}

TEST_CASE("free rocking period from theta0 = 0.5 alpha is 1.963458 s (full nonlinear equation)") {
  const RockingModel m(kBlockA, Foundation::rigid(), Sidedness::two_sided, Restitution::given(1.0));
  const RockingResult r = analyse_free(m, {0.5 * kBlockA.alpha, 0.0}, 4.5, tight());
  const auto imp = impacts(r);
  REQUIRE(imp.size() >= 4);
  CHECK_CLOSE(imp[0].t, 1.963458 / 4, abs_tol(kTimeTol));
  CHECK_CLOSE(2.0 * (imp[1].t - imp[0].t), 1.963458, abs_tol(kTimeTol));
  CHECK_CLOSE(imp[3].t - imp[1].t, 1.963458, abs_tol(kTimeTol));
}

TEST_CASE("impact times and pre-impact velocities with Housner e match rocking.md §2.2") {
  const RockingModel m(kBlockA, Foundation::rigid(), Sidedness::two_sided, Restitution::housner());
  const RockingResult r = analyse_free(m, {0.5 * kBlockA.alpha, 0.0}, 3.5, tight());
  const auto imp = impacts(r);
  REQUIRE(imp.size() == 5);
  const double t_ref[] = {0.490864, 1.344805, 2.104264, 2.788931, 3.411862};
  const double w_ref[] = {-0.458240, +0.431803, -0.406891, +0.383417, -0.361297};
  for (int i = 0; i < 5; ++i) {
    CHECK_CLOSE(imp[i].t, t_ref[i], abs_tol(kTimeTol));
    CHECK_CLOSE(imp[i].omega_minus, w_ref[i], abs_tol(kOmegaTol));
    CHECK_CLOSE(imp[i].omega_plus, m.restitution() * imp[i].omega_minus, abs_tol(1e-15));
  }
  CHECK(r.impacts == 5);
  CHECK_CLOSE(r.theta_max, 0.5 * kBlockA.alpha, abs_tol(1e-15));
}

TEST_CASE("amplitude after n impacts follows the energy law (rocking.md §2.2, nonlinear row)") {
  const RockingModel m(kBlockA, Foundation::rigid(), Sidedness::two_sided, Restitution::housner());
  const RockingResult r = analyse_free(m, {0.5 * kBlockA.alpha, 0.0}, 5.0, tight());
  const auto imp = impacts(r);
  REQUIRE(imp.size() >= 6);
  const double phi_ref[] = {0.422193, 0.360968, 0.311127, 0.269701, 0.234782, 0.205051};
  const double a = kBlockA.alpha;
  for (int n = 1; n <= 6; ++n) {
    // Closed form: cos(alpha - theta_n) - cos(alpha) = e^(2n) [cos(alpha - theta_0) - cos(alpha)]
    const double rhs = std::pow(m.restitution(), 2 * n) * (std::cos(0.5 * a) - std::cos(a));
    CHECK_CLOSE((a - std::acos(rhs + std::cos(a))) / a, phi_ref[n - 1], abs_tol(kPhiTol));
    // Integrated: restart from theta = 0 with the engine's post-impact velocity of impact n;
    // the first peak of that run is theta_n.
    const RockingResult rn = analyse_free(m, {0.0, imp[n - 1].omega_plus}, 0.6, tight());
    CHECK_CLOSE(rn.theta_max / a, phi_ref[n - 1], abs_tol(kPhiTol));
  }
}

TEST_CASE("with e = 1 the energy is conserved through impacts") {
  const RockingModel m(kBlockA, Foundation::rigid(), Sidedness::two_sided, Restitution::given(1.0));
  const RockingResult r = analyse_free(m, {0.5 * kBlockA.alpha, 0.0}, 10.0, tight());
  const auto imp = impacts(r);
  REQUIRE(imp.size() >= 10);
  // Energy at theta = 0 is kinetic only: |omega-| must stay that of the first impact,
  // and equal sqrt(2 W R (cos(alpha/2) - cos(alpha)) / I0) from the initial potential energy.
  const double w0 = std::sqrt(2.0 * kBlockA.W * kBlockA.R *
                              (std::cos(0.5 * kBlockA.alpha) - std::cos(kBlockA.alpha)) / kBlockA.I0);
  for (const auto& i : imp) CHECK_CLOSE(std::fabs(i.omega_minus), w0, rel_tol(kEnergyRelTol));
  CHECK_CLOSE(r.theta_max, 0.5 * kBlockA.alpha, rel_tol(kEnergyRelTol));
  CHECK(r.termination == RockingTermination::completed);
}

TEST_CASE("accumulating impacts (Zeno) end at rest before the linear accumulation time 12.2 s") {
  const RockingModel m(kBlockA, Foundation::rigid(), Sidedness::two_sided, Restitution::housner());
  RockingOptions o;
  o.record_history = true;
  const RockingResult r = analyse_free(m, {0.5 * kBlockA.alpha, 0.0}, 20.0, o);
  CHECK(r.termination == RockingTermination::completed);
  CHECK(r.t_end == doctest::Approx(20.0).epsilon(1e-12));
  // at rest: the last recorded state is theta = theta' = 0
  CHECK(r.history.theta.back() == 0.0);
  CHECK(r.history.omega.back() == 0.0);
  // impacts needed to bring |omega| from 0.458 rad/s below the rest velocity 1e-6 rad/s
  const double n_expected = std::log(o.rest_velocity / 0.458240) / std::log(m.restitution());
  CHECK(std::fabs(double(r.impacts) - n_expected) <= 2.0);
}

TEST_CASE("one-sided free rocking with e = -0.48 rebounds at the impact times of rocking.md §2.2") {
  const RockingModel m(kBlockA, Foundation::rigid(), Sidedness::one_sided, Restitution::given(-0.48));
  const RockingResult r = analyse_free(m, {0.5 * kBlockA.alpha, 0.0}, 1.1, tight());
  const auto imp = impacts(r);
  REQUIRE(imp.size() >= 4);
  const double t_ref[] = {0.490864, 0.821599, 0.972845, 1.044697};
  for (int i = 0; i < 4; ++i) {
    CHECK_CLOSE(imp[i].t, t_ref[i], abs_tol(kTimeTol));
    CHECK(imp[i].omega_plus > 0.0);  // rebound: theta >= 0 only
  }
  for (double th : r.history.theta) CHECK(th >= -kThetaEventTol);
  // peaks between the impacts: 0.090673, 0.020156, 0.004608 alpha (rebound from
  // theta = 0 with the engine's post-impact velocity)
  const double peaks[] = {0.090673, 0.020156, 0.004608};
  for (int n = 0; n < 3; ++n) {
    const RockingResult rn = analyse_free(m, {0.0, imp[n].omega_plus}, 0.3, tight());
    CHECK_CLOSE(rn.theta_max / kBlockA.alpha, peaks[n], abs_tol(kPhiTol));
  }
}
