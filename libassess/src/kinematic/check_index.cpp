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
#include "kinematic/checks_of_limit_state.hpp"
#include "support/root_find.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <vector>

namespace assess {
namespace {

constexpr double nan = std::numeric_limits<double>::quiet_NaN();
constexpr int scan_per_decade = 6;
constexpr double ln_tol = 1e-12;  // Brent's tolerance on ln x (relative 1e-12 on TR or ag)

bool same_check(const CheckRow& a, const CheckRow& b) {
  return a.code == b.code && a.limit_state == b.limit_state && a.kind == b.kind && a.location == b.location;
}


// The check's D/C along the axis x: TR (years) on the site's hazard, or ag (g) with the shape held.
struct DcAlongAxis {
  const KinematicResult& r;
  const CheckRow& row;
  const HazardAxis& axis;
  LimitState ls;
  HazardParams h_D;  // the limit state's hazard as the check used it
  CheckInput one;    // the check's inputs, its code only

  HazardParams hazard(double x) const {
    if (axis) return axis(x);
    HazardParams h = h_D;
    h.ag_g = x;
    return h;
  }
  double operator()(double x) {
    one.hazard[ls] = hazard(x);
    for (const CheckRow& c : detail::code_checks_of_limit_state(r, one, ls))
      if (same_check(c, row)) return c.dc;
    return nan;
  }
};

// The scan of the axis: log-spaced points, the tabulated return periods and
// x_D (whose D/C is the row's own), with the D/C at each.
struct Scan {
  std::vector<double> xs, fs;
  std::size_t iD = 0;  // index of x_D
};

Scan scan(DcAlongAxis& dc, double x_lo, double x_hi, double x_D, double dc_D) {
  Scan s;
  const double decades = std::log10(x_hi / x_lo);
  const int n = int(std::ceil(decades * scan_per_decade));
  for (int i = 0; i <= n; ++i) s.xs.push_back(x_lo * std::pow(10.0, decades * i / n));
  if (dc.axis) s.xs.insert(s.xs.end(), grid_return_periods.begin(), grid_return_periods.end());
  s.xs.push_back(x_D);
  std::sort(s.xs.begin(), s.xs.end());
  s.xs.erase(std::unique(s.xs.begin(), s.xs.end()), s.xs.end());
  s.fs.resize(s.xs.size());
  for (std::size_t i = 0; i < s.xs.size(); ++i) s.fs[i] = s.xs[i] == x_D ? dc_D : dc(s.xs[i]);
  s.iD = std::size_t(std::find(s.xs.begin(), s.xs.end(), x_D) - s.xs.begin());
  return s;
}

// The crossing D/C = 1 between xs[k-1] (D/C <= 1) and xs[k] (D/C > 1), by Brent in ln x.
double crossing(DcAlongAxis& dc, const Scan& s, std::size_t k) {
  const double c = detail::brent_root([&](double u) { return dc(std::exp(u)) - 1.0; }, std::log(s.xs[k - 1]),
                                      std::log(s.xs[k]), ln_tol, 0.0);
  return std::isfinite(c) ? std::exp(c) : 0.5 * (s.xs[k - 1] + s.xs[k]);
}

// The crossing on the side of the check: a failing check's lowest x at which
// it fails; a satisfied check's lowest x above x_D at which it fails. The
// other side's crossing marks a D/C that is not monotonic.
void locate(CheckIndex& ix, DcAlongAxis& dc, const Scan& s, bool failing, double& x_C) {
  const bool tr = static_cast<bool>(dc.axis);
  const double x_lo = s.xs.front(), x_hi = s.xs.back();
  if (failing) {
    std::size_t k = 0;
    while (k < s.iD && !(s.fs[k] > 1.0)) ++k;
    x_C = k == 0 ? x_lo : crossing(dc, s, k);
    ix.bound = k == 0 ? -1 : 0;
    for (std::size_t j = k; j < s.iD; ++j)
      if (!(s.fs[j] > 1.0)) {  // satisfied again between x_C and x_D
        ix.non_monotonic = true;
        std::size_t last = s.iD;  // the crossing nearest below x_D, where the check fails for good
        while (last > 0 && s.fs[last - 1] > 1.0) --last;
        ix.other_crossing_TR = tr ? crossing(dc, s, last) : nan;
        break;
      }
    return;
  }
  std::size_t k = s.iD + 1;
  while (k < s.xs.size() && !(s.fs[k] > 1.0)) ++k;
  x_C = k == s.xs.size() ? x_hi : crossing(dc, s, k);
  ix.bound = k == s.xs.size() ? +1 : 0;
  for (std::size_t j = 0; j < s.iD; ++j)
    if (s.fs[j] > 1.0) {  // the check fails at a lower x
      ix.non_monotonic = true;
      ix.other_crossing_TR = tr ? (j == 0 ? x_lo : crossing(dc, s, j)) : nan;
      break;
    }
}

}  // namespace

CheckIndex check_index(const KinematicResult& r, const CheckInput& in, const CheckRow& row, const HazardAxis& axis) {
  CheckIndex ix;
  if (row.kind != "strength" && row.kind != "displacement") {
    ix.note = {no_dynamic_index()};
    return ix;
  }
  if (!std::isfinite(row.dc) || row.no_verdict) {
    ix.note = {{"index.no_finite_dc", {}}};
    return ix;
  }
  const LimitState ls = parse_limit_state(row.limit_state);
  DcAlongAxis dc{r, row, axis, ls, in.hazard.at(ls), in};
  dc.one.codes = {parse_code_edition(row.code)};
  dc.one.sld = ls == LimitState::SLD;
  const bool tr = static_cast<bool>(axis);
  ix.shape_held = !tr;
  const double x_D = tr ? dc.h_D.TR : dc.h_D.ag_g;
  const double x_lo = tr ? check_index_tr_min : check_index_ag_min_g;
  const double x_hi = tr ? check_index_tr_max : check_index_ag_max_g;
  if (!(x_D >= x_lo && x_D <= x_hi)) {
    ix.note = {{"index.hazard_outside", {}}};
    return ix;
  }
  ix.TR_demand = tr ? x_D : nan;
  ix.ag_demand_g = dc.h_D.ag_g;
  const bool failing = row.dc > 1.0;
  double x_C = nan;
  locate(ix, dc, scan(dc, x_lo, x_hi, x_D, row.dc), failing, x_C);

  ix.defined = true;
  ix.ag_capacity_g = tr ? dc.hazard(x_C).ag_g : x_C;
  ix.zeta = ix.ag_capacity_g / ix.ag_demand_g;
  // A crossing within rounding of x_D can give ag(TR_C) == ag(TR_D) in
  // floating point: the index keeps the side of its check (zetaE < 1 exactly
  // where D/C > 1), the next representable number.
  if (failing && !(ix.zeta < 1.0)) ix.zeta = std::nextafter(1.0, 0.0);
  if (!failing && ix.zeta < 1.0) ix.zeta = 1.0;
  if (tr) {
    ix.TR_capacity = x_C;
    ix.TR_ratio = x_C / x_D;
    ix.extrapolated = x_C < tr_min_years || x_C > tr_max_years;
    if (failing && !(ix.TR_ratio < 1.0)) ix.TR_ratio = std::nextafter(1.0, 0.0);
    if (!failing && ix.TR_ratio < 1.0) ix.TR_ratio = 1.0;
  }
  if (ix.bound != 0)
    ix.note = {{ix.bound < 0 ? "index.bound_below" : "index.bound_above", {}}};
  return ix;
}

}  // namespace assess
