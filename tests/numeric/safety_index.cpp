// The safety index of a check (issue 41; docs/theory/building.md §4): the
// return period TR_C at which that same check reaches D/C = 1 with the site's
// whole hazard at TR_C (ag, F0, TC* of Allegato A), PGA_C = ag(TR_C),
// PGA_D = ag(TR_D), zetaE = PGA_C / PGA_D.
//
// References:
//  - hazard given per limit state (ag varied alone, F0 and TC* held): the
//    ntc.md §6b values of the 0.5 m x 6 m wall at L'Aquila [C], computed there
//    independently (soil A strength q a0*/g = 0.16461 g, soil B 0.13717 g;
//    displacement xi 8 %: A 0.27620 g, B 0.19302 g; xi 5 %: A 0.25145 g, B 0.17469 g);
//  - the grid (L'Aquila): the same checks' D/C written out here from NTC 2018
//    [3.2.2]-[3.2.5] (S = SS ST, SS of Tab. 3.2.IV, eta = sqrt(10/(5 + xi)),
//    TC = CC TC*, TD = 4 ag + 1.6) at the hazard of Site::hazard_at_tr, and
//    the return period where they equal 1 found by bisection;
//  - beyond 2475 years: ag by the power law of the 975-2475 segment, written out;
//  - a property over generated cases (sites, soils, topographies, VN, CU, at
//    ground and at height, both editions): zetaE < 1 exactly where D/C > 1,
//    and every check re-run at its TR_C gives D/C = 1;
//  - a synthetic grid whose F0 drops with TR: a non-monotonic D/C, flagged,
//    with the index on the side of the check.
#include <doctest/doctest.h>

#include "check_close.hpp"
#include "test_files.hpp"

#include <assess/assessment/case_file.hpp>
#include <assess/assessment/safety_index.hpp>
#include <assess/hazard/site.hpp>
#include <assess/kinematic/check_index.hpp>
#include <assess/kinematic/code_checks.hpp>
#include <assess/kinematic/kinematic_analysis.hpp>
#include <assess/kinematic/mechanism_catalogue.hpp>
#include <assess/support/units.hpp>

#include <nlohmann/json.hpp>

#include <cmath>
#include <functional>
#include <random>
#include <string>

using assess::test::abs_tol;
using assess::test::rel_tol;
using namespace assess;

namespace {

// §6b prints 5 decimals (g).
constexpr double tol_printed_g = 1.0e-5;
// D/C re-run at TR_C: Brent's tolerance is 1e-12 on ln TR; D/C is smooth in TR.
constexpr double tol_dc = 1e-8;
// TR_C against the bisection here (60 halvings of ln TR: ~1e-16): relative.
constexpr double tol_tr = 1e-8;
constexpr double g = 9.81;  // m/s^2, NTC 2018 §3.2.3.2.3 (as units::g)

KinematicResult wall_result() {
  SimpleOverturningParams p;
  Storey s;
  s.height = 6.0;
  s.thickness = 0.5;
  p.storeys = {s};
  p.unit_weight = 18000.0;
  p.hinge_level = 0;
  KinematicOptions opt;
  opt.FC = 1.35;
  opt.curve_model = CurveModel::Linearised;  // as in ntc.md §6b
  return analyse_kinematic(simple_overturning(p).candidates[0].chain, opt);
}

// A copy: the rows are often a temporary.
CheckRow find(const std::vector<CheckRow>& rows, const char* code, const char* ls, const char* kind) {
  for (const auto& r : rows)
    if (r.code == code && r.limit_state == ls && r.kind == kind) return r;
  FAIL("missing row " << code << " " << ls << " " << kind);
  return rows.front();
}

// Bisection in ln TR of a continuous f with f(lo) < 0 < f(hi).
double bisect(const std::function<double(double)>& f, double lo, double hi) {
  REQUIRE(f(lo) < 0.0);
  REQUIRE(f(hi) > 0.0);
  for (int i = 0; i < 200; ++i) {
    const double m = std::sqrt(lo * hi);
    (f(m) > 0.0 ? hi : lo) = m;
  }
  return std::sqrt(lo * hi);
}

// NTC 2018 Tab. 3.2.IV, soils A and B, and the spectrum's branches [3.2.4].
double SS(char soil, double ag, double F0) {
  return soil == 'A' ? 1.0 : std::clamp(1.40 - 0.40 * F0 * ag, 1.0, 1.20);
}
double CC(char soil, double Tc_star) { return soil == 'A' ? 1.0 : 1.10 * std::pow(Tc_star, -0.20); }
// Se (m/s^2) at T >= TC (the branches the wall's periods lie on, T < TE).
double Se_long(char soil, const HazardParams& h, double T, double xi) {
  const double S = SS(soil, h.ag_g, h.F0), eta = std::max(std::sqrt(10.0 / (5.0 + xi)), 0.55);
  const double TC = CC(soil, h.Tc_star) * h.Tc_star, TD = 4.0 * h.ag_g + 1.6;
  REQUIRE(T >= TC);
  const double plateau = h.ag_g * g * S * eta * h.F0;
  return T < TD ? plateau * TC / T : plateau * TC * TD / (T * T);
}

CheckInput laquila_input(char soil) {
  CheckInput in;
  in.hazard = {{LimitState::SLD, {50.2890, 0.10416, 2.33202, 0.28109}},
               {LimitState::SLV, {474.5611, 0.26066, 2.36350, 0.34649}},
               {LimitState::SLC, {974.79, 0.33, 2.40, 0.36}}};
  in.site.soil = soil == 'A' ? SoilClass::A : SoilClass::B;
  in.codes = {CodeEdition::NTC2018};
  in.sld = true;
  return in;
}

}  // namespace

TEST_CASE("hazard given per limit state: ag varied alone, F0 and TC* held, the ntc.md §6b capacities") {
  const KinematicResult r = wall_result();
  for (char soil : {'A', 'B'}) {
    CAPTURE(soil);
    CheckInput in = laquila_input(soil);
    const std::vector<CheckRow> rows = run_code_checks(r, in);
    const CheckIndex s = check_index(r, in, find(rows, "NTC2018", "SLV", "strength"), {});
    REQUIRE(s.defined);
    CHECK(s.shape_held);
    CHECK(std::isnan(s.TR_capacity));  // no return-period axis
    CHECK_CLOSE(s.ag_capacity_g, soil == 'A' ? 0.16461 : 0.13717, abs_tol(tol_printed_g));
    CHECK_CLOSE(s.ag_demand_g, 0.26066, abs_tol(1e-15));
    CHECK_CLOSE(s.zeta, s.ag_capacity_g / 0.26066, rel_tol(1e-15));
    const CheckIndex sld = check_index(r, in, find(rows, "NTC2018", "SLD", "strength"), {});
    CHECK_CLOSE(sld.ag_capacity_g, soil == 'A' ? 0.08230 : 0.06859, abs_tol(tol_printed_g));
    for (double xi : {8.0, 5.0}) {
      CAPTURE(xi);
      in.damping_SLV_pct = xi;
      const CheckIndex d = check_index(r, in, find(run_code_checks(r, in), "NTC2018", "SLV", "displacement"), {});
      const double expected = soil == 'A' ? (xi == 8.0 ? 0.27620 : 0.25145) : (xi == 8.0 ? 0.19302 : 0.17469);
      CHECK_CLOSE(d.ag_capacity_g, expected, abs_tol(tol_printed_g));
      CHECK((d.zeta < 1.0) == (find(run_code_checks(r, in), "NTC2018", "SLV", "displacement").dc > 1.0));
    }
  }
}

TEST_CASE("on the grid: the return period at which the check itself reaches D/C = 1 (L'Aquila, NTC 2018 written out)") {
  SiteSpec spec;
  spec.lat = 42.3498;
  spec.lon = 13.3995;
  const KinematicResult r = wall_result();
  const double q = 2.0;
  for (char soil : {'A', 'B'}) {
    CAPTURE(soil);
    spec.conditions.soil = soil == 'A' ? SoilClass::A : SoilClass::B;
    const Site site(spec);
    const HazardAxis axis = [&site](double tr) { return site.hazard_extrapolated(tr); };
    CheckInput in = laquila_input(soil);
    for (LimitState ls : {LimitState::SLD, LimitState::SLV, LimitState::SLC}) in.hazard[ls] = site.action(ls).hazard;
    const std::vector<CheckRow> rows = run_code_checks(r, in);

    // Strength SLV [C8.7.1.2.1.7]: D/C = ag SS ST g / (q a0*).
    const CheckRow& str = find(rows, "NTC2018", "SLV", "strength");
    auto dc_str = [&](double tr) {
      const HazardParams h = site.hazard_at_tr(tr);
      return h.ag_g * SS(soil, h.ag_g, h.F0) * g / (q * r.a0_star);
    };
    CHECK_CLOSE(str.dc, dc_str(site.action(LimitState::SLV).TR), rel_tol(1e-12));
    const double tr_str = bisect([&](double tr) { return dc_str(tr) - 1.0; }, 30.0, 2475.0);
    const CheckIndex is = check_index(r, in, str, axis);
    REQUIRE(is.defined);
    CHECK_FALSE(is.shape_held);
    CHECK(is.bound == 0);
    CHECK_CLOSE(is.TR_capacity, tr_str, rel_tol(tol_tr));
    CHECK_CLOSE(is.ag_capacity_g, site.hazard_at_tr(tr_str).ag_g, rel_tol(1e-8));
    CHECK_CLOSE(is.ag_demand_g, site.action(LimitState::SLV).hazard.ag_g, rel_tol(1e-15));
    CHECK_CLOSE(is.TR_demand, site.action(LimitState::SLV).TR, rel_tol(1e-15));
    CHECK_CLOSE(is.TR_ratio, tr_str / site.action(LimitState::SLV).TR, rel_tol(tol_tr));
    CHECK((is.zeta < 1.0) == (str.dc > 1.0));
    if (soil == 'A') CHECK_CLOSE(is.ag_capacity_g, q * r.a0_star / g, rel_tol(1e-8));  // S = 1: closed form

    // Displacement SLV [C8.7.1.2.1.8]: D/C = SDe(T_SLV, 8 %) / d_SLV (T_SLV on the branches above).
    const CheckRow& dis = find(rows, "NTC2018", "SLV", "displacement");
    auto dc_dis = [&](double tr) {
      const double T = r.T_SLV;
      return Se_long(soil, site.hazard_at_tr(tr), T, 8.0) * T * T / (4.0 * units::pi * units::pi) / r.d_SLV;
    };
    CHECK_CLOSE(dis.dc, dc_dis(site.action(LimitState::SLV).TR), rel_tol(1e-12));
    const CheckIndex id = check_index(r, in, dis, axis);
    REQUIRE(id.defined);
    CHECK((id.zeta < 1.0) == (dis.dc > 1.0));
    if (id.bound == 0 && !id.extrapolated) {
      const double tr_dis = bisect([&](double tr) { return dc_dis(tr) - 1.0; }, 30.0, 2475.0);
      CHECK_CLOSE(id.TR_capacity, tr_dis, rel_tol(tol_tr));
    }
  }
}

TEST_CASE("beyond 2475 years: ag by the end segment's power law, F0 and TC* held; the index is flagged extrapolated") {
  SiteSpec spec;
  spec.lat = 45.4668;  // Milano: a low hazard, so a stout wall's capacity lies beyond the data
  spec.lon = 9.1905;
  spec.conditions.soil = SoilClass::A;
  const Site site(spec);
  const HazardParams h975 = site.hazard_at_tr(975.0), h2475 = site.hazard_at_tr(2475.0);
  const double k = std::log(h2475.ag_g / h975.ag_g) / std::log(2475.0 / 975.0);
  const HazardParams h5000 = site.hazard_extrapolated(5000.0);
  CHECK_CLOSE(h5000.ag_g, h2475.ag_g * std::pow(5000.0 / 2475.0, k), rel_tol(1e-14));
  CHECK(h5000.F0 == h2475.F0);
  CHECK(h5000.Tc_star == h2475.Tc_star);
  CHECK(h5000.tr_clamped);
  const HazardParams h10 = site.hazard_extrapolated(10.0), h30 = site.hazard_at_tr(30.0), h50 = site.hazard_at_tr(50.0);
  CHECK_CLOSE(h10.ag_g, h30.ag_g * std::pow(10.0 / 30.0, std::log(h50.ag_g / h30.ag_g) / std::log(50.0 / 30.0)),
              rel_tol(1e-14));
  CHECK(site.hazard_extrapolated(475.0).ag_g == site.hazard_at_tr(475.0).ag_g);  // inside: Allegato A itself

  // Soil A strength at ground: PGA_C = q a0* / g whatever F0; TR_C from the power law.
  const KinematicResult r = wall_result();
  CheckInput in = laquila_input('A');
  for (LimitState ls : {LimitState::SLD, LimitState::SLV, LimitState::SLC}) in.hazard[ls] = site.action(ls).hazard;
  const CheckRow str = find(run_code_checks(r, in), "NTC2018", "SLV", "strength");
  const CheckIndex ix = check_index(r, in, str, [&site](double tr) { return site.hazard_extrapolated(tr); });
  const double ag_c = 2.0 * r.a0_star / g;
  REQUIRE(ag_c > h2475.ag_g);
  CHECK(ix.extrapolated);
  CHECK(ix.bound == 0);
  CHECK_CLOSE(ix.ag_capacity_g, ag_c, rel_tol(1e-8));
  CHECK_CLOSE(ix.TR_capacity, 2475.0 * std::pow(ag_c / h2475.ag_g, 1.0 / k), rel_tol(1e-8));
  CHECK(ix.zeta > 1.0);
}

namespace {

// A case on the grid at a perturbed city, with a one- or two-storey wall and the hinge at `level`.
nlohmann::json generated_case(std::mt19937& rng) {
  static const double cities[][2] = {{42.3498, 13.3995}, {41.8933, 12.4829}, {45.4668, 9.1905}, {40.8359, 14.2488},
                                     {38.1938, 15.5542}, {42.7930, 13.0930}, {43.1390, 13.0680}, {44.4949, 11.3426},
                                     {37.5079, 15.0830}, {46.0700, 13.2300}};
  std::uniform_int_distribution<int> city(0, 9), soil(0, 4), topo(0, 3), storeys(1, 3), cu(0, 2), codes(0, 2);
  std::uniform_real_distribution<double> jitter(-0.03, 0.03), t(0.3, 0.9), h(2.5, 5.0), vn(50.0, 100.0);
  const auto& c = cities[city(rng)];
  const char* soils[] = {"A", "B", "C", "D", "E"};
  const char* topos[] = {"T1", "T2", "T3", "T4"};
  const char* use[] = {"II", "III", "IV"};
  nlohmann::json st = nlohmann::json::array();
  const int n = storeys(rng);
  double H = 0.0;
  for (int i = 0; i < n; ++i) {
    const double hi = h(rng);
    st.push_back({{"height", hi}, {"thickness", t(rng)}, {"floor_weight", 10.0}, {"floor_distance_from_inner_face", 0.1}});
    H += hi;
  }
  nlohmann::json doc{{"site",
                      {{"lat", c[0] + jitter(rng)},
                       {"lon", c[1] + jitter(rng)},
                       {"soil", soils[soil(rng)]},
                       {"topography", topos[topo(rng)]},
                       {"VN_years", vn(rng)},
                       {"use_class", use[cu(rng)]}}},
                     {"mechanism",
                      {{"type", "simple_overturning"},
                       {"unit_weight", 18.0},
                       {"length", 1.0},
                       {"storeys", st},
                       {"hinge_level", std::uniform_int_distribution<int>(0, n - 1)(rng)}}},
                     {"building", {{"height_m", H}, {"storeys", n}}},
                     {"knowledge_level", "LC1"},
                     {"check_SLD", true}};
  const int cd = codes(rng);
  if (cd == 1) doc["codes"] = {"NTC2018"};
  if (cd == 2) doc["codes"] = {"NTC2008"};
  return doc;
}

}  // namespace

TEST_CASE("property over generated cases: zetaE < 1 exactly where D/C > 1, and D/C = 1 at TR_C, for every check") {
  std::mt19937 rng(20261128);
  int rows_checked = 0, failing = 0, at_height = 0;
  for (int k = 0; k < 60; ++k) {
    const nlohmann::json doc = generated_case(rng);
    CAPTURE(doc.dump());
    const CaseFile c = parse_case(doc, "generated.json");
    const KinematicCaseResult res = run_kinematic_case(c);
    const Site site(*c.site);
    for (const CandidateResult& cr : res.candidates)
      for (const CheckRow& row : cr.checks) {
        CAPTURE(row.code + " " + row.limit_state + " " + row.kind + " " + row.location);
        REQUIRE(row.index.defined);
        ++rows_checked;
        failing += row.dc > 1.0;
        at_height += row.location == "height";
        CHECK((row.index.zeta < 1.0) == (row.dc > 1.0));
        CHECK((row.index.TR_ratio < 1.0) == (row.dc > 1.0));
        if (row.index.bound != 0) continue;
        CheckInput in = *res.check_input;
        in.Z = cr.Z;
        in.hazard[parse_limit_state(row.limit_state)] = site.hazard_extrapolated(row.index.TR_capacity);
        for (const CheckRow& x : run_code_checks(cr.result, in))
          if (x.code == row.code && x.limit_state == row.limit_state && x.kind == row.kind && x.location == row.location)
            CHECK_CLOSE(x.dc, 1.0, abs_tol(tol_dc));
      }
    // The approach's index is the lowest of its checks', below 1 exactly where its verdict fails.
    for (const SafetyIndex& s : safety_indices(res, res.verdict)) {
      if (!s.defined) continue;
      CHECK((s.index.zeta < 1.0) == !s.satisfied);
    }
  }
  // The generator reaches both outcomes and the checks at height.
  CHECK(rows_checked > 300);
  CHECK(failing > 20);
  CHECK(failing < rows_checked - 20);
  CHECK(at_height > 50);
}

TEST_CASE("a D/C that is not monotonic in TR (a synthetic grid whose F0 drops): flagged, the index on the check's side") {
  // Four nodes of one cell, equal values: ag rises with TR, F0 falls from 3.5
  // to 1.8 between 101 and 140 years, so ag F0 (the plateau, and a wall at
  // height on it) falls there: Se(T1) at 101 years exceeds that at 475 years.
  const std::string dir = temp_dir("safety_index_grid");
  std::string csv = "id,lon,lat";
  for (int tr : {30, 50, 72, 101, 140, 201, 475, 975, 2475})
    csv += ",ag_" + std::to_string(tr) + ",F0_" + std::to_string(tr) + ",Tc_" + std::to_string(tr);
  csv += "\n";
  const double ag[9] = {0.05, 0.06, 0.07, 0.08, 0.085, 0.09, 0.12, 0.15, 0.20};
  const double F0[9] = {3.5, 3.5, 3.5, 3.5, 1.8, 1.8, 1.8, 1.8, 1.8};
  const struct { int id; double lon, lat; } nodes[4] = {{1000, 13.00, 42.05}, {1001, 13.05, 42.05}, {1222, 13.00, 42.00},
                                                       {1223, 13.05, 42.00}};
  for (const auto& n : nodes) {
    csv += std::to_string(n.id) + "," + std::to_string(n.lon) + "," + std::to_string(n.lat);
    for (int i = 0; i < 9; ++i) csv += "," + std::to_string(ag[i]) + "," + std::to_string(F0[i]) + ",0.3";
    csv += "\n";
  }
  SiteSpec spec;
  spec.lat = 42.025;
  spec.lon = 13.025;
  spec.grid_path = write(dir + "/grid.csv", csv);
  spec.conditions.soil = SoilClass::A;
  const Site site(spec);
  const HazardAxis axis = [&site](double tr) { return site.hazard_extrapolated(tr); };
  const KinematicResult r = wall_result();
  CheckInput in = laquila_input('A');
  for (LimitState ls : {LimitState::SLD, LimitState::SLV, LimitState::SLC}) in.hazard[ls] = site.action(ls).hazard;
  // At height on the plateau: a_Z = Se(T1) psi gamma sqrt(1 + 0.0004 xi^2) (TB <= T1 < TC).
  BuildingModel b;
  b.H = 6.0;
  b.storeys = 2;
  b.T1 = 0.2;
  in.building = b;
  in.Z = 3.0;
  const double a_over_agF0 = g * (3.0 / 6.0) * (6.0 / 5.0) * std::sqrt(1.0 + 0.0004 * 25.0);
  auto dc_at = [&](double tr, double a0) {
    const HazardParams h = site.hazard_at_tr(tr);
    return h.ag_g * h.F0 * a_over_agF0 / 2.0 / a0;
  };
  REQUIRE(dc_at(101.0, 1.0) > dc_at(site.action(LimitState::SLV).TR, 1.0));
  KinematicResult rr = r;
  SUBCASE("satisfied at TR_D, failing at 101 years: zetaE >= 1, the lower crossing reported") {
    rr.a0_star = 0.5 * (dc_at(101.0, 1.0) + dc_at(site.action(LimitState::SLV).TR, 1.0));
    const CheckRow row = find(run_code_checks(rr, in), "NTC2018", "SLV", "strength");
    REQUIRE(row.dc < 1.0);
    const CheckIndex ix = check_index(rr, in, row, axis);
    CHECK(ix.non_monotonic);
    CHECK(ix.zeta >= 1.0);
    CHECK(ix.other_crossing_TR < 101.0);
    CHECK(ix.other_crossing_TR > 30.0);
    CHECK_CLOSE(dc_at(ix.other_crossing_TR, rr.a0_star), 1.0, abs_tol(tol_dc));
    CHECK(ix.TR_capacity > site.action(LimitState::SLV).TR);
    CHECK_CLOSE(dc_at(ix.TR_capacity, rr.a0_star), 1.0, abs_tol(tol_dc));
  }
  SUBCASE("monotonic above: a stronger wall is not flagged") {
    rr.a0_star = 2.0 * dc_at(101.0, 1.0);
    const CheckIndex ix = check_index(rr, in, find(run_code_checks(rr, in), "NTC2018", "SLV", "strength"), axis);
    CHECK_FALSE(ix.non_monotonic);
    CHECK(ix.zeta > 1.0);
  }
}
