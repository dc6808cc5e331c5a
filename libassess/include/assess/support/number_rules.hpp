// number_rules.hpp: the one rule set for numbers read from input files
// (issue 31): case files, building files and tie rods.
//
// Every number a user writes must be (1) a number, (2) finite, (3) a normal
// double or zero (a subnormal such as 1e-320 is never a measured quantity and
// makes every ratio it divides infinite), and (4) within the physical range
// of its quantity, in the unit the file uses. The ranges are wide (they refuse
// what cannot be a masonry wall, a tie rod or a site, not what is unusual;
// unusual values are warnings, assessment/plausibility.hpp) and each names
// its reason. JsonNode::as_number(const NumberRule&) applies them with the
// file and the JSON path; messages never print "inf" or "nan"
// (number_for_message).
#pragma once

#include <string>

namespace assess {

/// The physical range of one kind of quantity, in the unit of the input file.
struct NumberRule {
  const char* unit;      ///< named in errors: "m", "kN", "kN/m^3", "MPa", "mm", "s", "years", "%", "-"
  double lo, hi;         ///< the range (closed unless lo_open)
  bool lo_open = false;  ///< (lo, hi] instead of [lo, hi]
  bool zero_ok = false;  ///< 0 is accepted besides [lo, hi] (a weightless block, no pretension)
  const char* why = "";  ///< the reason for the range, quoted in errors
};

/// "" when `v` obeys the rule; else what is wrong, e.g. "value 1e+150 out of
/// range: expected in [-1000, 1000] m (a point of the building within 1 km of
/// its origin)", "value 1e-320 is a subnormal number (|x| < 2.2e-308): not a
/// physical value, expected in [0.001, 1000] m", "not a number".
std::string number_rule_violation(double v, const NumberRule& rule);

/// True for a subnormal double (0 < |v| < 2.2e-308).
bool is_subnormal(double v);

/// A number for a message: %g-style digits, and never "inf", "-inf" or "nan":
/// "infinite", "minus infinite", "not a number".
std::string number_for_message(double v);

/// Reads `text` as one decimal number written in full ("6.5", "-1e-3",
/// "+250"): the rule of every number a user writes as text (a cell of
/// metadata.csv, a command-line option, a list of periods; issue 39). Returns
/// "" and sets `v`, else what is wrong: "must be a decimal number, got
/// '0x1p3' (a hexadecimal number)", "must be a finite number, got 'inf'",
/// "expected a number, got '6.5 km'", "must be a number of normal size, got
/// '1e-320' (a subnormal number, |x| < 2.2e-308)". Leading or trailing
/// blanks are not part of a number.
std::string decimal_number_violation(const std::string& text, double& v);

/// "" when `text` holds no control character; else "the text holds a control
/// character (U+001B) at character 5". Control characters are U+0000-U+001F,
/// U+007F and U+0080-U+009F (UTF-8 C2 80-C2 9F): names, ids and notes are
/// printed on terminals (an ESC sequence re-programs one), in text tables and
/// in HTML (issues 31, 39). Every text of an input file obeys it.
std::string control_character_violation(const std::string& text);

/// The named rules (file units). One place: a range changes here for every
/// reader that uses it. docs/reliability.md, "Bounds and limits".
namespace rules {
/// A point [x, z] of a mechanism or a tie anchor.
inline constexpr NumberRule coordinate_m{"m", -1e3, 1e3, false, false,
                                         "a point of the wall within 1 km of the origin of its coordinates"};
/// A dimension of a wall, a block or a tie (height, thickness, length, spacing, free length).
inline constexpr NumberRule dimension_m{"m", 1e-3, 1e3, false, false, "a dimension of a wall: 1 mm to 1 km"};
/// A height or a distance that may be zero (base of the wall, setback, Z, a load's distance from a face).
inline constexpr NumberRule offset_m{"m", 0.0, 1e3, false, false, "0 to 1 km"};
/// A displacement cap of the capacity curve.
inline constexpr NumberRule displacement_cap_m{"m", 1e-6, 1e3, false, false, "a displacement of 1 um to 1 km"};
/// A weight or a tensile force (>= 0): floor loads, tie forces, pretension.
inline constexpr NumberRule weight_kN{"kN", 0.0, 1e6, false, false, "0 to 1 GN: a weight or a tie force"};
/// A force that may act either way (thrusts, force components).
inline constexpr NumberRule force_kN{"kN", -1e6, 1e6, false, false, "up to 1 GN either way"};
/// The unit weight of masonry (a hundred times steel's 78.5 kN/m^3 at most; analysis_limits.hpp).
inline constexpr NumberRule unit_weight_kN_m3{"kN/m^3", 1e-3, 1e4, false, false,
                                              "1 N/m^3 to 10 000 kN/m^3; masonry weighs about 12-22 kN/m^3"};
/// The same for a block that may be weightless (explicit blocks carrying loads).
inline constexpr NumberRule block_unit_weight_kN_m3{"kN/m^3", 1e-3, 1e4, false, true,
                                                    "0, or 1 N/m^3 to 10 000 kN/m^3"};
/// A strength of masonry or steel (fm, tau, fyk).
inline constexpr NumberRule stress_MPa{"MPa", 1e-3, 1e4, false, false, "1 kPa to 10 GPa"};
/// A dimension of a rod or an anchor (diameter, plate side and thickness, bar length).
inline constexpr NumberRule steel_mm{"mm", 0.1, 1e4, false, false, "0.1 mm to 10 m"};
/// The cross-section of a rod.
inline constexpr NumberRule area_mm2{"mm^2", 1e-2, 1e8, false, false, "0.01 mm^2 to 100 m^2"};
/// A period of vibration (the building's T1, the spectrum's Tc*).
inline constexpr NumberRule period_s{"s", 1e-3, 100.0, false, false, "1 ms to 100 s"};
/// A return period.
inline constexpr NumberRule return_period_years{"years", 1.0, 1e6, false, false, "1 to 1 000 000 years"};
/// A nominal life VN (NTC 2018 Tab. 2.4.I: 10, 50 or 100 years).
inline constexpr NumberRule nominal_life_years{"years", 1.0, 1e4, false, false,
                                               "1 to 10 000 years; NTC 2018 Tab. 2.4.I: 10, 50, 100"};
/// A viscous damping ratio in percent, > 0.
inline constexpr NumberRule damping_pct{"%", 0.0, 100.0, true, false, "above 0 and at most 100 %"};
/// A viscous damping ratio in percent, >= 0.
inline constexpr NumberRule damping_or_zero_pct{"%", 0.0, 100.0, false, false, "0 to 100 %"};
/// A behaviour factor q.
inline constexpr NumberRule behaviour_factor{"-", 1.0, 100.0, false, false, "1 to 100"};
/// A coefficient of use CU (NTC 2018 Tab. 2.4.II: 0.7 to 2).
inline constexpr NumberRule use_coefficient{"-", 0.1, 10.0, false, false, "0.1 to 10; NTC 2018: 0.7 to 2"};
/// A latitude and a longitude (decimal degrees).
inline constexpr NumberRule latitude_deg{"deg", -90.0, 90.0, false, false, "a latitude in decimal degrees"};
inline constexpr NumberRule longitude_deg{"deg", -180.0, 180.0, false, false, "a longitude in decimal degrees"};
/// The hazard parameters of a site given directly (NTC 2018 §3.2, Allegato A):
/// ag on rock, F0, TC*. The NTC grid spans ag 0.02-0.39 g, F0 2.2-3.0, TC*
/// 0.14-0.6 s; the ranges refuse what is no site.
inline constexpr NumberRule ag_g{"g", 0.0, 5.0, true, false, "ag on rock, above 0"};
inline constexpr NumberRule F0{"-", 1.0, 10.0, false, false, "the spectrum's largest amplification F0"};
inline constexpr NumberRule Tc_star_s{"s", 0.01, 10.0, false, false, "the period TC* of the spectrum's plateau end"};
/// The relative height h/H of a site on a relief (NTC 2018 §3.2.3.2.1).
inline constexpr NumberRule relative_height{"-", 0.0, 1.0, false, false, "h/H: 0 at the foot, 1 at the top"};
/// A confidence factor FC or a partial factor gamma.
inline constexpr NumberRule factor{"-", 1.0, 10.0, false, false, "1 to 10"};
}  // namespace rules

}  // namespace assess
