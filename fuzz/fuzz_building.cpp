// libFuzzer harness: the building case reader (JSON text -> BuildingCase:
// the building keys, the merge of wall and mechanism overrides, every
// expanded case parsed by parse_case, the shared record groups with their
// kinematic pre-pass) and, for a valid building, the kinematic analysis and
// code checks of every mechanism. A "site" that needs the hazard grid or the
// list of comuni on disk is replaced by explicit hazard parameters, so that
// each run stays in memory; the "dynamic" sections stay (parsed, never run).
// Any exception but InputError, any crash, leak or undefined behaviour is a
// finding; so is a non-finite alpha0 of a valid analysis (issue 31).
#include <assess/assessment/building_case.hpp>
#include <assess/support/error.hpp>
#include <assess/support/json_input.hpp>

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace {
// Norcia, soil B (NTC 2018 grid values, rounded), three limit states.
const char* const kHazard = R"({"hazard": {
  "SLD": {"ag_g": 0.089, "F0": 2.37, "Tc_star": 0.28, "TR": 50},
  "SLV": {"ag_g": 0.252, "F0": 2.37, "Tc_star": 0.33, "TR": 475},
  "SLC": {"ag_g": 0.327, "F0": 2.41, "Tc_star": 0.34, "TR": 975}}, "soil": "B"})";
}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    nlohmann::json doc = assess::parse_json_text(text, "fuzz.json");
    if (doc.is_object() && doc.contains("site") && !(doc["site"].is_object() && doc["site"].contains("hazard")))
      doc["site"] = nlohmann::json::parse(kHazard);
    const assess::BuildingCase b = assess::parse_building(doc, "fuzz.json");
    for (const assess::BuildingMechanism& m : b.mechanisms) {
      const assess::KinematicCaseResult r = assess::run_kinematic_case(m.kase);
      for (const auto& cand : r.candidates)
        if (!std::isfinite(cand.result.alpha0)) std::abort();
    }
    if (!b.mechanisms.empty()) (void)assess::find_mechanism(b, b.mechanisms.back().id);
  } catch (const assess::InputError&) {
  }
  return 0;
}
