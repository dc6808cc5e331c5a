// building_case.cpp: the building case file and its expansion into
// single-mechanism cases (docs/user/building.md; docs/theory/building.md §2-3).
#include "assess/assessment/building_case.hpp"

#include "assess/assessment/dynamic_case.hpp"
#include "assess/assessment/facade_assessment.hpp"
#include "assess/assessment/mechanism_dynamics.hpp"
#include "assess/hazard/hazard.hpp"
#include "assess/records/record_selection.hpp"
#include "assess/support/error.hpp"
#include "assess/support/json_input.hpp"
#include "assess/kinematic/tie.hpp"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <map>
#include <set>

namespace assess {

namespace {

// The keys a wall or a mechanism entry may override (the case keys but the site:
// one building stands on one site). "ties" and "design" (issues 23, 37) are
// given in a wall or a mechanism only, and are not overrides: a wall's levels
// go to the mechanisms they cross (wall_ties below); a mechanism's own "ties"
// are added to them (docs/user/building.md, Tie rods).
constexpr std::initializer_list<const char*> override_keys = {"knowledge_level", "FC", "codes", "method", "check_SLD",
                                                               "building", "analysis", "dynamic"};

std::string directory_of(const std::string& path) {
  const auto p = path.find_last_of('/');
  return p == std::string::npos ? "." : path.substr(0, p);
}

// Merges the overrides of `over` (a wall or a mechanism entry) into `into`:
// JSON merge patch per key (RFC 7386), and "FC" and "knowledge_level"
// replace each other (a case gives one of them).
void apply_overrides(nlohmann::json& into, const nlohmann::json& over) {
  for (const char* k : override_keys) {
    if (!over.contains(k)) continue;
    if (std::string(k) == "FC") into.erase("knowledge_level");
    if (std::string(k) == "knowledge_level") into.erase("FC");
    nlohmann::json patch = nlohmann::json::object();
    patch[k] = over.at(k);
    into.merge_patch(patch);
  }
}

bool contains_pointer(const nlohmann::json& j, const std::string& path) {
  try {
    return j.contains(nlohmann::json::json_pointer(path));
  } catch (const nlohmann::json::exception&) {
    return false;
  }
}

std::string first_token(const std::string& path) {
  const auto e = path.find('/', 1);
  return path.substr(1, e == std::string::npos ? std::string::npos : e - 1);
}

// The building-file path of a path of the expanded case.
// The index after `prefix` in `path` ("/ties/3/rod" -> 3, rest "/rod"), or -1.
long index_after(const std::string& path, const std::string& prefix, std::string& rest) {
  if (path.compare(0, prefix.size(), prefix) != 0) return -1;
  std::size_t i = prefix.size(), j = i;
  while (j < path.size() && std::isdigit(static_cast<unsigned char>(path[j]))) ++j;
  if (j == i) return -1;
  rest = path.substr(j);
  return std::stol(path.substr(i, j - i));
}

std::string origin(const BuildingCase& b, const BuildingMechanism& m, const std::string& path) {
  const nlohmann::json& wall = b.doc.at("walls").at(m.wall_index);
  const nlohmann::json& entry = wall.at("mechanisms").at(m.index);
  const std::string wall_path = "/walls/" + std::to_string(m.wall_index);
  // Issue 37: the tie levels of the expanded case come from the wall or the entry.
  std::string rest;
  long k = index_after(path, "/ties/", rest);
  if (k >= 0 && static_cast<std::size_t>(k) < m.tie_origin.size()) return m.tie_origin[std::size_t(k)] + rest;
  k = index_after(path, "/design/ties/levels/", rest);
  if (k >= 0 && static_cast<std::size_t>(k) < m.design_origin.size()) return m.design_origin[std::size_t(k)] + rest;
  if (path.compare(0, 7, "/design") == 0 && wall.contains("design")) return wall_path + path;
  if (path == "/ties" && wall.contains("ties") && !entry.contains("ties")) return wall_path + path;
  if (path == "/project") return m.json_path + "/name";
  if (contains_pointer(entry, path)) return m.json_path + path;
  if (contains_pointer(wall, path) && first_token(path) != "mechanisms" && first_token(path) != "name")
    return wall_path + path;
  if (contains_pointer(b.doc, path)) return path;
  const std::string t = first_token(path);
  if (entry.contains(t)) return m.json_path + path;
  if (wall.contains(t) && t != "mechanisms" && t != "name") return wall_path + path;
  return path;
}

// Parses an expanded case; its errors name the building file's paths.
CaseFile parse_expanded(const BuildingCase& b, const BuildingMechanism& m) {
  try {
    return parse_case(m.expanded, b.file);
  } catch (const InputError& e) {
    throw InputError(building_path_message(b, m, e.what()));
  }
}

// "M" followed by decimal digits (the form of a mechanism id).
bool is_mechanism_id(const std::string& s) {
  if (s.size() < 2 || s[0] != 'M') return false;
  return std::all_of(s.begin() + 1, s.end(), [](char c) { return c >= '0' && c <= '9'; });
}

}  // namespace

bool is_building_document(const nlohmann::json& doc) { return doc.is_object() && doc.contains("walls"); }

std::string to_string(RecordSetKind k) {
  switch (k) {
    case RecordSetKind::none: return "none";
    case RecordSetKind::listed: return "listed";
    case RecordSetKind::shared: return "shared";
    case RecordSetKind::own: return "own";
  }
  return "none";
}

std::string building_path_message(const BuildingCase& b, const BuildingMechanism& m, const std::string& message) {
  const std::string prefix = b.file + ": /";
  std::string out;
  std::size_t pos = 0;
  // Every "<file>: /path" in the message (a warning may name several).
  while (true) {
    const std::size_t at = message.find(prefix, pos);
    if (at == std::string::npos) break;
    std::size_t end = at + prefix.size() - 1;
    while (end < message.size() && (std::isalnum(static_cast<unsigned char>(message[end])) || message[end] == '/' ||
                                    message[end] == '_'))
      ++end;
    const std::string path = message.substr(at + b.file.size() + 2, end - (at + b.file.size() + 2));
    const std::string where = origin(b, m, path);
    out += message.substr(pos, at - pos) + b.file + ": " + where;
    // A key the building gives but this wall or mechanism sets to null
    // (RFC 7386: null removes it): say so, or "/dynamic: missing" reads as false.
    if (contains_pointer(b.doc, where) && b.doc.at(nlohmann::json::json_pointer(where)).is_null())
      out += " (set to null there, which removes the building's value for this mechanism)";
    pos = end;
  }
  out += message.substr(pos);
  // Name the mechanism for the reader.
  return out + " [" + m.id + " \"" + m.name + "\"]";
}

namespace {

// Issue 37: each tie level given on a wall (its "ties", and the levels of its
// "design") goes to every mechanism of the wall whose moving blocks it
// crosses (a candidate's chain holds its anchor point); a level that crosses
// none is an error. A wall's design with no level to design (the least change
// to its existing ties) goes to the mechanisms that hold an existing tie. The
// same level must meet the same wall in every mechanism (its crown and
// masonry, which default to the block it holds): otherwise give them.
void distribute_wall_ties(BuildingCase& b) {
  const JsonNode root(b.doc, b.file);
  const std::vector<JsonNode> walls = root.array("walls", 1);
  for (std::size_t wi = 0; wi < walls.size(); ++wi) {
    const JsonNode& w = walls[wi];
    if (!w.find("ties") && !w.find("design")) continue;
    const std::string wall_path = "/walls/" + std::to_string(wi);
    const nlohmann::json ties = w.find("ties") && !w.value().at("ties").is_null() ? w.value().at("ties") : nlohmann::json();
    const nlohmann::json design = w.find("design") ? w.value().at("design") : nlohmann::json();
    if (!ties.is_null() && !ties.is_array()) w.at("ties").fail("expected an array of tie levels");
    if (!design.is_null() && !(design.is_object() && design.contains("ties") && design["ties"].is_object()))
      w.at("design").fail("expected {\"ties\": {...}}");
    const nlohmann::json levels = design.is_null() || !design["ties"].contains("levels") ? nlohmann::json::array()
                                                                                         : design["ties"]["levels"];
    if (!levels.is_array()) w.at("design").at("ties").at("levels").fail("expected an array of tie levels");
    // Whether level j (a JSON tie) crosses a moving block of mechanism m.
    auto crosses = [&](const BuildingMechanism& m, const JsonNode& node) {
      if (!node.is_object()) node.fail("expected an object (a tie level)");
      const Eigen::Vector2d p = node.point("point");
      const int block = node.find("block") ? node.integer("block", 0, 1000000) : -1;
      for (const MechanismCandidate& c : m.kase.mechanism.candidates) {
        if (block >= static_cast<int>(c.chain.blocks().size())) continue;
        if (block >= 0 && !c.chain.contains(block, p)) continue;
        if (tie_block(c.chain, block, p) >= 0) return true;
      }
      return false;
    };
    std::vector<bool> tie_used(ties.is_array() ? ties.size() : 0, false), level_used(levels.size(), false);
    for (BuildingMechanism& m : b.mechanisms) {
      if (m.wall_index != wi) continue;
      nlohmann::json own = m.expanded.contains("ties") ? m.expanded["ties"] : nlohmann::json::array();
      nlohmann::json mine = nlohmann::json::array();
      std::vector<std::string> origins;
      bool existing = false;
      for (std::size_t j = 0; j < tie_used.size(); ++j) {
        const JsonNode node = w.at("ties").at(j);
        if (!crosses(m, node)) continue;
        tie_used[j] = true;
        mine.push_back(ties[j]);
        origins.push_back(wall_path + "/ties/" + std::to_string(j));
        existing = existing || (ties[j].is_object() && ties[j].value("existing", false));
      }
      for (std::size_t j = 0; j < own.size(); ++j) {
        mine.push_back(own[j]);
        origins.push_back(j < m.tie_origin.size() ? m.tie_origin[j] : m.json_path + "/ties/" + std::to_string(j));
        existing = existing || (own[j].is_object() && own[j].value("existing", false));
      }
      nlohmann::json dlevels = nlohmann::json::array();
      std::vector<std::string> dorigins;
      for (std::size_t j = 0; j < levels.size(); ++j) {
        const JsonNode node = w.at("design").at("ties").at("levels").at(j);
        if (!crosses(m, node)) continue;
        level_used[j] = true;
        dlevels.push_back(levels[j]);
        dorigins.push_back(wall_path + "/design/ties/levels/" + std::to_string(j));
      }
      const bool takes = !mine.empty() && mine.size() > own.size();
      const bool designs = !design.is_null() && (!dlevels.empty() || (levels.empty() && existing));
      if (!takes && !designs) continue;
      m.wall_ties = true;
      if (!mine.empty()) m.expanded["ties"] = mine;
      m.tie_origin = origins;
      if (designs) {
        nlohmann::json d = design;
        d["ties"]["levels"] = dlevels;
        m.expanded["design"] = d;
        m.design_origin = dorigins;
      }
      m.kase = parse_expanded(b, m);
    }
    for (std::size_t j = 0; j < tie_used.size(); ++j)
      if (!tie_used[j])
        w.at("ties").at(j).at("point").fail("the anchor point is on no moving block of any mechanism of the wall "
                                            "(a wall's tie acts on the mechanisms whose moving blocks it crosses)");
    for (std::size_t j = 0; j < level_used.size(); ++j)
      if (!level_used[j])
        w.at("design").at("ties").at("levels").at(j).at("point").fail(
            "the anchor point is on no moving block of any mechanism of the wall (a wall's tie acts on the "
            "mechanisms whose moving blocks it crosses)");
    // One wall: the same level meets the same crown and masonry in every mechanism.
    std::map<std::string, std::pair<const BuildingMechanism*, Tie>> seen;
    for (const BuildingMechanism& m : b.mechanisms) {
      if (m.wall_index != wi || !m.wall_ties) continue;
      std::vector<const Tie*> all;
      for (const Tie& t : m.kase.ties) all.push_back(&t);
      for (const Tie& t : m.kase.new_ties) all.push_back(&t);
      if (m.kase.tie_design)
        for (const Tie& t : m.kase.tie_design->levels) all.push_back(&t);
      for (const Tie* t : all) {
        const auto it = seen.find(t->name);
        if (it == seen.end()) {
          seen.emplace(t->name, std::make_pair(&m, *t));
          continue;
        }
        const Tie& u = it->second.second;
        if (u.layout.crown != t->layout.crown || u.masonry.unit_weight != t->masonry.unit_weight)
          w.fail("the tie level \"" + t->name + "\" meets a different wall in " + it->second.first->id + " (crown z = " +
                 std::to_string(u.layout.crown) + " m) and in " + m.id + " (crown z = " +
                 std::to_string(t->layout.crown) +
                 " m), which default to the top of the block it holds: give \"crown_z_m\" (and "
                 "\"masonry\"/\"unit_weight_kN_m3\") on the level");
      }
    }
  }
}

}  // namespace

BuildingCase parse_building(const nlohmann::json& doc, const std::string& file) {
  BuildingCase b;
  b.file = file;
  b.doc = doc;
  const JsonNode root(b.doc, file);
  if (!root.is_object()) root.fail("expected an object (a building case file)");
  for (const char* k : {"ties", "design"})
    if (root.find(k))
      root.at(k).fail(std::string("\"") + k +
                      "\" is not a building-wide key: tie anchor points are in each mechanism's own coordinates; give "
                      "it in a wall (its mechanisms) or a mechanism (docs/user/building.md, Tie rods)");
  root.allow_only({"schema_version", "project", "site", "building", "knowledge_level", "FC", "codes", "method",
                   "check_SLD", "analysis", "dynamic", "walls", "record_selection", "report"});
  if (root.find("schema_version")) root.integer("schema_version", 1, 1);
  b.project = root.find("project") ? root.string("project") : "";
  if (!root.has("site"))
    root.fail("missing required key \"site\": the building's site, checked against by every mechanism "
              "(\"comune\", \"lat\"/\"lon\" in deg, \"island\" or \"hazard\"; docs/user/building.md)");
  if (root.find("record_selection")) b.record_selection = root.choice("record_selection", {"shared", "per_mechanism"});
  if (root.find("FC") && root.find("knowledge_level")) root.fail("give \"knowledge_level\" or \"FC\", not both");

  nlohmann::json base = b.doc;
  base.erase("walls");
  base.erase("record_selection");
  base.erase("project");

  std::set<std::string> names;
  const std::vector<JsonNode> walls = root.array("walls", 1);
  for (std::size_t wi = 0; wi < walls.size(); ++wi) {
    const JsonNode& w = walls[wi];
    if (!w.is_object()) w.fail("expected an object {\"name\", \"mechanisms\": [...]}");
    w.allow_only({"name", "mechanisms", "knowledge_level", "FC", "codes", "method", "check_SLD", "building",
                  "analysis", "dynamic", "ties", "design"});
    const std::string wall_name = w.string("name");
    if (w.find("FC") && w.find("knowledge_level")) w.fail("give \"knowledge_level\" or \"FC\", not both");
    const std::vector<JsonNode> ms = w.array("mechanisms", 1);
    for (std::size_t mi = 0; mi < ms.size(); ++mi) {
      const JsonNode& e = ms[mi];
      if (b.mechanisms.size() >= building_max_mechanisms)
        e.fail("more than " + std::to_string(building_max_mechanisms) +
               " mechanisms in the building: split it into several building cases");
      if (!e.is_object()) e.fail("expected an object {\"name\", \"mechanism\": {...}}");
      e.allow_only({"name", "mechanism", "knowledge_level", "FC", "codes", "method", "check_SLD", "building",
                    "analysis", "dynamic", "ties", "design"});
      BuildingMechanism m;
      m.name = e.string("name");
      if (m.name.empty()) e.at("name").fail("expected a non-empty name");
      if (!names.insert(m.name).second)
        e.at("name").fail("\"" + m.name + "\": another mechanism of the building has this name (names must be unique)");
      // A name that reads as another mechanism's id (M1, M2, ... in the file's
      // order) would make `--mechanism M2` ambiguous: ids win, so such a name
      // is refused rather than silently shadowed.
      if (is_mechanism_id(m.name) && m.name != "M" + std::to_string(b.mechanisms.size() + 1))
        e.at("name").fail("\"" + m.name + "\" reads as the id of another mechanism (this is mechanism M" +
                          std::to_string(b.mechanisms.size() + 1) +
                          "; ids M1, M2, ... number the mechanisms in the file's order and --mechanism matches "
                          "an id first): choose a descriptive name");
      if (!e.at("mechanism").is_object()) e.at("mechanism").fail("expected an object (a mechanism, docs/catalogue.md)");
      if (e.find("FC") && e.find("knowledge_level")) e.fail("give \"knowledge_level\" or \"FC\", not both");
      m.wall = wall_name;
      m.wall_index = wi;
      m.index = mi;
      m.id = "M" + std::to_string(b.mechanisms.size() + 1);
      m.json_path = e.path();
      nlohmann::json x = base;
      apply_overrides(x, w.value());
      apply_overrides(x, e.value());
      x["mechanism"] = e.value().at("mechanism");
      x["project"] = (b.project.empty() ? std::string() : b.project + " — ") + wall_name + ": " + m.name;
      // The mechanism's own ties and design (the wall's are added below, once
      // the mechanism's chains are known).
      if (e.value().contains("design") && w.value().contains("design") && !w.value().at("design").is_null())
        e.at("design").fail("the wall gives a \"design\" of ties: it acts on every mechanism of the wall whose moving "
                            "blocks its levels cross (issue 37), so a mechanism of that wall cannot give its own (nor "
                            "null); give the design on the wall or on the mechanisms only");
      if (e.find("ties") && !e.value().at("ties").is_null()) {
        x["ties"] = e.value().at("ties");
        for (std::size_t i = 0; i < x["ties"].size(); ++i)
          m.tie_origin.push_back(m.json_path + "/ties/" + std::to_string(i));
      }
      if (e.find("design") && !e.value().at("design").is_null()) {
        x["design"] = e.value().at("design");
        const nlohmann::json& dl = x["design"];
        if (dl.is_object() && dl.contains("ties") && dl["ties"].is_object() && dl["ties"].contains("levels") &&
            dl["ties"]["levels"].is_array())
          for (std::size_t i = 0; i < dl["ties"]["levels"].size(); ++i)
            m.design_origin.push_back(m.json_path + "/design/ties/levels/" + std::to_string(i));
      }
      // The expanded case in the order of a case file (nlohmann sorts keys; kept for diffing).
      m.expanded = std::move(x);
      b.mechanisms.push_back(std::move(m));
    }
  }
  for (BuildingMechanism& m : b.mechanisms) m.kase = parse_expanded(b, m);
  distribute_wall_ties(b);
  b.report = b.mechanisms.front().kase.report;  // "report" is building-wide: every expanded case holds it

  // Record sets (docs/theory/building.md §3): mechanisms selecting with the
  // same settings and no range of their own share one selection over the
  // union of their ranges (ground records; floor records are listed).
  std::map<std::string, std::vector<std::size_t>> groups;
  std::vector<std::string> group_order;
  for (std::size_t i = 0; i < b.mechanisms.size(); ++i) {
    BuildingMechanism& m = b.mechanisms[i];
    const nlohmann::json& dyn = m.expanded.contains("dynamic") ? m.expanded.at("dynamic") : nlohmann::json();
    if (!dyn.is_object()) continue;
    if (!dyn.contains("select")) {
      m.record_set = RecordSetKind::listed;
      continue;
    }
    const DynamicSpec d = [&] {
      try {
        return parse_dynamic(m.kase.dynamic, b.file, directory_of(b.file));
      } catch (const InputError& err) {
        throw InputError(building_path_message(b, m, err.what()));
      }
    }();
    KinematicCaseResult kr;
    try {
      kr = run_kinematic_case(m.kase, false);  // the governing candidate's periods: no safety indices
    } catch (const InputError& err) {
      throw InputError(building_path_message(b, m, err.what()));
    }
    const CandidateResult& gov = kr.candidates[kr.governing];
    // Its errors (a restitution against the sidedness, a Winkler modulus)
    // name the building's paths and the mechanism, as every other error.
    const MechanismDynamics md = [&] {
      try {
        return build_mechanism_dynamics(m.kase, gov, m.kase.mechanism.candidates[kr.governing].chain, d);
      } catch (const InputError& err) {
        throw InputError(building_path_message(b, m, err.what()));
      }
    }();
    if (!md.applies) continue;  // reported by the run ("not applicable")
    const double T1 = std::min(gov.result.Ts, gov.result.T_SLV), T2 = std::max(gov.result.Ts, gov.result.T_SLV);
    const PeriodRange r = rocking_period_range(T1, T2);
    m.own_T_min = r.T_min;
    m.own_T_max = r.T_max;
    m.record_set = RecordSetKind::own;
    if (b.record_selection != "shared" || dyn.at("select").contains("period_range_s")) continue;
    const std::string key = dyn.at("select").dump();
    if (!groups.count(key)) group_order.push_back(key);
    groups[key].push_back(i);
  }
  for (const std::string& key : group_order) {
    const std::vector<std::size_t>& members = groups[key];
    if (members.size() < 2) continue;  // a group of one selects its own
    SharedSelection s;
    s.id = "S" + std::to_string(b.selections.size() + 1);
    s.members = members;
    s.T_min = b.mechanisms[members[0]].own_T_min;
    s.T_max = b.mechanisms[members[0]].own_T_max;
    for (std::size_t i : members) {
      s.T_min = std::min(s.T_min, b.mechanisms[i].own_T_min);
      s.T_max = std::max(s.T_max, b.mechanisms[i].own_T_max);
    }
    for (std::size_t i : members) {
      BuildingMechanism& m = b.mechanisms[i];
      m.expanded["dynamic"]["select"]["period_range_s"] = nlohmann::json::array({s.T_min, s.T_max});
      m.kase = parse_expanded(b, m);
      m.record_set = RecordSetKind::shared;
      m.record_group = s.id;
    }
    b.selections.push_back(std::move(s));
    // "Where the periods allow it" (docs/theory/building.md §3): the shared set
    // is decided here, once, from the selection itself, so that the building,
    // a mechanism run alone (--mechanism) and its expanded case agree.
    const BuildingMechanism& first = b.mechanisms[members[0]];
    const NoteText problem = [&] {
      try {
        return shared_selection_problem(first.kase);
      } catch (const InputError& err) {
        throw InputError(building_path_message(b, first, err.what()));
      }
    }();
    if (!problem.empty()) {
      SharedSelection& added = b.selections.back();
      fall_back_to_own_selection(b, b.selections.size() - 1);
      added.note = problem;
      added.note.push_back({"sel.fell_back", {number_arg(added.T_min, 3), number_arg(added.T_max, 3, "s")}});
    }
  }
  return b;
}

BuildingCase read_building_file(const std::string& path) { return parse_building(read_json_file(path), path); }

void fall_back_to_own_selection(BuildingCase& b, std::size_t selection) {
  SharedSelection& s = b.selections.at(selection);
  s.fell_back = true;
  for (std::size_t i : s.members) {
    BuildingMechanism& m = b.mechanisms[i];
    m.expanded["dynamic"]["select"].erase("period_range_s");
    m.kase = parse_expanded(b, m);
    m.record_set = RecordSetKind::own;
  }
}

nlohmann::json standalone_case(const BuildingCase& b, const BuildingMechanism& m) {
  nlohmann::json x = m.expanded;
  const std::string dir = directory_of(b.file);
  auto absolute = [&](nlohmann::json& f) {
    if (!f.is_string()) return;
    const std::string s = f.get<std::string>();
    if (s.empty() || s[0] == '/') return;
    const std::filesystem::path p = std::filesystem::path(dir) / s;
    if (std::filesystem::exists(p)) f = std::filesystem::absolute(p).lexically_normal().string();
  };
  if (x.contains("dynamic") && x["dynamic"].is_object()) {
    nlohmann::json& d = x["dynamic"];
    if (d.contains("records") && d["records"].is_array())
      for (nlohmann::json& r : d["records"])
        if (r.is_object() && r.contains("file")) absolute(r["file"]);
    if (d.contains("select") && d["select"].is_object() && d["select"].contains("catalogue"))
      absolute(d["select"]["catalogue"]);
  }
  x["schema_version"] = 1;
  return x;
}

const BuildingMechanism& find_mechanism(const BuildingCase& b, const std::string& id_or_name) {
  // An id first (M1, M2, ... in the file's order), then a name: a name of
  // the form of another mechanism's id is refused by parse_building, so
  // `--mechanism M2` always means the second mechanism (issue 31).
  for (const BuildingMechanism& m : b.mechanisms)
    if (m.id == id_or_name) return m;
  for (const BuildingMechanism& m : b.mechanisms)
    if (m.name == id_or_name) return m;
  std::string names;
  for (const BuildingMechanism& m : b.mechanisms) names += (names.empty() ? "" : ", ") + m.id + " \"" + m.name + "\"";
  throw InputError(b.file + ": no mechanism \"" + id_or_name + "\" in the building (its mechanisms: " + names + ")");
}

}  // namespace assess
