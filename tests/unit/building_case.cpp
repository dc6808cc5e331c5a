// Issue 22: the building case file: expansion into single cases (merge-patch
// overrides, FC/knowledge level, "dynamic": null), ids and paths, the shared
// record selection (union of the members' ranges, written into each expanded
// case; fall-back to own ranges), error paths in the building file, and the
// NTC 2008 PGA capacity of the safety indices (docs/theory/building.md §2-4).
#include <doctest/doctest.h>

#include <assess/assessment/building_assessment.hpp>
#include <assess/assessment/building_case.hpp>
#include <assess/kinematic/code_checks.hpp>
#include <assess/hazard/site.hpp>
#include <assess/support/error.hpp>

#include <cmath>
#include <string>

using namespace assess;
using nlohmann::json;

namespace {

json storey_mech(int hinge) {
  return json::parse(R"({"type": "simple_overturning", "storeys": [
    {"height": 4.0, "thickness": 0.6, "floor_weight": 40.0, "floor_distance_from_inner_face": 0.2},
    {"height": 3.5, "thickness": 0.45, "floor_weight": 25.0, "floor_distance_from_inner_face": 0.15}],
    "unit_weight": 20.0, "length": 8.0, "hinge_level": )" + std::to_string(hinge) + "}");
}

json building_doc() {
  json d = json::parse(R"({
    "project": "Test house",
    "site": {"lat": 42.35, "lon": 13.40, "soil": "B"},
    "building": {"height_m": 7.5, "storeys": 2},
    "knowledge_level": "LC2",
    "dynamic": {"model": "rigid", "restitution": [-0.5], "select": {"count": 7}},
    "walls": [
      {"name": "Front", "mechanisms": [{"name": "ground"}, {"name": "first floor"}]},
      {"name": "Side", "FC": 1.1, "dynamic": {"restitution": [-0.6]},
       "mechanisms": [{"name": "side, no dynamics", "dynamic": null, "codes": ["NTC2018"]}]}
    ]})");
  d["walls"][0]["mechanisms"][0]["mechanism"] = storey_mech(0);
  d["walls"][0]["mechanisms"][1]["mechanism"] = storey_mech(1);
  d["walls"][1]["mechanisms"][0]["mechanism"] = storey_mech(0);
  return d;
}

}  // namespace

TEST_CASE("building documents are told from single cases by the key walls") {
  CHECK(is_building_document(building_doc()));
  CHECK_FALSE(is_building_document(json::parse(R"({"mechanism": {"type": "simple_overturning"}})")));
  CHECK_FALSE(is_building_document(json::array()));
}

TEST_CASE("each mechanism expands into its single case: shared keys, wall overrides, mechanism overrides") {
  const BuildingCase b = parse_building(building_doc(), "house.json");
  REQUIRE(b.mechanisms.size() == 3);
  CHECK(b.mechanisms[0].id == "M1");
  CHECK(b.mechanisms[2].id == "M3");
  CHECK(b.mechanisms[1].json_path == "/walls/0/mechanisms/1");
  CHECK(b.mechanisms[2].wall == "Side");
  const json& x0 = b.mechanisms[0].expanded;
  CHECK(x0.at("project") == "Test house — Front: ground");
  CHECK(x0.at("knowledge_level") == "LC2");
  CHECK(x0.at("mechanism") == storey_mech(0));
  CHECK(x0.at("dynamic").at("model") == "rigid");
  CHECK(b.mechanisms[0].kase.options.FC == doctest::Approx(1.20));
  // The wall's FC replaces the building's knowledge level; the mechanism's
  // "dynamic": null deletes the dynamic section; "codes" replaced.
  const json& x2 = b.mechanisms[2].expanded;
  CHECK_FALSE(x2.contains("knowledge_level"));
  CHECK(x2.at("FC") == 1.1);
  CHECK_FALSE(x2.contains("dynamic"));
  CHECK(x2.at("codes") == json::array({"NTC2018"}));
  CHECK(b.mechanisms[2].kase.options.FC == doctest::Approx(1.1));
  CHECK(b.mechanisms[2].record_set == RecordSetKind::none);
}

TEST_CASE("a wall's partial dynamic section merges key by key (JSON merge patch)") {
  json d = building_doc();
  d["walls"][1]["mechanisms"][0].erase("dynamic");
  const BuildingCase b = parse_building(d, "house.json");
  const json& dyn = b.mechanisms[2].expanded.at("dynamic");
  CHECK(dyn.at("model") == "rigid");                       // the building's
  CHECK(dyn.at("restitution") == json::array({-0.6}));      // the wall's
  CHECK(dyn.at("select").at("count") == 7);                 // the building's
}

TEST_CASE("the mechanisms with the same selection share one range: the union of their own, written in each case") {
  const BuildingCase b = parse_building(building_doc(), "house.json");
  REQUIRE(b.selections.size() == 1);
  const SharedSelection& s = b.selections[0];
  REQUIRE(s.members.size() == 2);
  const BuildingMechanism& m1 = b.mechanisms[0];
  const BuildingMechanism& m2 = b.mechanisms[1];
  CHECK(m1.record_set == RecordSetKind::shared);
  CHECK(m1.record_group == "S1");
  CHECK(s.T_min == std::min(m1.own_T_min, m2.own_T_min));
  CHECK(s.T_max == std::max(m1.own_T_max, m2.own_T_max));
  CHECK(m1.own_T_min != m2.own_T_min);  // different mechanisms, different ranges
  const json pr = json::array({s.T_min, s.T_max});
  CHECK(m1.expanded.at("dynamic").at("select").at("period_range_s") == pr);
  CHECK(m2.expanded.at("dynamic").at("select").at("period_range_s") == pr);
  // The written range survives the file: the standalone case parses to the same doubles.
  const json re = json::parse(standalone_case(b, m1).dump());
  CHECK(re.at("dynamic").at("select").at("period_range_s").at(0).get<double>() == s.T_min);
  CHECK(re.at("dynamic").at("select").at("period_range_s").at(1).get<double>() == s.T_max);

  BuildingCase c = b;
  fall_back_to_own_selection(c, 0);
  CHECK(c.selections[0].fell_back);
  CHECK(c.mechanisms[0].record_set == RecordSetKind::own);
  CHECK_FALSE(c.mechanisms[0].expanded.at("dynamic").at("select").contains("period_range_s"));

  json d = building_doc();
  d["record_selection"] = "per_mechanism";
  const BuildingCase p = parse_building(d, "house.json");
  CHECK(p.selections.empty());
  CHECK(p.mechanisms[0].record_set == RecordSetKind::own);
  CHECK_FALSE(p.mechanisms[0].expanded.at("dynamic").at("select").contains("period_range_s"));
}

TEST_CASE("errors and warnings name the path in the building file") {
  const BuildingCase b = parse_building(building_doc(), "house.json");
  const BuildingMechanism& m2 = b.mechanisms[1];
  CHECK(building_path_message(b, m2, "house.json: /mechanism/storeys/0/thickness: bad") ==
        "house.json: /walls/0/mechanisms/1/mechanism/storeys/0/thickness: bad [M2 \"first floor\"]");
  CHECK(building_path_message(b, m2, "house.json: /dynamic/model: bad") ==
        "house.json: /dynamic/model: bad [M2 \"first floor\"]");
  CHECK(building_path_message(b, b.mechanisms[2], "house.json: /FC: bad") ==
        "house.json: /walls/1/FC: bad [M3 \"side, no dynamics\"]");

  json d = building_doc();
  d["walls"][0]["mechanisms"][1]["mechanism"]["storeys"][1]["height"] = -1.0;
  try {
    parse_building(d, "house.json");
    FAIL("no error");
  } catch (const InputError& e) {
    const std::string what = e.what();
    CAPTURE(what);
    CHECK(what.find("house.json: /walls/0/mechanisms/1/mechanism/storeys/1/height") == 0);
    CHECK(what.find("m") != std::string::npos);
  }
  d = building_doc();
  d["walls"][1]["mechanisms"][0]["name"] = "ground";
  CHECK_THROWS_WITH_AS(parse_building(d, "house.json"), doctest::Contains("/walls/1/mechanisms/0/name"), InputError);
  d = building_doc();
  d["walls"][0]["bogus"] = 1;
  CHECK_THROWS_WITH_AS(parse_building(d, "house.json"), doctest::Contains("/walls/0: unknown key \"bogus\""),
                       InputError);
}

TEST_CASE("safety indices (issue 41): each check reaches D/C = 1 at its own TR_C; the approach's is the lowest") {
  json d = building_doc();
  d.erase("dynamic");
  d["walls"][1]["mechanisms"][0].erase("codes");
  const BuildingCase b = parse_building(d, "house.json");
  constexpr double tol_dc = 1e-9;  // D/C (-) re-run at TR_C: Brent's tolerance 1e-12 on ln TR
  for (const BuildingMechanism& m : b.mechanisms) {
    const FacadeAssessment a = assess_facade(m.kase);
    const Site site(*m.kase.site);
    for (const SafetyIndex& s : a.indices) {
      if (!s.defined) continue;
      const std::string label = m.id + " " + s.code + " " + s.approach;
      CAPTURE(label);
      CHECK(s.index.zeta == doctest::Approx(s.index.ag_capacity_g / s.index.ag_demand_g).epsilon(1e-14));
      CHECK((s.index.zeta < 1.0) == (s.dc > 1.0));
      // Every check of the approach has an index >= zetaE (it is the lowest), and
      // re-run with the site's whole hazard at its TR_C its D/C is 1.
      for (const CandidateResult& cr : a.kinematic.candidates)
        for (const CheckRow& r : cr.checks) {
          if (r.code != s.code || r.kind != s.approach) continue;
          REQUIRE(r.index.defined);
          CHECK(r.index.zeta >= s.index.zeta);
          CHECK((r.index.zeta < 1.0) == (r.dc > 1.0));
          if (r.index.bound != 0) continue;
          CheckInput in = *a.kinematic.check_input;
          in.Z = cr.Z;
          in.hazard[parse_limit_state(r.limit_state)] = site.hazard_extrapolated(r.index.TR_capacity);
          bool found = false;
          for (const CheckRow& x : run_code_checks(cr.result, in))
            if (x.code == r.code && x.limit_state == r.limit_state && x.kind == r.kind && x.location == r.location) {
              found = true;
              CHECK(x.dc == doctest::Approx(1.0).epsilon(tol_dc));
            }
          CHECK(found);
        }
    }
  }
}

TEST_CASE("a building of more than 1000 mechanisms is refused before any analysis") {
  json d = building_doc();
  json entry = d["walls"][0]["mechanisms"][0];
  json many = json::array();
  for (int i = 0; i < 1001; ++i) {
    entry["name"] = "m" + std::to_string(i);
    many.push_back(entry);
  }
  d["walls"][0]["mechanisms"] = many;
  CHECK_THROWS_WITH_AS(parse_building(d, "house.json"),
                       doctest::Contains("house.json: /walls/0/mechanisms/1000: more than 1000 mechanisms"), InputError);
}

// Hostile values at every place of a building file: each parse either
// succeeds or throws InputError naming the file (never another exception).
namespace {
void leaf_paths(const json& j, const std::string& path, std::vector<std::string>& out) {
  if (j.is_object()) {
    for (auto it = j.begin(); it != j.end(); ++it) leaf_paths(it.value(), path + "/" + it.key(), out);
  } else if (j.is_array()) {
    for (std::size_t i = 0; i < j.size(); ++i) leaf_paths(j[i], path + "/" + std::to_string(i), out);
  }
  out.push_back(path);
}
}  // namespace

TEST_CASE("hostile values anywhere in a building file give an InputError naming the file, or a valid case") {
  const json base = building_doc();
  std::vector<std::string> paths;
  leaf_paths(base, "", paths);
  const std::vector<json> hostile = {json(nullptr), json(-1.0), json(1e308), json("x"), json::array(), json::object()};
  int parsed = 0, refused = 0;
  for (const std::string& p : paths) {
    if (p.empty()) continue;
    for (const json& v : hostile) {
      json d = base;
      d[json::json_pointer(p)] = v;
      try {
        const BuildingCase b = parse_building(d, "hostile.json");
        ++parsed;
        CHECK(!b.mechanisms.empty());
      } catch (const InputError& e) {
        ++refused;
        const std::string what = e.what();
        CAPTURE(p);
        CAPTURE(what);
        CHECK(what.rfind("hostile.json", 0) == 0);
      }
    }
  }
  MESSAGE(parsed << " hostile variants parsed, " << refused << " refused");
  CHECK(refused > 100);
}

// Issues 23, 37: a wall's "ties" and "design" levels go to every mechanism of
// the wall whose moving blocks they cross (and to no other); a mechanism's own
// "ties" are added to them; a mechanism of a wall with a design cannot give
// its own (nor null); errors name the path in the building file
// (docs/theory/building.md §8).
TEST_CASE("tie rods in a building: a wall's ties and design reach every mechanism of the wall they cross") {
  json d = building_doc();
  d.erase("dynamic");  // kinematic only: no record selection pre-pass
  const json masonry = {{"fm_MPa", 2.0}, {"tau_MPa", 0.035}, {"thickness_m", 0.45}};
  json level = {{"name", "eaves"}, {"point", {0.0, 7.3}}, {"free_length_m", 9.0}, {"masonry", masonry},
                {"wall_length_m", 8.0}, {"spacing_m", 2.5}};
  json low = level;  // at 3.0 m: below the first floor, it crosses the ground mechanism only
  low["name"] = "low";
  low["point"] = {0.0, 3.0};
  d["walls"][0]["design"] = {{"ties", {{"levels", {level, low}}, {"grades", {"S275", "S355"}}}}};
  json given = level;
  given["name"] = "existing";
  given["existing"] = true;  // issue 29: part of the stato di fatto (it acts in the mechanism's own analyses)
  given["rod"] = {{"diameter_mm", 16}};
  given["anchor"] = {{"type", "plate"}, {"a_mm", 200}, {"t_mm", 15}};
  d["walls"][0]["ties"] = json::array({given});
  json own = given;  // a tie of the first-floor mechanism only
  own["name"] = "own";
  own["point"] = {0.0, 6.0};
  d["walls"][0]["mechanisms"][1]["ties"] = json::array({own});
  const BuildingCase b = parse_building(d, "house.json");
  REQUIRE(b.mechanisms.size() == 3);
  // M1 (hinge at the foot): the wall's existing tie and both design levels.
  const auto& m1 = b.mechanisms[0];
  CHECK(m1.wall_ties);
  REQUIRE(m1.kase.tie_design.has_value());
  REQUIRE(m1.kase.tie_design->levels.size() == 2);
  CHECK(m1.kase.tie_design->levels[1].point.y() == doctest::Approx(3.0).epsilon(1e-15));
  REQUIRE(m1.kase.ties.size() == 1);
  CHECK(m1.kase.ties[0].name == "existing");
  CHECK(m1.tie_origin == std::vector<std::string>{"/walls/0/ties/0"});
  CHECK(m1.design_origin == std::vector<std::string>{"/walls/0/design/ties/levels/0", "/walls/0/design/ties/levels/1"});
  // The crown defaults to the top of the block the tie holds: 7.5 m in both mechanisms.
  CHECK(m1.kase.ties[0].layout.crown == doctest::Approx(7.5).epsilon(1e-15));
  // M2 (hinge at the first floor, 4.0 m): the existing tie and the eaves level cross it, the low level does not;
  // its own tie is added after the wall's (Ø16: A = pi 16^2 / 4 mm^2).
  const auto& m2 = b.mechanisms[1];
  CHECK(m2.wall_ties);
  REQUIRE(m2.kase.tie_design.has_value());
  REQUIRE(m2.kase.tie_design->levels.size() == 1);
  CHECK(m2.kase.tie_design->levels[0].name == "eaves");
  REQUIRE(m2.kase.ties.size() == 2);
  CHECK(m2.kase.ties[0].name == "existing");
  CHECK(m2.kase.ties[1].name == "own");
  CHECK(m2.kase.ties[1].rod.area == doctest::Approx(std::acos(-1.0) * 0.016 * 0.016 / 4.0).epsilon(1e-14));
  CHECK(m2.tie_origin == std::vector<std::string>{"/walls/0/ties/0", "/walls/0/mechanisms/1/ties/0"});
  CHECK(m2.design_origin == std::vector<std::string>{"/walls/0/design/ties/levels/0"});
  // M3 (another wall): none.
  CHECK_FALSE(b.mechanisms[2].wall_ties);
  CHECK_FALSE(has_ties(b.mechanisms[2].kase));
  // An error in a tie a mechanism took from its wall names the wall's path.
  {
    json bad = d;
    bad["walls"][0]["ties"][0]["rod"]["grade"] = "S420";
    try {
      parse_building(bad, "house.json");
      FAIL("a bad grade was accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find("house.json: /walls/0/ties/0/rod/grade") != std::string::npos);
    }
  }
  // A mechanism of a wall with a design cannot give its own, nor null.
  for (const json& v : {json(nullptr), d["walls"][0]["design"]}) {
    json bad = d;
    bad["walls"][0]["mechanisms"][1]["design"] = v;
    try {
      parse_building(bad, "house.json");
      FAIL("a mechanism's design in a wall with a design was accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find("house.json: /walls/0/mechanisms/1/design: the wall gives a \"design\"") !=
            std::string::npos);
    }
  }
  // A wall's level that crosses no mechanism of the wall.
  {
    json bad = d;
    bad["walls"][0]["ties"][0]["point"] = {0.0, 9.0};
    try {
      parse_building(bad, "house.json");
      FAIL("a wall tie crossing no mechanism was accepted");
    } catch (const InputError& e) {
      CHECK(std::string(e.what()).find("house.json: /walls/0/ties/0/point: the anchor point is on no moving block of any "
                                       "mechanism of the wall") != std::string::npos);
    }
  }

  // Not at the building level: the message says why.
  json top = building_doc();
  top.erase("dynamic");
  top["design"] = d["walls"][0]["design"];
  try {
    parse_building(top, "house.json");
    FAIL("a building-level design was accepted");
  } catch (const InputError& e) {
    CHECK(std::string(e.what()).find("house.json: /design: \"design\" is not a building-wide key") != std::string::npos);
  }
  // A bad value in the wall's design is reported at the wall's path, for the mechanism that uses it.
  d["walls"][0]["design"]["ties"]["levels"][0]["spacing_m"] = 0;
  try {
    parse_building(d, "house.json");
    FAIL("a zero spacing was accepted");
  } catch (const InputError& e) {
    const std::string m = e.what();
    CHECK(m.find("house.json: /walls/0/design/ties/levels/0/spacing_m: value 0 out of range: expected in [0.1, 500] m") !=
          std::string::npos);
    CHECK(m.find("[M1 \"ground\"]") != std::string::npos);
  }
}
