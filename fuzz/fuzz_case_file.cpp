// libFuzzer harness: the case-file reader (JSON text -> CaseFile) and, when
// the case is valid, its kinematic analysis and code checks. A "site" that
// needs the hazard grid on disk (lat/lon, island) is dropped so that each
// run stays in memory; a site with explicit "hazard" parameters is kept.
// Any exception but InputError, any crash, leak or undefined behaviour is a
// finding; so is a non-finite multiplier alpha0 of a valid analysis.
#include <assess/assessment/case_file.hpp>
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
    if (doc.is_object() && doc.contains("site") && doc["site"].is_object() && !doc["site"].contains("hazard"))
      doc.erase("site");
    const assess::CaseFile c = assess::parse_case(doc, "fuzz.json");
    const assess::KinematicCaseResult r = assess::run_kinematic_case(c);
    fuzz::require_finite_alpha0(r);
  } catch (const assess::InputError&) {
  }
  return 0;
}
