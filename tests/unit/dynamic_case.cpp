// The "dynamic" section of a case file: defaults, and errors that name the
// JSON path, the expected type or range and the unit.
#include <doctest/doctest.h>

#include <assess/assessment/dynamic_case.hpp>
#include <assess/support/error.hpp>

#include <nlohmann/json.hpp>

using namespace assess;
using nlohmann::json;

namespace {
DynamicSpec parse(const json& j) { return parse_dynamic(j, "case.json", ASSESS_TEST_DATA_DIR); }
}  // namespace

TEST_CASE("a minimal dynamic section gets the documented defaults") {
  const DynamicSpec d = parse(json{{"k", 1e6}, {"records", {{{"file", "spectra/records/elCentro.AT2"}}}}});
  CHECK(d.smooth);
  CHECK(d.k == 1e9);  // kN/m3 -> N/m3
  CHECK(d.sidedness == Sidedness::one_sided);
  REQUIRE(d.restitutions.size() == 1);
  CHECK(d.restitutions[0].kind == Restitution::Kind::one_sided_theory);
  CHECK(d.polarity == Polarity::normal);
  REQUIRE(d.records.size() == 1);
  CHECK(d.records[0].scale == 1.0);
  CHECK(d.records[0].json_path == "/dynamic/records/0");
}

TEST_CASE("restitution lists accept values and named laws") {
  const DynamicSpec d = parse(json{{"model", "rigid"},
                                   {"sidedness", "two-sided"},
                                   {"restitution", {0.9, "housner"}},
                                   {"select", {{"count", 5}}}});
  CHECK_FALSE(d.smooth);
  REQUIRE(d.restitutions.size() == 2);
  CHECK(d.restitutions[0].e == 0.9);
  CHECK(d.restitutions[1].kind == Restitution::Kind::housner);
  REQUIRE(d.selection);
  CHECK(d.selection->count == 5);
}

TEST_CASE("bad dynamic input names the JSON path") {
  const json rec = {{{"file", "spectra/records/elCentro.AT2"}, {"scale", 1.0}}};
  CHECK_THROWS_WITH_AS(parse(json{{"k", 1e6}, {"restitution", {-0.48, 2.0}}, {"records", rec}}),
                       doctest::Contains("/dynamic/restitution/1"), InputError);
  CHECK_THROWS_WITH_AS(parse(json{{"k", 1e6}, {"records", json::array()}}), doctest::Contains("/dynamic/records"),
                       InputError);
  CHECK_THROWS_WITH_AS(
      parse(json{{"k", 1e6}, {"records", {{{"file", "spectra/records/elCentro.AT2"}, {"scale", -2.0}}}}}),
      doctest::Contains("/dynamic/records/0/scale"), InputError);
  CHECK_THROWS_WITH_AS(parse(json{{"k", 1e6}, {"restitusion", -0.5}, {"records", rec}}),
                       doctest::Contains("restitution"), InputError);  // did-you-mean suggestion
  CHECK_THROWS_WITH_AS(parse(json{{"records", rec}}), doctest::Contains("/dynamic: missing required key \"k\""), InputError);
  CHECK_THROWS_WITH_AS(parse(json{{"k", 1e6}}), doctest::Contains("records"), InputError);
  CHECK_THROWS_WITH_AS(parse(json{{"k", -5.0}, {"records", rec}}), doctest::Contains("kN/m3"), InputError);
}
