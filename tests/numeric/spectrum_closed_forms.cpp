// NTC 2018 §3.2.3.2 elastic spectra: closed forms and the soil table of
// ntc.md §6b (computed there independently with g = 9.81 m/s^2).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/support/error.hpp>
#include <assess/hazard/spectrum.hpp>
#include <assess/support/units.hpp>

#include <cmath>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

// Closed forms are exact up to round-off in double precision.
constexpr double tol_closed_rel = 1e-12;
// ntc.md §6b prints 5 decimals: half a unit of the last digit (g, s, m, -).
constexpr double tol_table_g = 0.6e-5;
constexpr double tol_table_s = 0.6e-5;
constexpr double tol_table_m = 0.6e-5;
constexpr double tol_table_factor = 0.6e-5;

namespace {
const HazardParams laquila_slv{474.5611, 0.26066, 2.36350, 0.34649};
double g_units(double a) { return a / units::g; }
}  // namespace

TEST_CASE("Se(0) = ag*S, plateau = ag*S*eta*F0, and continuity at TB, TC, TD") {
  for (SoilClass soil : {SoilClass::A, SoilClass::B, SoilClass::C, SoilClass::D, SoilClass::E}) {
    for (double xi : {2.0, 5.0, 8.0, 10.0, 20.0}) {
      CAPTURE(to_string(soil));
      CAPTURE(xi);
      const ElasticSpectrum s(laquila_slv, {soil, Topography::T2, 0.5}, xi);
      CHECK_CLOSE(s.Se(0.0), s.ag() * s.S(), rel_tol(tol_closed_rel));
      const double plateau = s.ag() * s.S() * s.eta() * s.F0();
      CHECK_CLOSE(s.Se(0.5 * (s.TB() + s.TC())), plateau, rel_tol(tol_closed_rel));
      for (double t : {s.TB(), s.TC(), s.TD()}) {
        const double h = 1e-9 * t;  // s
        CHECK_CLOSE(s.Se(t - h), s.Se(t + h), rel_tol(1e-8));
      }
      CHECK_CLOSE(s.Se(s.TD() * 1.5), plateau * s.TC() * s.TD() / std::pow(1.5 * s.TD(), 2),
                  rel_tol(tol_closed_rel));
    }
  }
}

TEST_CASE("eta(5 %) = 1, eta follows sqrt(10/(5+xi)) and is floored at 0.55") {
  CHECK(damping_factor(5.0) == 1.0);
  CHECK_CLOSE(damping_factor(8.0), std::sqrt(10.0 / 13.0), rel_tol(tol_closed_rel));
  CHECK_CLOSE(damping_factor(0.0), std::sqrt(2.0), rel_tol(tol_closed_rel));
  // sqrt(10/(5+xi)) = 0.55 at xi = 28.06 %.
  CHECK(damping_factor(28.0) > 0.55);
  CHECK(damping_factor(30.0) == 0.55);
  CHECK(damping_factor(100.0) == 0.55);
  CHECK_THROWS_AS(damping_factor(-1.0), InputError);
}

TEST_CASE("soil table of ntc.md 6b (L'Aquila SLV, T1, 5 %)") {
  struct Row {
    SoilClass soil;
    double SS, CC, TB, TC, TD, Se0, plateau, Se05, Se10, SDe10, SDe30;
  };
  const Row rows[] = {
      {SoilClass::A, 1.00000, 1.00000, 0.11550, 0.34649, 2.64264, 0.26066, 0.61607, 0.42692, 0.21346, 0.05304,
       0.14017},
      {SoilClass::B, 1.15357, 1.35974, 0.15704, 0.47113, 2.64264, 0.30069, 0.71068, 0.66965, 0.33483, 0.08320,
       0.21987},
      {SoilClass::C, 1.33036, 1.48967, 0.17205, 0.51616, 2.64264, 0.34677, 0.81959, 0.81959, 0.42304, 0.10512,
       0.27780},
  };
  for (const Row& r : rows) {
    CAPTURE(to_string(r.soil));
    const ElasticSpectrum s(laquila_slv, {r.soil, Topography::T1, 1.0}, 5.0);
    CHECK_CLOSE(s.SS(), r.SS, abs_tol(tol_table_factor));
    CHECK_CLOSE(s.CC(), r.CC, abs_tol(tol_table_factor));
    CHECK_CLOSE(s.TB(), r.TB, abs_tol(tol_table_s));
    CHECK_CLOSE(s.TC(), r.TC, abs_tol(tol_table_s));
    CHECK_CLOSE(s.TD(), r.TD, abs_tol(tol_table_s));
    CHECK_CLOSE(g_units(s.Se(0.0)), r.Se0, abs_tol(tol_table_g));
    CHECK_CLOSE(g_units(s.Se(0.5 * (s.TB() + s.TC()))), r.plateau, abs_tol(tol_table_g));
    CHECK_CLOSE(g_units(s.Se(0.5)), r.Se05, abs_tol(tol_table_g));
    CHECK_CLOSE(g_units(s.Se(1.0)), r.Se10, abs_tol(tol_table_g));
    CHECK_CLOSE(s.SDe(1.0), r.SDe10, abs_tol(tol_table_m));
    CHECK_CLOSE(s.SDe(3.0), r.SDe30, abs_tol(tol_table_m));
  }
  // Soil B with xi = 8 %: eta = 0.87706, Se(1.0) = 0.29366 g.
  const ElasticSpectrum b8(laquila_slv, {SoilClass::B, Topography::T1, 1.0}, 8.0);
  CHECK_CLOSE(b8.eta(), 0.87706, abs_tol(tol_table_factor));
  CHECK_CLOSE(g_units(b8.Se(1.0)), 0.29366, abs_tol(tol_table_g));
}

TEST_CASE("SS and CC clamps of Tab. 3.2.IV, ST of Tab. 3.2.V with h/H") {
  // Very low ag: SS at its upper bound; very high ag: at its lower bound.
  CHECK(soil_factor_SS(SoilClass::B, 0.01, 2.5) == 1.20);
  CHECK(soil_factor_SS(SoilClass::C, 0.01, 2.5) == 1.50);
  CHECK(soil_factor_SS(SoilClass::D, 0.01, 2.5) == 1.80);
  CHECK(soil_factor_SS(SoilClass::E, 0.01, 2.5) == 1.60);
  CHECK(soil_factor_SS(SoilClass::B, 0.6, 3.0) == 1.00);
  CHECK(soil_factor_SS(SoilClass::D, 0.6, 3.0) == 0.90);
  CHECK_CLOSE(soil_factor_SS(SoilClass::D, 0.2, 2.5), 2.40 - 1.50 * 0.5, rel_tol(tol_closed_rel));
  CHECK_CLOSE(soil_factor_CC(SoilClass::D, 0.25), 1.25 * 2.0, rel_tol(tol_closed_rel));
  CHECK_CLOSE(soil_factor_CC(SoilClass::E, 0.3), 1.15 * std::pow(0.3, -0.4), rel_tol(tol_closed_rel));
  CHECK(topographic_factor(Topography::T1, 1.0) == 1.0);
  CHECK(topographic_factor(Topography::T2, 1.0) == doctest::Approx(1.2).epsilon(1e-15));
  CHECK(topographic_factor(Topography::T4, 1.0) == doctest::Approx(1.4).epsilon(1e-15));
  CHECK(topographic_factor(Topography::T4, 0.5) == doctest::Approx(1.2).epsilon(1e-15));
  CHECK(topographic_factor(Topography::T3, 0.0) == 1.0);
  CHECK_THROWS_AS(topographic_factor(Topography::T3, 1.5), InputError);
}

TEST_CASE("SDe follows [3.2.10] up to TE, the linear [3.2.11] to TF, then dg") {
  const ElasticSpectrum s(laquila_slv, {SoilClass::C, Topography::T1, 1.0}, 5.0);
  const double dg = 0.025 * s.ag() * s.S() * s.TC() * s.TD();  // [3.2.12]
  CHECK(s.TE() == 6.0);
  CHECK(s.TF() == 10.0);
  CHECK_CLOSE(s.SDe(2.0), s.Se(2.0) * std::pow(2.0 / (2 * units::pi), 2), rel_tol(tol_closed_rel));
  CHECK_CLOSE(s.SDe(s.TF()), dg, rel_tol(tol_closed_rel));
  CHECK_CLOSE(s.SDe(12.0), dg, rel_tol(tol_closed_rel));
  CHECK_CLOSE(s.SDe(s.TE() + 1e-12), dg * s.F0() * s.eta(), rel_tol(1e-9));
  CHECK_CLOSE(s.SDe(8.0), dg * (s.F0() + (1 - s.F0()) * 0.5), rel_tol(tol_closed_rel));
}

TEST_CASE("vertical spectrum [3.2.8]-[3.2.9] and design spectrum with q") {
  const ElasticSpectrum s(laquila_slv, {SoilClass::B, Topography::T1, 1.0}, 5.0);
  const double Fv = 1.35 * 2.36350 * std::sqrt(0.26066);
  CHECK_CLOSE(s.Fv(), Fv, rel_tol(tol_closed_rel));
  CHECK_CLOSE(s.Sve(0.1), s.ag() * Fv, rel_tol(tol_closed_rel));  // plateau, SS = 1, ST = 1
  CHECK_CLOSE(s.Sve(0.5), s.ag() * Fv * 0.15 / 0.5, rel_tol(tol_closed_rel));
  CHECK_CLOSE(s.Sve(2.0), s.ag() * Fv * 0.15 * 1.0 / 4.0, rel_tol(tol_closed_rel));
  // Design spectrum: plateau ag*S*F0/q; floor 0.2 ag at long periods.
  CHECK_CLOSE(s.Sd(0.3, 2.0), s.ag() * s.S() * s.F0() / 2.0, rel_tol(tol_closed_rel));
  CHECK_CLOSE(s.Sd(3.5, 4.0), 0.2 * s.ag(), rel_tol(tol_closed_rel));
  CHECK_THROWS_AS(s.Sd(0.3, 0.5), InputError);
  CHECK_THROWS_AS(s.Se(-0.1), InputError);
}
