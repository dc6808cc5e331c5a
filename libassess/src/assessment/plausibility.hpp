// plausibility.hpp (private): bounds outside which an input is probably a
// typing or unit slip (cm for m, kg/m^3 for kN/m^3 ...). They are not code
// limits: the run goes on and a warning names the field, the value, the unit
// and why it looks wrong (docs/user/case-file.md §Warnings).
#pragma once

#include <cstdio>
#include <string>
#include <vector>

namespace assess::plausibility {

/// Wall thickness (m): thinner than a half-brick leaf (0.05 m) or thicker
/// than the thickest historic walls (about 3 m) is likely a unit slip (60 typed in cm).
inline constexpr double thickness_min_m = 0.05, thickness_max_m = 3.0;
/// Height of a wall or storey (m): over 60 m is a tower, not a façade.
inline constexpr double height_max_m = 60.0;
/// Unit weight of masonry (kN/m^3): the masonry types of Circ. 2019 Tab. C8.5.I
/// weigh about 12-22 kN/m^3 (recalled, not re-read); 10-30 leaves margin for
/// light tuff and dense stone. 1800 is kg/m^3.
inline constexpr double unit_weight_min_kN_m3 = 10.0, unit_weight_max_kN_m3 = 30.0;
/// A wall thinner than 1/30 of its height (h/t > 30) is far more slender than
/// load-bearing masonry (the NTC limits on the slenderness h0/t of load-bearing
/// walls are 20 or less; recalled, not re-read): probably a thickness in the
/// wrong unit or a height that spans several storeys.
inline constexpr double slenderness_max = 30.0;
/// alpha0 > 1: the mechanism needs a horizontal force larger than the weight
/// to start; real façades are in 0.02-0.5 (check a thrust sign or a tie).
inline constexpr double alpha0_max = 1.0;
/// A scaled record with PGA > 2 g is beyond recorded ground motions.
inline constexpr double record_pga_max_g = 2.0;
/// Winkler modulus of the smooth model (kN/m^3): the seed paper (Lipo & de
/// Felice 2017, Fig. 2) spans 5e4-1e7 kN/m^3; below 1e4 an ordinary wall has no
/// restoring branch, above 1e8 the model is the rigid block (use "rigid").
inline constexpr double k_min_kN_m3 = 1e4, k_max_kN_m3 = 1e8;

inline std::string number(double v) {
  char b[32];
  std::snprintf(b, sizeof b, "%.4g", v);
  return b;
}

/// Appends a warning when v is outside [lo, hi].
inline void range(std::vector<std::string>& out, const std::string& where, double v, const char* unit, double lo,
                  double hi, const std::string& why) {
  if (v >= lo && v <= hi) return;
  out.push_back(where + " = " + number(v) + " " + unit + " is outside the plausible range " + number(lo) + "-" +
                number(hi) + " " + unit + ": " + why + " (the run goes on with " + number(v) + " " + unit + ")");
}

}  // namespace assess::plausibility
