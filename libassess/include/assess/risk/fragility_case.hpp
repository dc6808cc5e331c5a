// fragility_case.hpp: which mechanism a fragility analysis studies, for every
// front end (`assess fragility CASE [--mechanism ID]`, the Python module's
// assess.fragility): a single-mechanism case's governing mechanism, or a
// building case's mechanism named by its id or name, else the building's
// governing one (docs/user/building.md, "Fragility").
#pragma once

#include "assess/assessment/building_case.hpp"
#include "assess/assessment/case_file.hpp"
#include "assess/risk/fragility_study.hpp"

#include <nlohmann/json.hpp>

#include <cstddef>
#include <optional>
#include <string>

namespace assess {

struct FragilityCase {
  CaseFile kase;                        ///< the single-mechanism case studied
  std::optional<BuildingCase> building; ///< a building case: the building
  std::size_t mechanism = 0;            ///< the mechanism's index in building->mechanisms
  /// A building's governing mechanism chosen for the user: which and why
  /// ("M3 \"...\", the building's governing mechanism (lowest NTC 2018 zetaE,
  /// displacement); --mechanism ID for another"); empty otherwise.
  std::string note;
  /// The default output directory: CASE.fragility, a building's CASE.M3.fragility.
  std::string default_out;
};

/// The case of `file` (its parsed document `doc`); `mechanism` (id or name)
/// for a building case only.
/// @throws InputError naming the file, the JSON path or the mechanism
FragilityCase fragility_case(const nlohmann::json& doc, const std::string& file, const std::string& mechanism = "");

/// prepare_fragility of the case; a building mechanism's errors name the
/// building file's paths and the mechanism (building_path_message).
FragilityStudy prepare_case_fragility(const FragilityCase& c, const FragilityOptions& options);

}  // namespace assess
