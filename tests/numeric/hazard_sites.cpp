// Site hazard from the NTC 2008 Allegato B grid: published and regression
// values of ntc.md §6 (computed there independently from the same grid file).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/support/error.hpp>
#include <assess/hazard/hazard.hpp>
#include <assess/hazard/seismic_action.hpp>
#include <assess/hazard/site.hpp>

#include <algorithm>
#include <string>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

// The issue asks for the §6b regression sites to 1e-4 relative; the table
// prints 5 decimals, so half a unit of the last digit is added (matters for
// Milano's ag = 0.02416 g, where rounding alone is 2e-4 relative).
constexpr double tol_regression_rel = 1e-4;
constexpr double tol_regression_abs = 0.5e-5;
// Published L'Aquila values are rounded to 3 decimals: half a unit.
constexpr double tol_published_ag_g = 0.0005;
constexpr double tol_published_F0 = 0.0005;
constexpr double tol_published_Tc_s = 0.0005;
// A node hit returns the tabulated value exactly (log-log of one value).
constexpr double tol_node_rel = 1e-12;

namespace {
const HazardGrid& grid() {
  static const HazardGrid g = HazardGrid::load(std::string(ASSESS_TEST_DATA_DIR) + "/spectra/ntc2008_hazard_grid.csv");
  return g;
}
void check_site(double lat, double lon, double tr, double ag, double f0, double tc) {
  CAPTURE(lat);
  CAPTURE(lon);
  CAPTURE(tr);
  const HazardParams h = grid().at(lat, lon, tr);
  const assess::test::Tol tol{tol_regression_abs, tol_regression_rel};
  CHECK_CLOSE(h.ag_g, ag, tol);
  CHECK_CLOSE(h.F0, f0, tol);
  CHECK_CLOSE(h.Tc_star, tc, tol);
}
}  // namespace

TEST_CASE("the grid has 10751 nodes") { CHECK(grid().size() == 10751); }

TEST_CASE("L'Aquila TR 475 matches the published 0.261 g, 2.364, 0.347 s") {
  const HazardParams h = grid().at(42.3498, 13.3995, 475.0);
  CHECK_CLOSE(h.ag_g, 0.261, abs_tol(tol_published_ag_g));
  CHECK_CLOSE(h.F0, 2.364, abs_tol(tol_published_F0));
  CHECK_CLOSE(h.Tc_star, 0.347, abs_tol(tol_published_Tc_s));
}

TEST_CASE("regression sites of ntc.md 6b (enclosing cell, IDW 1/d, log-log TR)") {
  check_site(42.3498, 13.3995, 30, 0.07878, 2.40001, 0.27212);
  check_site(42.3498, 13.3995, 50.2890, 0.10416, 2.33202, 0.28109);
  check_site(42.3498, 13.3995, 474.5611, 0.26066, 2.36350, 0.34649);
  check_site(42.3498, 13.3995, 475, 0.26074, 2.36355, 0.34653);
  check_site(45.4668, 9.1905, 50.2890, 0.02416, 2.55206, 0.19043);
  check_site(45.4668, 9.1905, 474.5611, 0.04973, 2.65507, 0.27960);
  check_site(40.8359, 14.2488, 50.2890, 0.05932, 2.33235, 0.31204);
  check_site(40.8359, 14.2488, 474.5611, 0.16761, 2.36977, 0.33716);
  check_site(38.1938, 15.5542, 50.2890, 0.08202, 2.31595, 0.29402);
  check_site(38.1938, 15.5542, 474.5611, 0.24860, 2.41103, 0.35914);
}

TEST_CASE("Roma uses the enclosing cell, not the 4 nearest nodes") {
  const std::vector<int> cell = grid().cell_nodes(41.8933, 12.4829);
  std::vector<int> sorted = cell;
  std::sort(sorted.begin(), sorted.end());
  CHECK(sorted == std::vector<int>{28290, 28291, 28512, 28513});
  check_site(41.8933, 12.4829, 50.2890, 0.05476, 2.50296, 0.26947);
  check_site(41.8933, 12.4829, 474.5611, 0.12055, 2.62746, 0.29424);
  // The 4-nearest answer (0.11785 g) must NOT come out.
  CHECK(grid().at(41.8933, 12.4829, 474.5611).ag_g > 0.1200);
}

TEST_CASE("an exact node hit returns the node's values; TR 100 interpolates 72-101") {
  const HazardNode* n = grid().node(26528);
  REQUIRE(n != nullptr);
  const HazardParams h475 = grid().at(n->lat, n->lon, 475.0);
  CHECK_CLOSE(h475.ag_g, 0.26099, rel_tol(tol_node_rel));
  CHECK_CLOSE(h475.F0, 2.364, rel_tol(tol_node_rel));
  CHECK_CLOSE(h475.Tc_star, 0.34696, rel_tol(tol_node_rel));
  const HazardParams h100 = grid().at(n->lat, n->lon, 100.0);
  CHECK_CLOSE(h100.ag_g, 0.14179, rel_tol(tol_regression_rel));
  CHECK_CLOSE(h100.F0, 2.3047, rel_tol(tol_regression_rel));
  CHECK_CLOSE(h100.Tc_star, 0.29649, rel_tol(tol_regression_rel));
  CHECK_CLOSE(interpolate_in_tr(*n, 100.0).ag_g, h100.ag_g, rel_tol(tol_node_rel));
}

TEST_CASE("TR is clamped to [30, 2475] years with a flag") {
  const HazardNode* n = grid().node(26528);
  const HazardParams lo = grid().at(42.3498, 13.3995, 21.08);
  CHECK(lo.tr_clamped);
  CHECK(lo.TR == 30.0);
  CHECK_CLOSE(lo.ag_g, 0.07878, rel_tol(tol_regression_rel));
  const HazardParams hi = interpolate_in_tr(*n, 5000.0);
  CHECK(hi.tr_clamped);
  CHECK(hi.TR == 2475.0);
  CHECK(hi.ag_g == n->ag_g[8]);
  CHECK_FALSE(grid().at(42.3498, 13.3995, 475).tr_clamped);
  CHECK_THROWS_AS(grid().at(42.3498, 13.3995, 0.0), InputError);
}

TEST_CASE("points outside the grid and bad coordinates are clear errors") {
  CHECK_THROWS_WITH_AS(grid().at(48.5, 2.35, 475), doctest::Contains("outside the NTC hazard grid"), InputError);
  CHECK_THROWS_WITH_AS(grid().at(40.0, 9.0, 475), doctest::Contains("outside"), InputError);  // Sardinia
  CHECK_THROWS_WITH_AS(grid().at(95.0, 13.0, 475), doctest::Contains("latitude"), InputError);
  CHECK_THROWS_AS(HazardGrid::load("/nonexistent/grid.csv"), InputError);
}

TEST_CASE("islands of Allegato B Tab. 2 by name") {
  const IslandTable t = IslandTable::load(std::string(ASSESS_TEST_DATA_DIR) + "/spectra/ntc2008_islands_table2.csv");
  const HazardParams s = t.at("Sardegna", 475.0);
  CHECK_CLOSE(s.ag_g, 0.05, rel_tol(tol_node_rel));
  CHECK_CLOSE(s.F0, 2.88, rel_tol(tol_node_rel));
  CHECK_CLOSE(s.Tc_star, 0.34, rel_tol(tol_node_rel));
  CHECK_CLOSE(t.at("lipari", 975).ag_g, 0.2823, rel_tol(tol_node_rel));
  CHECK_CLOSE(t.at("Egadi", 30).ag_g, 0.0186, rel_tol(tol_node_rel));
  CHECK_THROWS_WITH_AS(t.at("Atlantide", 475), doctest::Contains("Sardegna"), InputError);
}

TEST_CASE("Site gives TR and hazard per limit state") {
  SiteSpec spec;
  spec.lat = 42.3498;
  spec.lon = 13.3995;
  spec.conditions.soil = SoilClass::B;
  const Site site(spec);
  const SeismicAction slv = site.action(LimitState::SLV);
  CHECK_CLOSE(slv.TR, 474.5611, abs_tol(1e-3));
  CHECK_CLOSE(slv.hazard.ag_g, 0.26066, rel_tol(tol_regression_rel));
  // SS from the interpolated (unrounded) ag, F0: the table's inputs are rounded.
  CHECK_CLOSE(site.spectrum(LimitState::SLV).SS(), 1.15357, abs_tol(2e-5));
  SiteSpec bad = spec;
  bad.island = "Lipari";
  CHECK_THROWS_AS(Site{bad}, InputError);
}
