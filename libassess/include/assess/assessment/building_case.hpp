// building_case.hpp: the building case file (issue 22; docs/user/building.md,
// docs/schema/building.schema.json): one site, one building, one knowledge
// level, shared dynamic settings and a list of walls, each with its local
// mechanisms. Each mechanism expands into exactly the single-mechanism case an
// engineer would have written (docs/user/case-file.md): the shared keys, then
// the wall's overrides, then the mechanism's, merged as a JSON merge patch
// (RFC 7386: objects merge key by key, null deletes). The expanded case is
// parsed by parse_case and run by assess_facade, the code path of a single run.
// Issue 37: a wall's "ties" and "design" are not merged whole: each tie level
// given on the wall (existing, new, or to design) acts on every mechanism of
// the wall whose moving blocks it crosses, and only on those; a mechanism's
// own "ties" are added to them.
#pragma once

#include "assess/assessment/case_file.hpp"
#include "assess/support/note.hpp"

#include <nlohmann/json.hpp>

#include <string>
#include <vector>

namespace assess {

/// The most mechanisms a building case may list (a palazzo has a few dozen;
/// each is a full assessment): bounds the run time of a hostile file.
inline constexpr std::size_t building_max_mechanisms = 1000;

/// A building document is recognised by its top-level key "walls"; a
/// single-mechanism case (key "mechanism") is not one.
bool is_building_document(const nlohmann::json& doc);

/// How a mechanism's records were chosen (docs/theory/building.md §3).
enum class RecordSetKind {
  none,         ///< no dynamic analysis
  listed,       ///< records listed in its (expanded) dynamic section
  shared,       ///< the building's shared selection: one set for every mechanism of the group
  own,          ///< its own selection (period range given, shared selection off, or the shared range failed)
};
std::string to_string(RecordSetKind k);

/// One mechanism of the building, expanded.
struct BuildingMechanism {
  std::string id;         ///< "M1", "M2", ... in the file's order
  std::string wall;       ///< the wall's name
  std::string name;       ///< the mechanism's name (unique in the building)
  std::string json_path;  ///< "/walls/0/mechanisms/1"
  std::size_t wall_index = 0, index = 0;
  /// The single-mechanism case document this mechanism expands into (with the
  /// shared selection's period range written into dynamic/select when shared).
  nlohmann::json expanded;
  CaseFile kase;          ///< expanded, parsed (file = the building file)
  RecordSetKind record_set = RecordSetKind::none;
  std::string record_group;  ///< "S1", "S2", ... for a shared selection ("" otherwise)
  /// The period range the mechanism alone would select over (s), from its
  /// governing candidate's Ts and T_SLV (0 when not selecting).
  double own_T_min = 0.0, own_T_max = 0.0;
  /// Issue 37: the mechanism holds some of its wall's tie levels ("ties" or
  /// "design" of the wall that cross its moving blocks): the wall's ties are
  /// assessed and designed for all such mechanisms of the wall together.
  bool wall_ties = false;
  /// Where each tie level of the expanded case was written in the building
  /// file ("/walls/0/ties/1", "/walls/0/mechanisms/1/ties/0"), and each level
  /// of its design: the expanded case lists only the wall's levels that cross
  /// the mechanism, so its indices differ from the file's.
  std::vector<std::string> tie_origin, design_origin;
};

/// A shared record selection: mechanisms with the same "select" settings whose
/// records are selected once over the union of their period ranges.
struct SharedSelection {
  std::string id;                    ///< "S1", ...
  double T_min = 0.0, T_max = 0.0;   ///< union of the members' ranges (s)
  std::vector<std::size_t> members;  ///< indices in BuildingCase::mechanisms
  bool fell_back = false;            ///< no compatible set over the union: members selected their own
  NoteText note;                     ///< why it fell back (as data)
};

struct BuildingCase {
  std::string file;
  std::string project;
  nlohmann::json doc;  ///< the building document as read
  std::vector<BuildingMechanism> mechanisms;
  std::vector<SharedSelection> selections;
  /// "shared" (default) or "per_mechanism" (key "record_selection").
  std::string record_selection = "shared";
  /// "report": the relazione's frontespizio and descriptive sections (issue 28), building-wide.
  ReportInfo report;
};

/// Parses a building document: validates the building keys (unknown keys are
/// errors with a suggestion), expands every mechanism and parses it with
/// parse_case. Errors name `file`, the JSON path in the building file (e.g.
/// /walls/1/mechanisms/0/mechanism/height), the expected value and unit.
/// Then groups the mechanisms that select records (docs/theory/building.md §3)
/// and writes each group's union range into its members' expanded cases
/// (a kinematic pre-pass gives each mechanism's range).
BuildingCase parse_building(const nlohmann::json& doc, const std::string& file);
BuildingCase read_building_file(const std::string& path);

/// Rewrites an error or warning of an expanded case ("<file>: /mechanism/...:")
/// so that it names the path in the building file where the value was written.
std::string building_path_message(const BuildingCase& b, const BuildingMechanism& m, const std::string& message);

/// Makes the members of a shared selection select their own records (when the
/// union range gives no compatible set): removes the shared range from their
/// expanded cases and re-parses them.
void fall_back_to_own_selection(BuildingCase& b, std::size_t selection);

/// The expanded case of `m` as a stand-alone file written into `dir`: record
/// and catalogue paths made absolute so that it runs from anywhere. Returns the
/// document (the caller writes it).
nlohmann::json standalone_case(const BuildingCase& b, const BuildingMechanism& m);

/// Finds a mechanism by id ("M3") or name; InputError listing the names.
const BuildingMechanism& find_mechanism(const BuildingCase& b, const std::string& id_or_name);

}  // namespace assess
