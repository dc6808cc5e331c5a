// The case file's tie rods (issue 23): units at the edge (mm, mm^2, MPa, kN,
// m) to SI, defaults, errors naming the JSON path; and the tie intervention
// of a case against hand forms: alpha0 with two given levels, the design's
// choice being the smallest passing rod and plate of the lists.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/assessment/case_file.hpp>
#include <assess/assessment/tie_intervention.hpp>
#include <assess/kinematic/tie_catalogue.hpp>
#include <assess/kinematic/tie_checks.hpp>
#include <assess/support/error.hpp>
#include <assess/support/units.hpp>

#include <nlohmann/json.hpp>

#include <string>

using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

constexpr double tol_si = 1e-12;     // relative: unit conversions
constexpr double tol_alpha = 1e-12;  // alpha0 (-)

const double t_wall = 0.65, h_wall = 14.57, gamma_kN = 18.0;

nlohmann::json base_case() {
  return nlohmann::json::parse(R"({
    "project": "tie test",
    "site": { "hazard": { "SLD": {"ag_g": 0.07, "F0": 2.5, "Tc_star": 0.28},
                          "SLV": {"ag_g": 0.20, "F0": 2.4, "Tc_star": 0.31},
                          "SLC": {"ag_g": 0.26, "F0": 2.45, "Tc_star": 0.33} }, "soil": "C" },
    "mechanism": { "type": "simple_overturning", "storeys": [ { "height": 14.57, "thickness": 0.65 } ],
                   "unit_weight": 18.0, "length": 1.0, "hinge_level": 0 },
    "knowledge_level": "LC2",
    "ties": [
      { "name": "eaves", "point": [0.0, 14.0], "rod": {"diameter_mm": 20, "grade": "S355"}, "free_length_m": 12.0,
        "anchor": {"type": "plate", "a_mm": 300, "t_mm": 20}, "masonry": {"fm_MPa": 2.0, "tau_MPa": 0.05, "thickness_m": 0.65},
        "spacing_m": 3.0, "pretension_kN": 4 },
      { "name": "mid", "point": [-0.65, 8.0], "rod": {"area_mm2": 201}, "free_length_m": 8.0,
        "anchor": {"type": "bar", "length_mm": 600, "diameter_mm": 40},
        "masonry": {"fm_MPa": 1.5, "tau_MPa": 0.04, "thickness_m": 0.65, "FC": 1.0, "gamma_M": 3.0}, "spacing_m": 4.0 }
    ]
  })");
}

std::string error_of(const nlohmann::json& doc) {
  try {
    assess::parse_case(doc, "c.json");
  } catch (const assess::InputError& e) {
    return e.what();
  }
  return "";
}

}  // namespace

TEST_CASE("case file ties: units to SI and defaults") {
  const auto c = assess::parse_case(base_case(), "c.json");
  REQUIRE(c.ties.size() == 2);
  const auto& a = c.ties[0];
  CHECK(a.name == "eaves");
  CHECK_CLOSE(a.rod.diameter, 0.020, rel_tol(tol_si));
  CHECK_CLOSE(a.rod.area, assess::units::pi * 0.02 * 0.02 / 4, rel_tol(tol_si));
  CHECK_CLOSE(a.rod.fyk, 355e6, rel_tol(tol_si));
  CHECK_CLOSE(a.rod.gamma_M0, 1.05, rel_tol(tol_si));
  CHECK(a.anchor.type == assess::AnchorType::Plate);
  CHECK_CLOSE(a.anchor.a, 0.3, rel_tol(tol_si));
  CHECK_CLOSE(a.anchor.b, 0.3, rel_tol(tol_si));  // b defaults to a
  CHECK_CLOSE(a.anchor.t, 0.02, rel_tol(tol_si));
  CHECK_CLOSE(a.anchor.fyk, 275e6, rel_tol(tol_si));  // plate grade default S275
  CHECK_CLOSE(a.masonry.fm, 2e6, rel_tol(tol_si));
  CHECK_CLOSE(a.masonry.tau, 5e4, rel_tol(tol_si));
  CHECK_CLOSE(a.masonry.FC, 1.20, rel_tol(tol_si));  // LC2
  CHECK_CLOSE(a.masonry.gamma_M, 2.0, rel_tol(tol_si));
  CHECK_CLOSE(a.pretension, 4e3, rel_tol(tol_si));
  CHECK_CLOSE(a.direction.x(), -1.0, rel_tol(tol_si));
  const auto& b = c.ties[1];
  CHECK_CLOSE(b.rod.area, 201e-6, rel_tol(tol_si));
  CHECK(b.rod.diameter == 0.0);
  CHECK_CLOSE(b.rod.fyk, 275e6, rel_tol(tol_si));
  CHECK(b.anchor.type == assess::AnchorType::Bar);
  CHECK_CLOSE(b.anchor.a, 0.6, rel_tol(tol_si));
  CHECK_CLOSE(b.anchor.b, 0.04, rel_tol(tol_si));
  CHECK_CLOSE(b.masonry.FC, 1.0, rel_tol(tol_si));
  CHECK_CLOSE(b.masonry.gamma_M, 3.0, rel_tol(tol_si));
}

TEST_CASE("case file ties: bad fields name the file, the JSON path, the expected value and unit") {
  auto doc = base_case();
  doc["ties"][0]["rod"]["diameter_mm"] = -20;
  CHECK(error_of(doc).find("c.json: /ties/0/rod/diameter_mm: value -20 out of range: expected in [0.1, 10000] mm") != std::string::npos);
  doc = base_case();
  doc["ties"][1]["free_length_m"] = "8";
  CHECK(error_of(doc).find("/ties/1/free_length_m") != std::string::npos);
  doc = base_case();
  doc["ties"][0]["masonry"]["FC"] = 0.5;
  CHECK(error_of(doc).find("/ties/0/masonry/FC: value 0.5 out of range") != std::string::npos);
  doc = base_case();
  doc["ties"][0]["anchor"]["type"] = "wedge";
  CHECK(error_of(doc).find("/ties/0/anchor/type") != std::string::npos);
  doc = base_case();
  doc["ties"][0]["direction"] = {0, 0};
  CHECK(error_of(doc).find("/ties/0/direction: expected a non-zero direction") != std::string::npos);
  doc = base_case();
  doc["ties"][0]["point"] = {0.0, 20.0};  // above the wall
  CHECK(error_of(doc).find("/ties/0/point: the anchor point") != std::string::npos);
  doc = base_case();
  doc["design"] = {{"ties", {{"levels", nlohmann::json::array()}}}};
  CHECK(error_of(doc).find("/design/ties/levels") != std::string::npos);
}

TEST_CASE("tie intervention: alpha0 after = (W t/2 + sum T_Rd,i / s_i z_i) / (W h/2) with two given levels") {
  const auto c = assess::parse_case(base_case(), "c.json");
  const auto t = assess::run_tie_intervention(c);
  const double W = gamma_kN * assess::units::kN * t_wall * h_wall;
  const double T1 = assess::tie_resistance(c.ties[0]).design / 3.0, T2 = assess::tie_resistance(c.ties[1]).design / 4.0;
  const auto& after = t.after.candidates[t.after.governing].result;
  const auto& before = t.before.candidates[t.before.governing].result;
  CHECK_CLOSE(before.alpha0, t_wall / h_wall, abs_tol(tol_alpha));
  CHECK_CLOSE(after.alpha0, (W * t_wall / 2 + T1 * 14.0 + T2 * 8.0) / (W * h_wall / 2), abs_tol(tol_alpha));
  REQUIRE(t.levels.size() == 2);
  // Every required force per tie is the largest over the checks; the tie checks use it.
  for (const auto& L : t.levels) {
    double mx = 0.0;
    for (const auto& f : L.required) mx = std::max(mx, f.per_tie);
    CHECK_CLOSE(L.N_Ed, mx, rel_tol(1e-15));
    CHECK(L.checks.size() == 5);
  }
  CHECK(t.zetaE_after > t.zetaE_before);
}

TEST_CASE("tie design: the proposed rod and plate pass, the next smaller ones of the lists do not") {
  auto doc = base_case();
  doc.erase("ties");
  doc["design"] = nlohmann::json::parse(R"({"ties": {"levels": [
      {"name": "eaves", "point": [0.0, 14.0], "free_length_m": 12.0,
       "masonry": {"fm_MPa": 2.0, "tau_MPa": 0.05, "thickness_m": 0.65}, "spacing_m": 3.0}]}})");
  const auto c = assess::parse_case(doc, "c.json");
  const auto t = assess::run_tie_intervention(c);
  REQUIRE(t.found);
  CHECK_FALSE(t.passes_before);
  CHECK(t.passes_after);
  REQUIRE(t.levels.size() == 1);
  const auto& chosen = t.levels[0].tie;
  // The same search by hand: the first (rod, plate) in the lists' order whose
  // design strength reaches the linear checks' required force, and which
  // passes the rest, must be the proposed one; every smaller rod fails.
  std::size_t idx = 0;
  while (assess::tie_catalogue::rod_diameters[idx] < chosen.rod.diameter - 1e-12) ++idx;
  for (std::size_t i = 0; i < idx; ++i) {
    // The strongest plate with a smaller rod: the rod's own strength is below N_Ed.
    const double d = assess::tie_catalogue::rod_diameters[i];
    const double rod = assess::units::pi * d * d / 4 * 275e6 / 1.05;
    CHECK(rod < t.levels[0].N_Ed);
  }
  CHECK(t.levels[0].resistance.design >= t.levels[0].N_Ed);
}
