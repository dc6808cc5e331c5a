// check_index.cpp: the return period at which a code check reaches D/C = 1
// (issue 41; docs/theory/building.md §4).
//
// The check is its own function of the hazard: run_code_checks re-run with
// the hazard of the row's limit state replaced, every other input (the
// analysis, the damping, the building, Z, q) unchanged. D/C is continuous in
// TR (ag, F0, TC* are continuous along Allegato A's log-log interpolation, the
// spectra continuous in them) but not always monotonic (F0 and TC* move with
// TR). The axis x (TR in years, or ag in g without a TR axis) is scanned on a
// log grid (scan_per_decade points per decade, the nine tabulated return
// periods and x_D added), then the crossing is refined by Brent in ln x.
#include "assess/kinematic/check_index.hpp"

#include "assess/kinematic/code_checks.hpp"
#include "assess/support/error.hpp"
#include "support/root_find.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace assess {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr double inf = std::numeric_limits<double>::infinity();
constexpr int scan_per_decade = 6;
constexpr double ln_tol = 1e-12;  // Brent's tolerance on ln x (relative 1e-12 on TR or ag)

bool same_check(const CheckRow& a, const CheckRow& b) {
  return a.code == b.code && a.limit_state == b.limit_state && a.kind == b.kind && a.location == b.location;
}

}  // namespace

CheckIndex check_index(const KinematicResult& r, const CheckInput& in, const CheckRow& row, const HazardAxis& axis) {
  CheckIndex ix;
  if (row.kind != "strength" && row.kind != "displacement") {
    ix.note = no_dynamic_index;
    return ix;
  }
  if (!std::isfinite(row.dc) || row.no_verdict) {
    ix.note = "no index: the check has no finite D/C";
    return ix;
  }
  const LimitState ls = parse_limit_state(row.limit_state);
  const HazardParams& h_D = in.hazard.at(ls);
  CheckInput one = in;
  one.codes = {parse_code_edition(row.code)};
  one.sld = ls == LimitState::SLD;
  const bool has_axis = static_cast<bool>(axis);
  ix.shape_held = !has_axis;
  // The hazard at x: the site's at TR = x, or the limit state's with ag = x (g).
  auto hazard = [&](double x) {
    if (has_axis) return axis(x);
    HazardParams h = h_D;
    h.ag_g = x;
    return h;
  };
  auto dc = [&](double x) {
    one.hazard[ls] = hazard(x);
    for (const CheckRow& c : run_code_checks(r, one))
      if (same_check(c, row)) return c.dc;
    return nan;
  };
  const double x_D = has_axis ? h_D.TR : h_D.ag_g;
  const double x_lo = has_axis ? check_index_tr_min : check_index_ag_min_g;
  const double x_hi = has_axis ? check_index_tr_max : check_index_ag_max_g;
  if (!(x_D >= x_lo && x_D <= x_hi)) {
    ix.note = "no index: the limit state's hazard lies outside the searched range";
    return ix;
  }
  ix.TR_demand = has_axis ? x_D : nan;
  ix.ag_demand_g = h_D.ag_g;

  // The scan grid: log-spaced, the tabulated return periods and x_D.
  std::vector<double> xs;
  const double decades = std::log10(x_hi / x_lo);
  const int n = int(std::ceil(decades * scan_per_decade));
  for (int i = 0; i <= n; ++i) xs.push_back(x_lo * std::pow(10.0, decades * i / n));
  if (has_axis) xs.insert(xs.end(), grid_return_periods.begin(), grid_return_periods.end());
  xs.push_back(x_D);
  std::sort(xs.begin(), xs.end());
  xs.erase(std::unique(xs.begin(), xs.end()), xs.end());
  std::vector<double> fs(xs.size());
  for (std::size_t i = 0; i < xs.size(); ++i) fs[i] = xs[i] == x_D ? row.dc : dc(xs[i]);
  const std::size_t iD = std::size_t(std::find(xs.begin(), xs.end(), x_D) - xs.begin());
  // The crossing D/C = 1 between xs[k-1] (f <= 1) and xs[k] (f > 1), in ln x.
  auto crossing = [&](std::size_t k) {
    const double c = detail::brent_root([&](double u) { return dc(std::exp(u)) - 1.0; }, std::log(xs[k - 1]),
                                        std::log(xs[k]), ln_tol, 0.0);
    return std::isfinite(c) ? std::exp(c) : 0.5 * (xs[k - 1] + xs[k]);
  };
  const bool failing = row.dc > 1.0;
  double x_C = nan;
  if (failing) {
    // The lowest x at which the check fails: the first point of the scan above 1.
    std::size_t k = 0;
    while (k < iD && !(fs[k] > 1.0)) ++k;
    if (k == 0) {
      x_C = x_lo;
      ix.bound = -1;
    } else {
      x_C = crossing(k);
    }
    // Satisfied again between x_C and x_D?
    for (std::size_t j = k; j < iD; ++j)
      if (!(fs[j] > 1.0)) {
        ix.non_monotonic = true;
        // The crossing nearest below x_D, where the check fails for good.
        std::size_t last = iD;
        while (last > 0 && fs[last - 1] > 1.0) --last;
        ix.other_crossing_TR = has_axis ? crossing(last) : nan;
        break;
      }
  } else {
    // The lowest x above x_D at which the check fails.
    std::size_t k = iD + 1;
    while (k < xs.size() && !(fs[k] > 1.0)) ++k;
    if (k == xs.size()) {
      x_C = x_hi;
      ix.bound = +1;
    } else {
      x_C = crossing(k);
    }
    for (std::size_t j = 0; j < iD; ++j)
      if (fs[j] > 1.0) {
        ix.non_monotonic = true;
        ix.other_crossing_TR = has_axis ? (j == 0 ? x_lo : crossing(j)) : nan;
        break;
      }
  }
  const double ag_C = has_axis ? hazard(x_C).ag_g : x_C;
  ix.defined = true;
  ix.ag_capacity_g = ag_C;
  ix.zeta = ag_C / ix.ag_demand_g;
  // A crossing within rounding of x_D can give ag(TR_C) == ag(TR_D) in
  // floating point: the index keeps the side of its check (zetaE < 1 exactly
  // where D/C > 1), the next representable number.
  if (failing && !(ix.zeta < 1.0)) ix.zeta = std::nextafter(1.0, 0.0);
  if (!failing && ix.zeta < 1.0) ix.zeta = 1.0;
  if (has_axis) {
    ix.TR_capacity = x_C;
    ix.TR_ratio = x_C / x_D;
    ix.extrapolated = x_C < tr_min_years || x_C > tr_max_years;
    if (failing && !(ix.TR_ratio < 1.0)) ix.TR_ratio = std::nextafter(1.0, 0.0);
    if (!failing && ix.TR_ratio < 1.0) ix.TR_ratio = 1.0;
  }
  if (ix.bound != 0)
    ix.note = ix.bound < 0 ? "the check fails at the lowest return period searched: the index is at most this"
                           : "the check is satisfied up to the highest return period searched: the index is at least this";
  return ix;
}

}  // namespace assess
