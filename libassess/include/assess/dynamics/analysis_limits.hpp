// analysis_limits.hpp: the one set of bounds on the inputs of a rocking
// analysis, shared by `assess rocking`, the case file's dynamic section and
// campaigns (issue 10, defect 11). RockingOptions::validate() and the
// rocking-model checks of analyse() enforce them for every front end; the
// parsers quote the same constants so that their messages name the JSON path
// or option. Units: SI (the front ends convert kN at the edge).
//
// Why each bound (docs/reliability.md, "Bounds and limits"):
//   rel_tol   [1e-14, 1e-2]  below 1e-14 the local error test asks for less
//                            than the rounding of a double (eps = 2.2e-16)
//                            over a step; above 1e-2 a "result" has no digit.
//   abs_tol   [1e-16, 1e-2]  rad and rad/s; same reasons (theta_u ~ 0.1 rad).
//   tail_s    [0, 600] s     free motion after the record: 10 minutes is far
//                            beyond any rocking decay (seconds) and bounds the
//                            run time of one analysis.
//   scale     (0, 100]       factor on a record: 100 x a 1 g record is 100 g.
//   max_steps [1, 1e9]       integrator steps (an integer: no cast of 1e300).
//   k         (0, 1e12] N/m^3 (1e9 kN/m^3): a Winkler modulus beyond a steel
//                            contact (E = 200 GPa over 0.2 m) is the rigid
//                            model; use model "rigid".
//   theta_cr >= 10 abs_tol   the full-contact branch |theta| <= theta_cr =
//                            W / (2 b^2 k) (seed Eq. 1) must be larger than
//                            the error the integrator accepts on theta, else
//                            its stiff oscillation is not controlled (k = 1e20
//                            kN/m^3 gave theta_max = 1.6e134 rad); measured:
//                            at theta_cr = 29 abs_tol theta_max is within
//                            1e-3 of a run 1e5 times tighter.
//   unit weight (0, 1e7] N/m^3 (1e4 kN/m^3, a hundred times steel's 78.5):
//                            keeps W, energies and periods finite (1e300 gave
//                            "period T = inf s"); a plausible but wrong value
//                            (1800, kg/m^3 typed as kN/m^3) is a warning of
//                            assessment/plausibility.hpp, not an error.
#pragma once

#include "assess/support/number_rules.hpp"

namespace assess::limits {

constexpr double rel_tol_min = 1e-14;       ///< - (relative local error per step)
constexpr double rel_tol_max = 1e-2;        ///< -
constexpr double abs_tol_min = 1e-16;       ///< rad, rad/s
constexpr double abs_tol_max = 1e-2;        ///< rad, rad/s
constexpr double tail_max_s = 600.0;        ///< s
constexpr double scale_max = 100.0;         ///< - (record scale factor, > 0)
constexpr double max_steps_max = 1e9;       ///< steps
constexpr double max_events_max = 1e9;      ///< events
constexpr double winkler_k_max_N_m3 = 1e12; ///< N/m^3 (= 1e9 kN/m^3)
constexpr double theta_cr_min_over_abs_tol = 10.0;  ///< -
constexpr double unit_weight_max_N_m3 = 1e7;        ///< N/m^3 (= 1e4 kN/m^3)
/// Events (impacts, contact-branch switches, lift-offs) an analysis may locate
/// per second of analysed time (motion and tail), plus events_floor: a
/// rocking wall meets a few tens per second (a stiff Winkler base: about 400);
/// more is an accumulation of events at rest, where the body only chatters
/// (issue 31: a campaign at scale 1e-13 located ten million events, 6 s per
/// analysis, before "failed"; now about 0.05 s). The analysis ends as
/// event_limit, a failure, with the count in its message.
constexpr double events_per_second_max = 2000.0;    ///< 1/s
constexpr double events_floor = 10000.0;            ///< events

/// The same bounds as number rules in the units users write (kN), for the
/// command line's options (issue 39: every option with its range and reason).
namespace option {
inline constexpr NumberRule rel_tol{"-", rel_tol_min, rel_tol_max, false, false,
                                    "below: less than a double's rounding over a step; above: no digit left"};
inline constexpr NumberRule abs_tol{"rad, rad/s", abs_tol_min, abs_tol_max, false, false,
                                    "below: less than a double's rounding; above: no digit of theta_u ~ 0.1 rad"};
inline constexpr NumberRule tail_s{"s", 0.0, tail_max_s, false, false, "free motion after the record; rocking decays in seconds"};
inline constexpr NumberRule scale{"-", 0.0, scale_max, true, false, "a factor on the record: 100 x a 1 g record is 100 g"};
inline constexpr NumberRule winkler_k_kN_m3{"kN/m^3", 0.0, winkler_k_max_N_m3 / 1e3, true, false,
                                            "a stiffer base is the rigid model: use --model rigid"};
}  // namespace option

}  // namespace assess::limits
