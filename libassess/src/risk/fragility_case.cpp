// fragility_case.cpp: the mechanism a fragility analysis studies
// (risk/fragility_case.hpp), moved from apps/cmd_fragility.cpp for issue 40 so
// that the Python module studies the same one.
#include "assess/risk/fragility_case.hpp"

#include "assess/assessment/building_assessment.hpp"
#include "assess/support/error.hpp"

#include <filesystem>

namespace assess {

FragilityCase fragility_case(const nlohmann::json& doc, const std::string& file, const std::string& mechanism) {
  FragilityCase c;
  const std::string stem = std::filesystem::path(file).stem().string();
  c.default_out = stem + ".fragility";
  if (!is_building_document(doc)) {
    if (!mechanism.empty())
      throw InputError(file + ": --mechanism applies to a building case (a file with \"walls\"), not to a "
                       "single-mechanism case");
    c.kase = parse_case(doc, file);
    return c;
  }
  // A building case (issue 22): the mechanism named, else the governing one.
  BuildingCase bc = parse_building(doc, file);
  const BuildingMechanism* m = mechanism.empty() ? nullptr : &find_mechanism(bc, mechanism);
  if (!m) {
    const std::string approach = bc.mechanisms.front().kase.method == "linear" ? "strength" : "displacement";
    m = &bc.mechanisms[governing_mechanism_kinematic(bc, approach)];
    c.note = m->id + " \"" + m->name + "\", the building's governing mechanism (lowest NTC 2018 zetaE, " + approach +
             "); --mechanism ID for another";
  }
  c.kase = m->kase;
  c.mechanism = static_cast<std::size_t>(m - bc.mechanisms.data());
  c.default_out = stem + "." + m->id + ".fragility";
  c.building = std::move(bc);
  return c;
}

FragilityStudy prepare_case_fragility(const FragilityCase& c, const FragilityOptions& options) {
  try {
    return prepare_fragility(c.kase, options);
  } catch (const InputError& e) {
    if (!c.building) throw;
    throw InputError(building_path_message(*c.building, c.building->mechanisms[c.mechanism], e.what()));
  }
}

}  // namespace assess
