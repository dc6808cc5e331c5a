// analysis_end.hpp: how long a dynamic analysis runs, and why it ended
// (issue 21; docs/theory/rocking.md §8). One rule for every front end
// (assess run, rocking, campaign, fragility) and both dynamic models (the
// rocking body and the 1-DOF chain):
//   - the whole motion as given, to its last sample; it ends earlier only
//     where that is exact: the body overturns, or it rests on its base and
//     what is left of the motion cannot lift it (|ug''| below the lift-off
//     threshold for the rest of the record, sample by sample);
//   - then free motion, which ends when the body is at rest, or at an impact
//     after which its energy is at most `free_energy_fraction` of the work
//     needed to reach the peak rotation again (no later excursion can then
//     change the peak, the energy D/C, d* or the overturning verdict), or at
//     the cap RockingOptions::tail_s.
#pragma once

namespace assess {

/// Why an analysis ended.
enum class AnalysisEnd {
  overturned,         ///< the body reached the overturning rotation
  rest_input_below,   ///< at rest during the motion; the rest of the motion cannot lift it
  rest_after_motion,  ///< at rest after the motion
  energy_decayed,     ///< free motion: energy after an impact <= free_energy_fraction x work to the peak
  free_motion_cap,    ///< free motion reached its cap RockingOptions::tail_s
  failed              ///< step or event limit, or integrator error (the result is not a result)
};

/// Fraction of the work of the restoring moment (force) from rest to the peak
/// rotation below which, after an impact in the free motion, the analysis
/// ends (-). Any value < 1 keeps the peak exact (proof in
/// docs/theory/rocking.md §8); 0.5 ends free motion one or two impacts after
/// the energy can no longer reach the peak.
constexpr double free_energy_fraction = 0.5;

/// "overturned", "rest_input_below", "rest_after_motion", "energy_decayed", "free_motion_cap", "failed".
const char* to_string(AnalysisEnd e);

}  // namespace assess
