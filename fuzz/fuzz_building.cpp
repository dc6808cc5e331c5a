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

#include "fuzz_support.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    nlohmann::json doc = assess::parse_json_text(text, "fuzz.json");
    if (doc.is_object() && doc.contains("site") && !(doc["site"].is_object() && doc["site"].contains("hazard")))
      doc["site"] = nlohmann::json::parse(fuzz::kHazard);
    const assess::BuildingCase b = assess::parse_building(doc, "fuzz.json");
    for (const assess::BuildingMechanism& m : b.mechanisms) {
      const assess::KinematicCaseResult r = assess::run_kinematic_case(m.kase);
      fuzz::require_finite_alpha0(r);
    }
    if (!b.mechanisms.empty()) (void)assess::find_mechanism(b, b.mechanisms.back().id);
  } catch (const assess::InputError&) {
  }
  return 0;
}
