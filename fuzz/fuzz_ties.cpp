// libFuzzer harness: the tie rods of a case file ("ties": given levels with
// rod, anchor, masonry, spacing, pretension; "design": levels to design) ->
// parse_case, the kinematic analysis held by the ties, and the intervention
// (run_tie_intervention: the force each check needs, the checks of every
// given tie, the smallest commercial rod and plate of a design, the verdicts
// before and after). A "site" that needs the hazard grid or the list of
// comuni on disk is replaced by explicit hazard parameters and the "dynamic"
// section is dropped (the intervention's statics only), so each run stays in
// memory. Any exception but InputError, any crash, leak or undefined
// behaviour is a finding; so is a non-finite alpha0 (issue 31).
#include <assess/assessment/case_file.hpp>
#include <assess/assessment/tie_intervention.hpp>
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
    if (doc.is_object()) {
      if (!(doc.contains("site") && doc["site"].is_object() && doc["site"].contains("hazard")))
        doc["site"] = nlohmann::json::parse(fuzz::kHazard);
      doc.erase("dynamic");
      if (doc.value("method", "") == "dynamic") doc.erase("method");
    }
    const assess::CaseFile c = assess::parse_case(doc, "fuzz.json");
    const assess::KinematicCaseResult r = assess::run_kinematic_case(c);
    fuzz::require_finite_alpha0(r);
    if (assess::has_ties(c)) (void)assess::run_tie_intervention(c);
  } catch (const assess::InputError&) {
  }
  return 0;
}
