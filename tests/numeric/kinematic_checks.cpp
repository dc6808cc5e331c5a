// Code checks of both editions: the free-standing 0.5 m x 6 m wall at
// L'Aquila (ntc.md §6b regression values, ground level) and a mechanism at
// height with every demand recomputed here from the formulas.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/kinematic/code_checks.hpp>
#include <assess/kinematic/code_rules.hpp>
#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>
#include <assess/support/units.hpp>

#include <cmath>

using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {
// §6b prints 5 decimals, some truncated (0.150345 g is printed 0.15034): one
// unit of the last digit (g, m).
constexpr double tol_printed = 1.0e-5;
// Demands recomputed from the same spectrum objects: round-off only.
constexpr double tol_formula = 1e-12;  // relative

const assess::HazardParams SLD{50.2890, 0.10416, 2.33202, 0.28109};
const assess::HazardParams SLV{474.5611, 0.26066, 2.36350, 0.34649};
const assess::HazardParams SLC{974.79, 0.33, 2.40, 0.36};  // illustrative

assess::KinematicResult wall_result() {
  assess::SimpleOverturningParams p;
  assess::Storey s;
  s.height = 6.0;
  s.thickness = 0.5;
  p.storeys = {s};
  p.unit_weight = 18000.0;
  p.hinge_level = 0;
  assess::KinematicOptions opt;
  opt.FC = 1.35;
  opt.curve_model = assess::CurveModel::Linearised;  // as in §6b
  return assess::analyse_kinematic(assess::simple_overturning(p).candidates[0].chain, opt);
}

const assess::CheckRow& find(const std::vector<assess::CheckRow>& rows, const char* code, const char* ls,
                             const char* kind, const char* loc) {
  for (const auto& r : rows)
    if (r.code == code && r.limit_state == ls && r.kind == kind && r.location == loc) return r;
  FAIL("missing row " << code << " " << ls << " " << kind << " " << loc);
  return rows.front();
}
}  // namespace

TEST_CASE("ground level, soil B: the §6b checks of the 0.5 m x 6 m wall at L'Aquila") {
  const auto r = wall_result();
  assess::CheckInput in;
  in.hazard = {{assess::LimitState::SLD, SLD}, {assess::LimitState::SLV, SLV}, {assess::LimitState::SLC, SLC}};
  in.site.soil = assess::SoilClass::B;
  const auto rows = assess::run_code_checks(r, in);
  const double g = assess::units::g;

  const auto& lin08 = find(rows, "NTC2008", "SLV", "strength", "ground");
  CHECK_CLOSE(lin08.demand / g, 0.15034, abs_tol(tol_printed));
  CHECK_CLOSE(lin08.capacity / g, 0.08230, abs_tol(tol_printed));
  CHECK_FALSE(lin08.satisfied);
  const auto& nl08 = find(rows, "NTC2008", "SLV", "displacement", "ground");
  CHECK_CLOSE(nl08.demand, 0.14660, abs_tol(tol_printed));
  CHECK_CLOSE(nl08.capacity, 0.13333, abs_tol(tol_printed));
  CHECK_FALSE(nl08.satisfied);
  const auto& sld08 = find(rows, "NTC2008", "SLD", "strength", "ground");
  CHECK_CLOSE(sld08.demand, assess::ElasticSpectrum(SLD, in.site).PGA(), rel_tol(tol_formula));

  // The safety indices of these checks: tests/numeric/safety_index.cpp.
  const auto& slv18 = find(rows, "NTC2018", "SLV", "strength", "ground");
  CHECK_CLOSE(slv18.demand, assess::ElasticSpectrum(SLV, in.site).PGA() / 2.0, rel_tol(tol_formula));
  const auto& nl18 = find(rows, "NTC2018", "SLV", "displacement", "ground");
  CHECK_CLOSE(nl18.demand, assess::ElasticSpectrum(SLV, in.site, 8.0).SDe(r.T_SLV), rel_tol(tol_formula));
  CHECK_CLOSE(nl18.capacity, 0.13333, abs_tol(tol_printed));
  const auto& slc18 = find(rows, "NTC2018", "SLC", "displacement", "ground");
  CHECK_CLOSE(slc18.demand, assess::ElasticSpectrum(SLC, in.site, 10.0).SDe(r.T_SLC), rel_tol(tol_formula));
  CHECK_CLOSE(slc18.capacity, 0.2, abs_tol(tol_printed));
  for (const auto& row : rows) {
    CHECK_CLOSE(row.dc, row.demand / row.capacity, rel_tol(tol_formula));
    CHECK(row.satisfied == (row.dc <= 1.0));
  }

}

TEST_CASE("at height: every demand of both editions recomputed from the formulas") {
  const auto r = wall_result();
  assess::CheckInput in;
  in.hazard = {{assess::LimitState::SLD, SLD}, {assess::LimitState::SLV, SLV}, {assess::LimitState::SLC, SLC}};
  in.site.soil = assess::SoilClass::C;
  const double H = 12.0, Z = 6.0, T1 = assess::code_rules::T1_simplified(H);
  const int N = 3;
  in.Z = Z;
  in.building = assess::BuildingModel{H, N, T1, 5.0};
  const auto rows = assess::run_code_checks(r, in);
  const double psi = Z / H, gam = 3.0 * N / (2.0 * N + 1.0);
  CHECK_CLOSE(T1, 0.05 * std::pow(12.0, 0.75), rel_tol(tol_formula));

  // NTC 2008.
  const assess::ElasticSpectrum sSLD(SLD, in.site), sSLV(SLV, in.site);
  CHECK_CLOSE(find(rows, "NTC2008", "SLD", "strength", "height").demand, sSLD.Se(T1) * psi * gam,
              rel_tol(tol_formula));
  CHECK_CLOSE(find(rows, "NTC2008", "SLV", "strength", "height").demand, sSLV.Se(T1) * psi * gam / 2.0,
              rel_tol(tol_formula));
  CHECK_CLOSE(find(rows, "NTC2008", "SLV", "strength", "ground").demand, sSLV.PGA() / 2.0, rel_tol(tol_formula));
  const double ratio = r.Ts / T1;
  CHECK_CLOSE(find(rows, "NTC2008", "SLV", "displacement", "height").demand,
              sSLV.SDe(T1) * psi * gam * ratio * ratio / std::sqrt((1 - ratio) * (1 - ratio) + 0.02 * ratio),
              rel_tol(tol_formula));
  CHECK_CLOSE(find(rows, "NTC2008", "SLV", "displacement", "ground").demand, sSLV.SDe(r.Ts), rel_tol(tol_formula));

  // NTC 2018: a_Z = Se(T1, 5 %) gamma psi sqrt(1 + 0.0004 * 25) [C7.2.7].
  const double corr = std::sqrt(1.0 + 0.0004 * 25.0);
  const double aZ_SLD = sSLD.Se(T1) * gam * psi * corr, aZ_SLV = sSLV.Se(T1) * gam * psi * corr;
  CHECK_CLOSE(find(rows, "NTC2018", "SLD", "strength", "height").demand, aZ_SLD, rel_tol(tol_formula));
  CHECK_CLOSE(find(rows, "NTC2018", "SLV", "strength", "height").demand, aZ_SLV / 2.0, rel_tol(tol_formula));
  // Floor spectrum [C7.2.6] at T_SLV (> b T1 here): A = 1.1 (0.05)^-0.5 eta(8 %).
  auto floor_disp = [&](const assess::HazardParams& h, double T, double xi) {
    const assess::ElasticSpectrum s5(h, in.site), sx(h, in.site, xi);
    const double aZ = s5.Se(T1) * gam * psi * corr;
    const double A = 1.1 / std::sqrt(0.05) * std::sqrt(10.0 / (5.0 + xi));
    const double a = 0.8, b = 1.1;
    auto SeZ = [&](double t) {
      double v;
      if (t < a * T1) v = aZ * A / (1 + (A - 1) * std::pow(1 - t / (a * T1), 1.6));
      else if (t < b * T1) v = aZ * A;
      else v = aZ * A / (1 + (A - 1) * std::pow(t / (b * T1) - 1, 1.2));
      return t > T1 ? std::max(v, sx.Se(t)) : v;
    };
    const double w = 2 * assess::units::pi;
    double d = SeZ(T) * T * T / (w * w);
    if (T > b * T1) d = std::max(d, SeZ(T1) * b * b * T1 * T1 / (w * w));
    return d;
  };
  REQUIRE(r.T_SLV > 1.1 * T1);
  const auto& slv = find(rows, "NTC2018", "SLV", "displacement", "height");
  CHECK_CLOSE(slv.demand, floor_disp(SLV, r.T_SLV, 8.0), rel_tol(tol_formula));
  CHECK_CLOSE(find(rows, "NTC2018", "SLC", "displacement", "height").demand, floor_disp(SLC, r.T_SLC, 10.0),
              rel_tol(tol_formula));
}
