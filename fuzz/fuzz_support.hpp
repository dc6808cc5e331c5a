// fuzz_support.hpp: what the case, building and tie harnesses share: the
// hazard given in the file (so a run never reads the grid or the comuni from
// disk) and the finding "a valid analysis with a non-finite alpha0" (issue 31).
#pragma once

#include <assess/assessment/case_file.hpp>

#include <cmath>
#include <cstdlib>

namespace fuzz {

// Norcia, soil B (NTC 2018 grid values, rounded), three limit states.
inline const char* const kHazard = R"({"hazard": {
  "SLD": {"ag_g": 0.089, "F0": 2.37, "Tc_star": 0.28, "TR": 50},
  "SLV": {"ag_g": 0.252, "F0": 2.37, "Tc_star": 0.33, "TR": 475},
  "SLC": {"ag_g": 0.327, "F0": 2.41, "Tc_star": 0.34, "TR": 975}}, "soil": "B"})";

// Aborts (a finding) when an analysis that did not refuse its input gives a non-finite alpha0.
inline void require_finite_alpha0(const assess::KinematicCaseResult& r) {
  for (const auto& cand : r.candidates)
    if (!std::isfinite(cand.result.alpha0)) std::abort();
}

}  // namespace fuzz
