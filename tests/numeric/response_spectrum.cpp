// Exact SDOF response (Nigam & Jennings 1969) against closed forms, an
// independent fine-step RK4 integration and the limits T -> 0, T -> infinity.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/records/record_io.hpp>

#include "assess/support/error.hpp"
#include "assess/records/record.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <tuple>
#include <fstream>
#include <sstream>
#include <string>

using assess::Record;
using assess::test::abs_tol;
using assess::test::rel_tol;
namespace units = assess::units;

namespace {

// Recurrence coefficients vs Chopra's closed forms: both are exact, they
// differ only by round-off of the closed forms at moderate w*h (-).
constexpr double kCoeffRelTol = 1e-10;
// Exact recurrence vs closed-form response to a constant step (piecewise
// linear excitation is then exact), relative to the static displacement p/w^2.
constexpr double kStepRelTol = 1e-11;
// Peak of u between samples by Hermite refinement: error O((w h)^4), with
// 20 steps per period w h <= 0.31; measured <= 2e-5 on El Centro (-).
constexpr double kPeakRelTol = 1e-4;
// Harmonic excitation sampled at dt = 0.0005 s: the piecewise-linear record
// differs from the sine by <= (Omega dt)^2 / 8 ~ 5e-6 of its amplitude (-).
constexpr double kHarmonicRelTol = 2e-5;
// PSA(T = 1 ms) vs PGA for a record with content below 5 Hz: rigid-limit
// error ~ (T/Tg)^2 ~ 4e-5 (-).
constexpr double kRigidRelTol = 1e-3;
// SD(T = 1e4 s) vs max ground displacement over 10 s: the correction is
// ~ (w t)^2 / 2 ~ 2e-5 (-).
constexpr double kFlexibleRelTol = 1e-3;
// Linearity in the record scale: round-off only (-).
constexpr double kLinearityRelTol = 1e-12;
// Recurrence vs RK4 with h = dt/1000: RK4 truncation (w h)^4 ~ 1e-13 per
// step; round-off over 1e5-1e6 steps dominates (m, relative to max|u|).
constexpr double kRk4RelTol = 1e-8;

Record make_record(double dt, std::vector<double> acc, std::string name = "synthetic") {
  Record r;
  r.name = std::move(name);
  r.dt = dt;
  r.acc = std::move(acc);
  return r;
}

// A deterministic broadband-ish record: sum of three sines under an envelope.
Record synthetic_record(double dt, double duration) {
  std::vector<double> a;
  for (double t = 0.0; t <= duration + 1e-12; t += dt) {
    const double env = std::sin(units::pi * t / duration);
    a.push_back(env * (2.0 * std::sin(2 * units::pi * 1.3 * t) + 1.2 * std::sin(2 * units::pi * 3.1 * t + 0.4) +
                       0.7 * std::sin(2 * units::pi * 0.45 * t + 1.1)));
  }
  return make_record(dt, a);
}

// Chopra, Dynamics of Structures (4th ed.), Tab. 5.2.1, with k = w^2, m = 1.
assess::SdofRecurrence chopra_coefficients(double T, double xi, double dt) {
  const double w = 2 * units::pi / T, k = w * w;
  const double sq = std::sqrt(1 - xi * xi), wD = w * sq;
  const double e = std::exp(-xi * w * dt), s = std::sin(wD * dt), c = std::cos(wD * dt);
  assess::SdofRecurrence r;
  r.a_uu = e * (xi / sq * s + c);
  r.a_uv = e * s / wD;
  r.a_up0 = (2 * xi / (w * dt) + e * (((1 - 2 * xi * xi) / (wD * dt) - xi / sq) * s - (1 + 2 * xi / (w * dt)) * c)) / k;
  r.a_up1 = (1 - 2 * xi / (w * dt) + e * ((2 * xi * xi - 1) / (wD * dt) * s + 2 * xi / (w * dt) * c)) / k;
  r.a_vu = -e * (w / sq * s);
  r.a_vv = e * (c - xi / sq * s);
  r.a_vp0 = (-1 / dt + e * ((w / sq + xi / (dt * sq)) * s + c / dt)) / k;
  r.a_vp1 = (1 - e * (xi / sq * s + c)) / (k * dt);
  return r;
}

// Independent check: classical RK4 on u'' = p(t) - 2 xi w u' - w^2 u with the
// piecewise-linear p, n_sub RK4 steps per record step: u at the samples and
// max|u| over every RK4 step.
struct Rk4Result {
  std::vector<double> u;
  double peak = 0.0;
};
Rk4Result rk4_response(const Record& r, double T, double xi, int n_sub) {
  const double w = 2 * units::pi / T;
  Rk4Result out;
  out.u.assign(r.size(), 0.0);
  double u = 0.0, v = 0.0;
  const double h = r.dt / n_sub;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    const double p0 = -r.acc[i], p1 = -r.acc[i + 1];
    auto p = [&](double s) { return p0 + (p1 - p0) * s / r.dt; };  // s in [0, dt]
    auto f = [&](double s, double uu, double vv) { return p(s) - 2 * xi * w * vv - w * w * uu; };
    for (int k = 0; k < n_sub; ++k) {
      const double s = k * h;
      const double k1u = v, k1v = f(s, u, v);
      const double k2u = v + 0.5 * h * k1v, k2v = f(s + 0.5 * h, u + 0.5 * h * k1u, v + 0.5 * h * k1v);
      const double k3u = v + 0.5 * h * k2v, k3v = f(s + 0.5 * h, u + 0.5 * h * k2u, v + 0.5 * h * k2v);
      const double k4u = v + h * k3v, k4v = f(s + h, u + h * k3u, v + h * k3v);
      u += h / 6 * (k1u + 2 * k2u + 2 * k3u + k4u);
      v += h / 6 * (k1v + 2 * k2v + 2 * k3v + k4v);
      out.peak = std::max(out.peak, std::fabs(u));
    }
    out.u[i + 1] = u;
  }
  return out;
}


}  // namespace

TEST_CASE("recurrence coefficients equal Chopra's closed forms (Tab. 5.2.1)") {
  // Named variables, not a structured binding: doctest's CAPTURE and the
  // lambdas below capture them, which C++17 (clang 14) forbids for bindings.
  for (const auto& c : {std::tuple{0.5, 0.05, 0.01}, {1.0, 0.2, 0.02}, {0.1, 0.02, 0.005}, {2.0, 0.0001, 0.01}}) {
    const double T = std::get<0>(c), xi = std::get<1>(c), dt = std::get<2>(c);
    CAPTURE(T);
    CAPTURE(xi);
    const auto a = assess::sdof_recurrence(T, xi, dt);
    const auto b = chopra_coefficients(T, xi, dt);
    CHECK_CLOSE(a.a_uu, b.a_uu, rel_tol(kCoeffRelTol));
    CHECK_CLOSE(a.a_uv, b.a_uv, rel_tol(kCoeffRelTol));
    CHECK_CLOSE(a.a_up0, b.a_up0, rel_tol(kCoeffRelTol));
    CHECK_CLOSE(a.a_up1, b.a_up1, rel_tol(kCoeffRelTol));
    CHECK_CLOSE(a.a_vu, b.a_vu, rel_tol(kCoeffRelTol));
    CHECK_CLOSE(a.a_vv, b.a_vv, rel_tol(kCoeffRelTol));
    CHECK_CLOSE(a.a_vp0, b.a_vp0, rel_tol(kCoeffRelTol));
    CHECK_CLOSE(a.a_vp1, b.a_vp1, rel_tol(kCoeffRelTol));
  }
}

TEST_CASE("recurrence stays exact for w*h -> 0: load coefficients tend to h^2/3 and h^2/6") {
  // Taylor expansion of the exact propagator: a_up0 = h^2/3 + O(h^3 w xi),
  // a_up1 = h^2/6 + O(...); at T = 1e5 s, h = 0.01 s, w h = 6e-7.
  const double h = 0.01;
  const auto c = assess::sdof_recurrence(1e5, 0.05, h);
  CHECK_CLOSE(c.a_up0, h * h / 3, rel_tol(1e-6));
  CHECK_CLOSE(c.a_up1, h * h / 6, rel_tol(1e-6));
  CHECK_CLOSE(c.a_uv, h, rel_tol(1e-6));
  CHECK_CLOSE(c.a_vp0, h / 2, rel_tol(1e-6));
}

TEST_CASE("response to a constant acceleration step equals the closed form") {
  // u'' + 2 xi w u' + w^2 u = -a0 from rest (Chopra eq. 4.3.2 / 4.3.3):
  // u = -(a0/w^2) [1 - e^{-xi w t} (cos wD t + xi/sqrt(1-xi^2) sin wD t)]
  const double a0 = 1.7, dt = 0.01, T = 0.37;
  const Record r = make_record(dt, std::vector<double>(801, a0));
  const double w = 2 * units::pi / T, ust = a0 / (w * w);
  for (double xi : {0.0, 0.05, 0.3}) {
    CAPTURE(xi);
    const auto hist = assess::sdof_response(r, T, xi);
    const double sq = std::sqrt(1 - xi * xi), wD = w * sq;
    double err = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      const double t = i * dt;
      const double exact = -ust * (1 - std::exp(-xi * w * t) * (std::cos(wD * t) + xi / sq * std::sin(wD * t)));
      err = std::max(err, std::fabs(hist.u[i] - exact));
    }
    CHECK_CLOSE(err / ust, 0.0, abs_tol(kStepRelTol));
    // Peak: 1 + exp(-xi pi / sqrt(1 - xi^2)) times the static value, at
    // t = T_D/2 = 0.185 s (between samples: tests the Hermite refinement).
    const auto so = assess::spectral_ordinates(r, T, {xi, 20});
    CHECK_CLOSE(so.SD, ust * (1 + std::exp(-xi * units::pi / sq)), rel_tol(kPeakRelTol));
    CHECK_CLOSE(so.PSA, w * w * so.SD, rel_tol(1e-15));
  }
}

TEST_CASE("response to harmonic excitation equals the full analytical solution") {
  // u'' + 2 xi w u' + w^2 u = p0 sin(W t), p0 = -A, from rest (Chopra §3.2).
  const double A = 2.0, W = 2 * units::pi * 1.5, dt = 0.0005, dur = 12.0;
  std::vector<double> acc;
  for (double t = 0; t <= dur + 1e-12; t += dt) acc.push_back(A * std::sin(W * t));
  const Record r = make_record(dt, acc);
  for (const auto& c : {std::pair{0.5, 0.05}, {1.0 / 1.5, 0.05}, {1.2, 0.1}}) {
    const double T = c.first, xi = c.second;
    CAPTURE(T);
    CAPTURE(xi);
    const double w = 2 * units::pi / T, beta = W / w, p0 = -A;
    const double den = std::pow(1 - beta * beta, 2) + std::pow(2 * xi * beta, 2);
    const double C = p0 / (w * w) * (1 - beta * beta) / den, D = p0 / (w * w) * (-2 * xi * beta) / den;
    const double wD = w * std::sqrt(1 - xi * xi);
    const double A1 = -D, B1 = (xi * w * A1 - C * W) / wD;
    auto exact = [&](double t) {
      return std::exp(-xi * w * t) * (A1 * std::cos(wD * t) + B1 * std::sin(wD * t)) + C * std::sin(W * t) +
             D * std::cos(W * t);
    };
    const auto hist = assess::sdof_response(r, T, xi);
    double err = 0.0, peak = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) {
      err = std::max(err, std::fabs(hist.u[i] - exact(i * dt)));
      peak = std::max(peak, std::fabs(exact(i * dt)));
    }
    CHECK_CLOSE(err / peak, 0.0, abs_tol(kHarmonicRelTol));
    CHECK_CLOSE(assess::spectral_ordinates(r, T, {xi, 20}).SD, peak, rel_tol(kHarmonicRelTol));
    // Steady state amplitude |p0|/w^2 / sqrt(den) is reached at the end.
    double tail = 0.0;
    for (std::size_t i = r.size() - 2000; i < r.size(); ++i) tail = std::max(tail, std::fabs(hist.u[i]));
    // The transient decays as exp(-xi w t); its initial amplitude is at most
    // beta = 1.8 times the steady one here, hence the factor 2.
    CHECK_CLOSE(tail, A / (w * w) / std::sqrt(den),
                rel_tol(2.0 * std::exp(-xi * w * (dur - 1.0)) + kHarmonicRelTol));
  }
}

TEST_CASE("T -> 0: PSA tends to PGA, exactly at T = 0") {
  const Record r = synthetic_record(0.01, 10.0);
  const auto s0 = assess::spectral_ordinates(r, 0.0);
  CHECK(s0.PSA == r.pga());
  CHECK(s0.SA == r.pga());
  CHECK(s0.SD == 0.0);
  const auto s1 = assess::spectral_ordinates(r, 0.001);
  CHECK_CLOSE(s1.PSA, r.pga(), rel_tol(kRigidRelTol));
  CHECK_CLOSE(s1.SA, r.pga(), rel_tol(kRigidRelTol));
}

TEST_CASE("T -> infinity: SD tends to the peak ground displacement, no NaN") {
  const Record r = synthetic_record(0.01, 10.0);
  // Exact double integration of the piecewise-linear acceleration.
  double vg = 0, dg = 0, dmax = 0;
  for (std::size_t i = 0; i + 1 < r.size(); ++i) {
    dg += vg * r.dt + (2 * r.acc[i] + r.acc[i + 1]) * r.dt * r.dt / 6;
    vg += 0.5 * (r.acc[i] + r.acc[i + 1]) * r.dt;
    dmax = std::max(dmax, std::fabs(dg));
  }
  CHECK_CLOSE(assess::spectral_ordinates(r, 1e4).SD, dmax, rel_tol(kFlexibleRelTol));
  for (double T : {1e6, 1e9}) {
    const auto s = assess::spectral_ordinates(r, T);
    CHECK(std::isfinite(s.SD));
    CHECK(std::isfinite(s.PSA));
    CHECK(std::isfinite(s.SA));
  }
}

TEST_CASE("the spectrum is linear in the record scale") {
  const Record r = synthetic_record(0.005, 8.0);
  const auto periods = assess::log_spaced_periods(0.05, 4.0, 12);
  const auto a = assess::response_spectrum(r, periods);
  const auto b = assess::response_spectrum(r.scaled(-2.5), periods);
  for (std::size_t i = 0; i < periods.size(); ++i) {
    CHECK_CLOSE(b.ordinates[i].PSA, 2.5 * a.ordinates[i].PSA, rel_tol(kLinearityRelTol));
    CHECK_CLOSE(b.ordinates[i].SV, 2.5 * a.ordinates[i].SV, rel_tol(kLinearityRelTol));
  }
}

TEST_CASE("exact recurrence agrees with a fine-step RK4 integration") {
  // A short irregular record: values change sign and slope every sample.
  std::vector<double> acc;
  for (int i = 0; i < 300; ++i) acc.push_back(3.0 * std::sin(0.37 * i * i) + std::cos(1.9 * i));
  const Record r = make_record(0.01, acc);
  for (const auto& c : {std::pair{0.3, 0.05}, {0.05, 0.02}, {2.0, 0.1}}) {
    const double T = c.first, xi = c.second;
    CAPTURE(T);
    const auto hist = assess::sdof_response(r, T, xi);
    const auto ref = rk4_response(r, T, xi, 1000);
    double err = 0.0;
    for (std::size_t i = 0; i < r.size(); ++i) err = std::max(err, std::fabs(hist.u[i] - ref.u[i]));
    CHECK_CLOSE(err / ref.peak, 0.0, abs_tol(kRk4RelTol));
  }
}

TEST_CASE("El Centro 1940 NS: peak of the exact response equals the fine RK4 peak") {
  const Record r = assess::read_record(std::string(ASSESS_TEST_DATA_DIR) + "/spectra/records/elCentro.AT2");
  CHECK_CLOSE(r.pga() / units::g_n, 0.319, abs_tol(0.0005));  // README: 0.319 g
  for (double T : {0.1, 0.5, 2.0}) {
    CAPTURE(T);
    // RK4 with 400 sub-steps (h = 5e-5 s): its max over the steps is within
    // (pi h / T)^2 / 2 <= 1.3e-6 of the true peak.
    const double ref = rk4_response(r, T, 0.05, 400).peak;
    CHECK_CLOSE(assess::spectral_ordinates(r, T).SD, ref, rel_tol(kPeakRelTol));
  }
}

TEST_CASE("invalid input throws InputError") {
  const Record r = synthetic_record(0.01, 1.0);
  CHECK_THROWS_AS(assess::spectral_ordinates(r, -0.1), assess::InputError);
  CHECK_THROWS_AS(assess::spectral_ordinates(r, 1.0, {-0.05, 10}), assess::InputError);
  CHECK_THROWS_AS(assess::spectral_ordinates(make_record(0.0, {1.0, 2.0}), 1.0), assess::InputError);
  CHECK_THROWS_AS(assess::spectral_ordinates(make_record(0.01, {1.0, NAN}), 1.0), assess::InputError);
  CHECK_THROWS_AS(assess::log_spaced_periods(1.0, 0.5, 10), assess::InputError);
}
