// tie_design.cpp: required tie forces per check (docs/theory/ties.md §4).
#include "assess/kinematic/tie_design.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>

namespace assess {
namespace {

bool same_check(const CheckRow& a, const RequiredTieForce& b) {
  return a.code == b.code && a.limit_state == b.limit_state && a.kind == b.kind && a.location == b.location;
}

}  // namespace

std::vector<RequiredTieForce> required_tie_forces(const Chain& chain, const KinematicOptions& options,
                                                  const CheckInput& in, const std::vector<TieRestraint>& ties,
                                                  std::size_t level, double spacing) {
  KinematicOptions opt = options;
  opt.curve_points = 3;  // the checks read the curve through the analysis, not its table
  std::vector<TieRestraint> t = ties;
  const double count = t.at(level).count;
  // D/C of every check with the level at strength T (N).
  // The chain without any level (the checks' fallback once the ties fail), once.
  const auto bare = std::make_shared<const KinematicResult>(analyse_kinematic(chain, opt, {}));
  bool complete = true;  // the last analysis had a complete capacity curve
  auto rows_at = [&](double T) {
    t[level].capacity = T;
    t[level].pretension = std::min(ties[level].pretension, T);
    const KinematicResult r = analyse_kinematic(chain, opt, t, bare);
    complete = r.curve_complete();
    if (!r.activates) return std::vector<CheckRow>{};
    return run_code_checks(r, in);
  };
  auto dc_of = [](const std::vector<CheckRow>& rows, const RequiredTieForce& f) {
    for (const CheckRow& row : rows)
      if (same_check(row, f)) return std::isfinite(row.dc) ? row.dc : std::numeric_limits<double>::infinity();
    return std::numeric_limits<double>::infinity();
  };
  // The rows of the mechanism with the level at a large strength, so that
  // every check (displacement ones need a complete curve) is listed.
  const double W = bare->sum_W;
  const double T_max = 100.0 * W;
  std::vector<RequiredTieForce> out;
  const std::vector<CheckRow> zero = rows_at(0.0);
  std::vector<CheckRow> keys = rows_at(0.05 * W);
  if (keys.size() < zero.size()) keys = zero;
  for (const CheckRow& k : keys) {
    RequiredTieForce f;
    f.code = k.code;
    f.limit_state = k.limit_state;
    f.kind = k.kind;
    f.location = k.location;
    f.dc_without = dc_of(zero, f);
    if (f.dc_without <= 1.0) {
      out.push_back(f);
      continue;
    }
    // Doubling: a stronger level cannot give back a capacity curve that a
    // weaker one lost (it only holds the wall longer), so a displacement check
    // whose tied curve is incomplete stops the search (not reachable).
    double lo = 0.0, hi = 0.05 * W;
    double dc_hi = dc_of(rows_at(hi), f);
    bool stuck = f.kind == "displacement" && !complete;
    while (dc_hi > 1.0 && hi < T_max && !stuck) {
      lo = hi;
      hi *= 2.0;
      dc_hi = dc_of(rows_at(hi), f);
      stuck = f.kind == "displacement" && !complete;
    }
    if (dc_hi > 1.0) {
      // No force reaches it: reported as such, with the reason, never as a number.
      f.reachable = false;
      const double dc = dc_hi;
      f.reason = stuck ? "with the level at " + std::to_string(static_cast<long long>(hi / 1e3)) +
                             " kN the mechanism has no complete capacity curve (the level holds it beyond three times "
                             "its size): its displacement capacity is that of the wall without the level"
                       : "the check is not satisfied even with the level at " +
                             std::to_string(static_cast<long long>(hi / 1e3)) + " kN (100 times the mechanism's weight)" +
                             (std::isfinite(dc) ? ", D/C " + std::to_string(dc).substr(0, 5) : "");
      f.level_force = f.per_tie = f.per_metre = 0.0;
      out.push_back(f);
      continue;
    } else {
      // To 1e-7 relative; a check that any level, however weak, satisfies
      // (the tied wall that does not rock under the short-period demand,
      // docs/theory/ties.md §4) ends at 1e-9 of the weight, reported as such.
      while (hi - lo > 1e-7 * hi && hi > 1e-9 * W) {
        const double mid = 0.5 * (lo + hi);
        (dc_of(rows_at(mid), f) > 1.0 ? lo : hi) = mid;
      }
      f.level_force = hi;
    }
    f.per_tie = f.level_force / count;
    f.per_metre = f.per_tie / spacing;
    out.push_back(f);
  }
  return out;
}

std::vector<double> tie_elongations_at(const Chain& chain, const KinematicResult& r,
                                       const std::vector<TieRestraint>& ties, double d_star) {
  std::vector<double> out;
  if (ties.empty()) return out;
  const double dk = d_star / r.d_star_per_dk;
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(chain.n_coordinates()));
  const int steps = std::max(1, static_cast<int>(std::ceil(std::fabs(dk) / (chain.size() / 200.0))));
  for (int i = 1; i <= steps; ++i) {
    Eigen::VectorXd next;
    if (!chain.solve_configuration(r.control_block, r.control_point, dk * i / steps, q, next))
      return std::vector<double>(ties.size(), std::numeric_limits<double>::quiet_NaN());
    q = next;
  }
  for (const TieRestraint& t : ties) out.push_back(tie_elongation(chain, t, q));
  return out;
}

}  // namespace assess
