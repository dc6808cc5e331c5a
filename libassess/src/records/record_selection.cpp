// record_selection.cpp: spectrum-compatible selection of scaled records.
//
// Notation:
//   Se(T)          target elastic spectrum (m/s^2), NTC 2018 [3.2.2]
//   S_i(T)         5 %-damped PSA of candidate i (m/s^2), response_spectrum.hpp
//   T_j            check periods, log-spaced in [T_min, T_max] (s)
//   rho_ij         S_i(T_j) / Se(T_j), unscaled ratio (-)
//   f_i            linear scale factor of record i (-): exp(-mean_j ln rho_ij)
//                  (least squares in log space) or Se(0)/PGA_i
//   r_ij = f_i rho_ij, mean ratio m_j = (1/N) sum_{i in set} r_ij
//   band           1 - lower_tol <= m_j <= 1 + upper_tol for all j
//                  (NTC 2018 §3.2.3.6: -10 %/+30 % on the mean spectrum;
//                  REXEL, Iervolino et al. 2010, Bull. Earthq. Eng. 8:339)
//   violation      sum_j max(0, 1 - lower_tol - m_j) + max(0, m_j - 1 - upper_tol)
//   rms            sqrt((1/n) sum_j (m_j - 1)^2)
#include "assess/records/record_selection.hpp"
#include "assess/records/selection_candidates.hpp"

#include "assess/support/error.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

namespace assess {

namespace {

struct Score {
  double violation = 0.0;
  double rms = 0.0;
  /// Lexicographic: band violation first, then RMS deviation.
  bool better_than(const Score& o) const {
    if (violation != o.violation) return violation < o.violation;
    return rms < o.rms;
  }
};

/// Scaled ratios r_ij of the eligible candidates, their scales and groups.
struct Pool {
  const std::vector<std::vector<double>>& r;
  const std::vector<double>& scale;
  const std::vector<int>& event;    // group ids
  const std::vector<int>& station;
  double lo, hi;
  int max_event, max_station;
  double max_scale_sum;             // max_mean_scale * N

  Score score(const std::vector<std::size_t>& set) const {
    const std::size_t n = r.front().size();
    Score s;
    for (std::size_t j = 0; j < n; ++j) {
      double m = 0.0;
      for (std::size_t i : set) m += r[i][j];
      m /= double(set.size());
      s.violation += std::max(0.0, lo - m) + std::max(0.0, m - hi);
      s.rms += (m - 1.0) * (m - 1.0);
    }
    s.rms = std::sqrt(s.rms / double(n));
    return s;
  }
  /// Can candidate i join `set` without breaking the group and scale limits?
  bool fits(const std::vector<std::size_t>& set, std::size_t i, double scale_sum) const {
    if (scale_sum + scale[i] > max_scale_sum * (1.0 + 1e-12)) return false;
    int ne = 0, ns = 0;
    for (std::size_t k : set) {
      ne += event[k] == event[i];
      ns += station[k] == station[i];
    }
    return ne < max_event && ns < max_station;
  }
};

/// C(n, k) as a double (exact up to 2^53, then approximate: only compared
/// with max_combinations).
double binomial(std::size_t n, std::size_t k) {
  if (k > n) return 0.0;
  double c = 1.0;
  for (std::size_t i = 1; i <= k; ++i) c = c * double(n - k + i) / double(i);
  return std::round(c);
}

/// Greedy forward selection, then best-improvement swaps until none helps
/// (feasible moves only).
std::vector<std::size_t> greedy_search(const Pool& p, const std::vector<std::size_t>& order, std::size_t k,
                                       double& evaluated) {
  std::vector<std::size_t> set;
  evaluated = 0.0;
  double ssum = 0.0;
  auto in_set = [&](std::size_t i) { return std::find(set.begin(), set.end(), i) != set.end(); };
  while (set.size() < k) {
    bool found = false;
    std::size_t best_i = 0;
    Score best_s;
    for (std::size_t i : order) {
      if (in_set(i) || !p.fits(set, i, ssum)) continue;
      set.push_back(i);
      const Score s = p.score(set);
      evaluated += 1.0;
      set.pop_back();
      if (!found || s.better_than(best_s)) best_i = i, best_s = s, found = true;
    }
    if (!found) return {};
    set.push_back(best_i);
    ssum += p.scale[best_i];
  }
  Score current = p.score(set);
  for (bool improved = true; improved;) {
    improved = false;
    std::size_t best_pos = k, best_i = 0;
    Score best_s = current;
    for (std::size_t pos = 0; pos < k; ++pos) {
      const std::size_t old = set[pos];
      set.erase(set.begin() + long(pos));
      const double rest = ssum - p.scale[old];
      for (std::size_t i : order) {
        if (i == old || in_set(i) || !p.fits(set, i, rest)) continue;
        set.insert(set.begin() + long(pos), i);
        const Score s = p.score(set);
        evaluated += 1.0;
        set.erase(set.begin() + long(pos));
        if (s.better_than(best_s)) best_s = s, best_pos = pos, best_i = i;
      }
      set.insert(set.begin() + long(pos), old);
    }
    if (best_pos < k) {
      ssum += p.scale[best_i] - p.scale[set[best_pos]];
      set[best_pos] = best_i;
      current = best_s;
      improved = true;
    }
  }
  std::sort(set.begin(), set.end());
  return set;
}

/// Every feasible k-subset of `order` (depth-first, lexicographic in `order`),
/// with the running sums of the ratios per level; keeps the best. Empty if
/// no subset satisfies the group and scale limits.
///
/// The result (the set kept) and `evaluated` (every feasible set, i.e. the
/// number of k-subsets that pass the group and scale limits) are those of
/// the plain enumeration, bit for bit; what is saved is arithmetic:
///  - group limits tested with per-event and per-station counters (O(1));
///  - a set's score stops as soon as it cannot beat the best: its band
///    violation is a sum of non-negative terms (a floating-point sum of such
///    terms never decreases), so a partial violation above the best one is
///    final; when the partial violation equals the best one, a partial sum of
///    squares above the best's (relative margin 1e-9) means a larger RMS;
///  - a subtree (the sets sharing the first members chosen so far) whose
///    every completion is provably worse than the best is only counted, not
///    scored: with c members left to choose from positions q.., the final
///    sum of ratios at T_j lies between the current sum plus the c smallest
///    and plus the c largest ratios at T_j among those positions (group and
///    scale limits ignored: a wider interval), which bounds m_j, hence the
///    violation and (m_j - 1)^2 from below. A subtree is cut only when the
///    bound exceeds the best by a margin of 1e-9 (absolute on the violation,
///    relative on the sum of squares), far above the round-off of the sums
///    (~1e-13), so no set that the plain enumeration would keep is skipped;
///    the RMS bound is used only once a set inside the band is known
///    (violation 0), when no completion can have a smaller violation;
///  - the first bound is the score of the greedy set (greedy_search), computed
///    with the enumeration's own arithmetic, so it is exactly the score the
///    enumeration gives that feasible set: sets as good as it are still
///    scored and the first best in lexicographic order is the one kept.
std::vector<std::size_t> exhaustive_search(const Pool& p, const std::vector<std::size_t>& order, std::size_t k,
                                           double& evaluated) {
  const std::size_t nT = p.r.front().size(), n = order.size();
  // Ratios of the pool in search order, one contiguous row per position.
  std::vector<double> r(n * nT);
  for (std::size_t q = 0; q < n; ++q)
    for (std::size_t j = 0; j < nT; ++j) r[q * nT + j] = p.r[order[q]][j];
  // low/high[(q (k+1) + c) nT + j]: sum of the c smallest / largest ratios at
  // T_j among positions q..n-1 (c <= n - q; unused entries stay 0).
  std::vector<double> low((n + 1) * (k + 1) * nT, 0.0), high((n + 1) * (k + 1) * nT, 0.0);
  {
    std::vector<double> col;
    for (std::size_t q = 0; q < n; ++q)
      for (std::size_t j = 0; j < nT; ++j) {
        col.clear();
        for (std::size_t t = q; t < n; ++t) col.push_back(r[t * nT + j]);
        std::sort(col.begin(), col.end());
        double lo_sum = 0.0, hi_sum = 0.0;
        for (std::size_t c = 1; c <= std::min(k, col.size()); ++c) {
          lo_sum += col[c - 1];
          hi_sum += col[col.size() - c];
          low[(q * (k + 1) + c) * nT + j] = lo_sum;
          high[(q * (k + 1) + c) * nT + j] = hi_sum;
        }
      }
  }
  // Scale factor, event and station of each position (contiguous).
  std::vector<double> scale_at(n);
  std::vector<std::size_t> event_at(n), station_at(n);
  std::size_t n_event = 0, n_station = 0;
  for (std::size_t q = 0; q < n; ++q) {
    scale_at[q] = p.scale[order[q]];
    event_at[q] = std::size_t(p.event[order[q]]);
    station_at[q] = std::size_t(p.station[order[q]]);
    n_event = std::max(n_event, event_at[q] + 1), n_station = std::max(n_station, station_at[q] + 1);
  }
  std::vector<int> in_event(n_event, 0), in_station(n_station, 0);
  const int max_event = p.max_event, max_station = p.max_station;
  std::vector<double> sums((k + 1) * nT, 0.0);
  std::vector<std::size_t> best;
  std::vector<double> scale_sum(k + 1, 0.0);
  Score best_score;
  double best_ss_limit = 0.0;  // best_score.rms^2 nT (1 + 1e-9)
  constexpr double margin = 1e-9;
  evaluated = 0.0;
  const double inv = 1.0 / double(k);
  // A bound before the first set: the greedy set's score (greedy_search,
  // cheap), computed with the enumeration's own arithmetic (ratios added in
  // position order from 0, then times 1/k), i.e. exactly the score the
  // enumeration gives that feasible set. Sets provably worse than it are not
  // scored; sets as good are, so the first best in lexicographic order is
  // still the one kept.
  bool have_bound = false;
  {
    double unused = 0.0;
    std::vector<std::size_t> g = greedy_search(p, order, k, unused);
    if (g.size() == k) {
      std::vector<std::size_t> gpos;
      for (std::size_t q = 0; q < n; ++q)
        if (std::find(g.begin(), g.end(), order[q]) != g.end()) gpos.push_back(q);
      std::vector<double> acc(nT, 0.0);
      for (std::size_t q : gpos)
        for (std::size_t j = 0; j < nT; ++j) acc[j] = acc[j] + r[q * nT + j];
      Score sg;
      for (std::size_t j = 0; j < nT; ++j) {
        const double m = acc[j] * inv;
        sg.violation += std::max(0.0, p.lo - m) + std::max(0.0, m - p.hi);
        sg.rms += (m - 1.0) * (m - 1.0);
      }
      sg.rms = std::sqrt(sg.rms / double(nT));
      best_score = sg;
      best_ss_limit = sg.rms * sg.rms * double(nT) * (1.0 + margin);
      have_bound = true;
    }
  }
  const double scale_limit = p.max_scale_sum * (1.0 + 1e-12);
  // Can no completion of the first d + 1 members (sums at level d + 1, next
  // position q) beat the best? (see above)
  auto subtree_worse = [&](std::size_t d, std::size_t q) {
    if (!have_bound) return false;
    const std::size_t c = k - d - 1;
    const double* sn = &sums[(d + 1) * nT];
    const double* lo_c = &low[(q * (k + 1) + c) * nT];
    const double* hi_c = &high[(q * (k + 1) + c) * nT];
    const bool use_rms = best_score.violation == 0.0;
    double v = 0.0, ss = 0.0;
    for (std::size_t j = 0; j < nT; ++j) {
      const double m_lo = (sn[j] + lo_c[j]) * inv, m_hi = (sn[j] + hi_c[j]) * inv;
      v += std::max(0.0, p.lo - m_hi) + std::max(0.0, m_lo - p.hi);
      if (v > best_score.violation + margin) return true;
      if (use_rms) {
        const double e = m_lo > 1.0 ? m_lo - 1.0 : (m_hi < 1.0 ? 1.0 - m_hi : 0.0);
        ss += e * e;
        if (ss > best_ss_limit * (1.0 + margin)) return true;
      }
    }
    return false;
  };
  // Iterative DFS: pos[d] = position in `order` chosen at depth d. Depths
  // >= count_only are inside a cut subtree: feasible sets counted, not scored.
  std::vector<std::size_t> pos(k, 0);
  std::size_t d = 0, count_only = k;
  pos[0] = 0;
  while (true) {
    if (pos[d] + (k - d) > n) {  // not enough left at this depth: backtrack
      if (d == 0) break;
      --d;
      --in_event[event_at[pos[d]]];
      --in_station[station_at[pos[d]]];
      if (count_only > d) count_only = k;
      ++pos[d];
      continue;
    }
    const std::size_t q = pos[d];
    if (scale_sum[d] + scale_at[q] > scale_limit || in_event[event_at[q]] >= max_event ||
        in_station[station_at[q]] >= max_station) {
      ++pos[d];
      continue;
    }
    if (d + 1 == k) {
      evaluated += 1.0;
      if (count_only == k) {
        const double* ri = &r[q * nT];
        const double* sd = &sums[d * nT];
        Score s;
        bool worse = false;
        for (std::size_t j = 0; j < nT; ++j) {
          const double m = (sd[j] + ri[j]) * inv;
          s.violation += std::max(0.0, p.lo - m) + std::max(0.0, m - p.hi);
          s.rms += (m - 1.0) * (m - 1.0);
          if (have_bound && (s.violation > best_score.violation ||
                            (s.violation == best_score.violation && s.rms > best_ss_limit))) {
            worse = true;
            break;
          }
        }
        if (!worse) {
          s.rms = std::sqrt(s.rms / double(nT));
          if (best.empty() || s.better_than(best_score)) {
            have_bound = true;
            best.clear();
            for (std::size_t t = 0; t < k; ++t) best.push_back(order[pos[t]]);
            best_score = s;
            best_ss_limit = s.rms * s.rms * double(nT) * (1.0 + margin);
          }
        }
      }
      ++pos[d];
      continue;
    }
    scale_sum[d + 1] = scale_sum[d] + scale_at[q];
    ++in_event[event_at[q]];
    ++in_station[station_at[q]];
    if (count_only == k) {
      const double* ri = &r[q * nT];
      const double* sd = &sums[d * nT];
      double* sn = &sums[(d + 1) * nT];
      for (std::size_t j = 0; j < nT; ++j) sn[j] = sd[j] + ri[j];
      if (subtree_worse(d, q + 1)) count_only = d + 1;
    }
    ++d;
    pos[d] = pos[d - 1] + 1;
  }
  std::sort(best.begin(), best.end());
  return best;
}

std::string fmt(double x, int prec = 3) {
  if (!std::isfinite(x)) return std::isnan(x) ? "not a number" : (x > 0 ? "infinite" : "minus infinite");
  std::ostringstream os;
  os.precision(prec);
  os << x;
  return os.str();
}

}  // namespace

PeriodRange rocking_period_range(double T_first, double T_last) {
  if (!(T_first > 0.0) || !(T_last >= T_first) || !std::isfinite(T_last))
    throw InputError("the mechanism's periods (Ts, T_SLV) " + fmt(T_first) + "-" + fmt(T_last) +
                     " s do not give a period range for the record selection: expected 0 < T1 <= T2, finite (s)");
  constexpr double lower_factor = rocking_range_lower_factor, upper_factor = rocking_range_upper_factor,
                   floor_s = rocking_range_floor_s, cap_s = rocking_range_cap_s;
  PeriodRange r;
  r.T_min = std::clamp(lower_factor * T_first, floor_s, cap_s);
  r.T_max = std::clamp(upper_factor * T_last, floor_s, cap_s);
  if (!(r.T_max > r.T_min))
    throw InputError("the mechanism's periods (Ts, T_SLV) " + fmt(T_first) + "-" + fmt(T_last) +
                     " s fall outside [0.1, 4] s, the periods over which records are selected (give the records, "
                     "or \"period_range_s\" in dynamic/select; docs/theory/record-selection.md)");
  return r;
}

void SelectionOptions::validate() const {
  if (n_records < 1) throw InputError("the number of records (count) must be >= 1");
  if (!(range.T_min > 0.0) || !(range.T_max > range.T_min) || !std::isfinite(range.T_max))
    throw InputError("period range must satisfy 0 < T_min < T_max (s)");
  if (!(lower_tol >= 0.0 && lower_tol < 1.0)) throw InputError("lower_tol must be in [0, 1) (fraction)");
  if (!(upper_tol >= 0.0) || !std::isfinite(upper_tol)) throw InputError("upper_tol must be >= 0 (fraction)");
  if (!(max_scale > 0.0)) throw InputError("max_scale must be > 0 (-)");
  if (!(max_mean_scale > 0.0)) throw InputError("max_mean_scale must be > 0 (-)");
  if (!(max_pga_ratio >= 0.0) || !std::isfinite(max_pga_ratio))
    throw InputError("max_pga_ratio must be >= 0 (-, multiple of Se(0) = ag S)");
  if (max_per_event < 1) throw InputError("max_per_event must be >= 1");
  if (max_per_station < 1) throw InputError("max_per_station must be >= 1");
  if (n_periods < 2) throw InputError("n_periods must be >= 2");
  if (!(damping_ratio >= 0.0) || !std::isfinite(damping_ratio))
    throw InputError("damping_ratio must be a finite fraction >= 0");
  if (!(max_combinations >= 1.0)) throw InputError("max_combinations must be >= 1");
  if (pool_size < n_records)
    throw InputError("a set of " + std::to_string(n_records) + " records (count) is more than the " +
                     std::to_string(pool_size) + " best-ranked candidates the search combines: ask for at most " +
                     std::to_string(pool_size) + " records");
  if (!(max_misfit > 0.0)) throw InputError("max_misfit must be > 0 (-)");
}

std::string to_string(SelectionResult::Status s) {
  switch (s) {
    case SelectionResult::Status::Compatible: return "compatible";
    case SelectionResult::Status::NotCompatible: return "not compatible";
    case SelectionResult::Status::FewerThanRequested: return "fewer than requested";
  }
  return "?";
}

SelectionResult select_records(const std::function<double(double)>& target,
                               const std::vector<Record>& candidates, const SelectionOptions& opts) {
  return select_records(target, SelectionCandidates(candidates, opts), opts);
}

SelectionResult select_records(const std::function<double(double)>& target,
                               const std::vector<Record>& candidates, const std::vector<CandidateInfo>& info,
                               const SelectionOptions& opts) {
  return select_records(target, SelectionCandidates(candidates, info, opts), opts);
}

SelectionResult select_records(const std::function<double(double)>& target, const SelectionCandidates& cands,
                               const SelectionOptions& opts) {
  opts.validate();
  cands.check_compatible(opts);
  const std::vector<SelectionCandidates::Candidate>& candidates = cands.candidates();
  SelectionResult res;
  res.periods = cands.periods();
  for (double T : res.periods) {
    const double se = target(T);
    if (!(se > 0.0) || !std::isfinite(se))
      throw InputError("select_records: target spectrum must be > 0 (m/s^2) on the range, got " + fmt(se) +
                       " at T = " + fmt(T) + " s");
    res.target.push_back(se);
  }
  res.target_pga = target(0.0);
  if ((opts.scale_rule == ScaleRule::Pga || opts.max_pga_ratio > 0.0) && !(res.target_pga > 0.0))
    throw InputError("select_records: PGA scaling and the PGA guard need Se(0) > 0 (m/s^2)");

  // Per-record limits: usable period, scale factor, scaled PGA. The spectra
  // are the candidates' unscaled PSA; f S is the scaled record's spectrum.
  const std::size_t nT = res.periods.size();
  std::vector<std::size_t> eligible;
  std::vector<double> scale, dev;
  std::vector<std::vector<double>> ratios, psa;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!candidates[i].usable) {
      res.rejected.push_back({i, candidates[i].name, 0.0,
                              "usable only up to " + fmt(candidates[i].info.max_usable_period_s) +
                                  " s (1/lowest usable frequency) < T_max = " + fmt(opts.range.T_max) + " s"});
    }
  }
  std::map<std::string, int> event_id, station_id;
  std::vector<int> ev, st;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    if (!candidates[i].usable) continue;
    const std::vector<double>& S = candidates[i].psa;
    const CandidateInfo& ci = candidates[i].info;
    std::vector<double> rho(nT);
    double sum_log = 0.0;
    bool zero = false;
    for (std::size_t j = 0; j < nT; ++j) {
      rho[j] = S[j] / res.target[j];
      zero = zero || !(rho[j] > 0.0);
      if (!zero) sum_log += std::log(rho[j]);
    }
    double f = 0.0;
    if (opts.scale_rule == ScaleRule::LeastSquares) f = zero ? 0.0 : std::exp(-sum_log / double(nT));
    else f = candidates[i].pga > 0.0 ? res.target_pga / candidates[i].pga : 0.0;
    if (!(f > 0.0) || f > opts.max_scale) {
      res.rejected.push_back({i, candidates[i].name, f,
                              f > 0.0 ? "scale factor " + fmt(f) + " > max " + fmt(opts.max_scale)
                                      : "zero spectrum"});
      continue;
    }
    const double spga = f * candidates[i].pga;
    if (opts.max_pga_ratio > 0.0 && spga > opts.max_pga_ratio * res.target_pga) {
      res.rejected.push_back({i, candidates[i].name, f,
                              "scaled PGA " + fmt(spga / units::g_n) + " g > " + fmt(opts.max_pga_ratio) +
                                  " Se(0) = " + fmt(opts.max_pga_ratio * res.target_pga / units::g_n) + " g"});
      continue;
    }
    double d2 = 0.0;
    for (double& r : rho) r *= f, d2 += (r - 1.0) * (r - 1.0);
    std::vector<double> p(nT);
    for (std::size_t j = 0; j < nT; ++j) p[j] = f * S[j];
    eligible.push_back(i);
    scale.push_back(f);
    dev.push_back(std::sqrt(d2 / double(nT)));
    ratios.push_back(std::move(rho));
    psa.push_back(std::move(p));
    const std::string ek = ci.event, sk = ci.event + "|" + ci.station;
    ev.push_back(event_id.emplace(ek, int(event_id.size())).first->second);
    st.push_back(station_id.emplace(sk, int(station_id.size())).first->second);
  }
  res.eligible = eligible.size();

  const std::size_t N = static_cast<std::size_t>(opts.n_records);
  if (eligible.empty()) {
    res.status = SelectionResult::Status::FewerThanRequested;
    res.message = "no candidate passes the per-record limits (scale <= " + fmt(opts.max_scale) +
                  ", scaled PGA <= " + fmt(opts.max_pga_ratio) + " ag S, usable period)";
    return res;
  }
  // Rank by individual deviation (ties: candidate order).
  std::vector<std::size_t> ranked(eligible.size());
  for (std::size_t c = 0; c < ranked.size(); ++c) ranked[c] = c;
  std::stable_sort(ranked.begin(), ranked.end(), [&](std::size_t a, std::size_t b) { return dev[a] < dev[b]; });
  std::vector<int> rank_of(eligible.size());
  for (std::size_t k = 0; k < ranked.size(); ++k) rank_of[ranked[k]] = int(k) + 1;

  const Pool pool{ratios, scale, ev, st, 1.0 - opts.lower_tol, 1.0 + opts.upper_tol, opts.max_per_event,
                  opts.max_per_station, opts.max_mean_scale * double(std::min(N, eligible.size()))};
  std::vector<std::size_t> chosen;  // indices into eligible
  const std::size_t k = std::min(N, eligible.size());
  std::vector<std::size_t> order;
  if (binomial(eligible.size(), k) <= opts.max_combinations) {
    for (std::size_t c = 0; c < eligible.size(); ++c) order.push_back(c);
    res.exhaustive = true;
  } else {
    order.assign(ranked.begin(), ranked.begin() + std::min<std::size_t>(ranked.size(), std::size_t(opts.pool_size)));
    std::sort(order.begin(), order.end());
  }
  res.pool = order.size();
  if (binomial(order.size(), k) <= std::max(opts.max_combinations, binomial(std::size_t(opts.pool_size), k)) &&
      binomial(order.size(), k) <= 5e6) {
    chosen = exhaustive_search(pool, order, k, res.combinations);
  } else {
    chosen = greedy_search(pool, order, k, res.combinations);
    res.exhaustive = false;
  }
  // Only the best `pool_size` records were combined and the best set leaves
  // the band: a greedy search with swaps over every eligible record may find
  // a set inside it (issue 30: tried before the site class is relaxed); the
  // better of the two by the same score is kept.
  if (!res.exhaustive && order.size() < eligible.size() && (chosen.empty() || pool.score(chosen).violation > 0.0)) {
    std::vector<std::size_t> all(eligible.size());
    for (std::size_t c = 0; c < all.size(); ++c) all[c] = c;
    double more = 0.0;
    std::vector<std::size_t> g = greedy_search(pool, all, k, more);
    res.combinations += more;
    if (!g.empty() && (chosen.empty() || pool.score(g).better_than(pool.score(chosen)))) {
      chosen = std::move(g);
      res.pool = eligible.size();
    }
  }
  if (chosen.empty()) {
    res.status = SelectionResult::Status::FewerThanRequested;
    res.message = "no set of " + std::to_string(k) + " of the " + std::to_string(eligible.size()) +
                  " eligible records satisfies max " + std::to_string(opts.max_per_event) + " per event, " +
                  std::to_string(opts.max_per_station) + " per station and mean scale <= " + fmt(opts.max_mean_scale);
    return res;
  }

  res.mean_psa.assign(nT, 0.0);
  for (std::size_t c : chosen) {
    const std::size_t i = eligible[c];
    res.records.push_back({i, candidates[i].name, scale[c], scale[c] * candidates[i].pga, dev[c], rank_of[c],
                           dev[c] > opts.max_misfit, psa[c]});
    for (std::size_t j = 0; j < nT; ++j) res.mean_psa[j] += psa[c][j] / double(chosen.size());
    res.mean_scale += scale[c] / double(chosen.size());
    res.max_scaled_pga = std::max(res.max_scaled_pga, scale[c] * candidates[i].pga);
  }
  res.min_ratio = 1e300;
  res.max_ratio = 0.0;
  for (std::size_t j = 0; j < nT; ++j) {
    const double m = res.mean_psa[j] / res.target[j];
    res.min_ratio = std::min(res.min_ratio, m);
    res.max_ratio = std::max(res.max_ratio, m);
  }
  const Score final_score = pool.score(chosen);
  res.rms_deviation = final_score.rms;
  res.band_violation = final_score.violation;
  res.band_satisfied = res.min_ratio >= 1.0 - opts.lower_tol && res.max_ratio <= 1.0 + opts.upper_tol;
  const std::string band = "mean/target in [" + fmt(res.min_ratio) + ", " + fmt(res.max_ratio) + "] over " +
                           fmt(opts.range.T_min) + "-" + fmt(opts.range.T_max) + " s (band [" +
                           fmt(1.0 - opts.lower_tol) + ", " + fmt(1.0 + opts.upper_tol) + "])";
  if (chosen.size() < N) {
    res.status = SelectionResult::Status::FewerThanRequested;
    res.message = "only " + std::to_string(chosen.size()) + " of " + std::to_string(N) +
                  " requested records pass the per-record limits (scale <= " + fmt(opts.max_scale) + "); " + band;
  } else {
    res.status = res.band_satisfied ? SelectionResult::Status::Compatible : SelectionResult::Status::NotCompatible;
    res.message = std::string(res.band_satisfied ? "compatible: " : "NOT compatible: ") + band;
  }
  return res;
}

namespace {

int class_rank(const std::string& c) {
  static const std::string order = "ABCD";
  const auto p = order.find(c);
  return p == std::string::npos ? -1 : int(p);
}

bool in_list(const std::vector<std::string>& list, const std::string& v) {
  return std::find(list.begin(), list.end(), v) != list.end();
}

}  // namespace

std::vector<std::vector<std::string>> site_class_ladder(const std::vector<std::string>& classes, bool relax) {
  std::vector<std::vector<std::string>> steps;
  if (classes.empty()) return {{}};
  steps.push_back(classes);
  if (!relax) return steps;
  std::vector<std::string> wide = classes;
  for (const std::string& c : classes) {
    const int r = class_rank(c);
    if (c == "E") wide.push_back("C"), wide.push_back("D");
    if (r > 0) wide.push_back(std::string(1, "ABCD"[r - 1]));
    if (r >= 0 && r < 3) wide.push_back(std::string(1, "ABCD"[r + 1]));
  }
  std::sort(wide.begin(), wide.end());
  wide.erase(std::unique(wide.begin(), wide.end()), wide.end());
  std::vector<std::string> first = classes;
  std::sort(first.begin(), first.end());
  if (wide != first) steps.push_back(wide);
  steps.push_back({});
  return steps;
}

CandidateInfo candidate_info(const CatalogueEntry& e) {
  CandidateInfo c;
  c.event = e.event + " " + e.date;
  c.station = e.station_code.empty() ? e.station : e.station_code;
  if (std::isfinite(e.lowest_usable_hz) && e.lowest_usable_hz > 0.0) c.max_usable_period_s = 1.0 / e.lowest_usable_hz;
  return c;
}

CatalogueFilterResult filter_catalogue(const std::vector<CatalogueEntry>& entries, const CatalogueFilters& f) {
  if (!(f.Mw_min <= f.Mw_max)) throw InputError("Mw window: expected Mw_min <= Mw_max");
  if (!(f.R_min_km <= f.R_max_km) || f.R_min_km < 0.0) throw InputError("distance window: expected 0 <= R_min <= R_max (km)");
  CatalogueFilterResult out;
  if (!f.Mw_given || !f.R_given)
    out.warnings.push_back(std::string("default ") + (!f.Mw_given ? "Mw window " + fmt(f.Mw_min) + "-" + fmt(f.Mw_max) : "") +
                           (!f.Mw_given && !f.R_given ? " and " : "") +
                           (!f.R_given ? "distance window " + fmt(f.R_min_km) + "-" + fmt(f.R_max_km) + " km" : "") +
                           " used: NTC 2018 §3.2.3.6 asks for records consistent with the site's seismogenesis; "
                           "give the windows from the hazard disaggregation of the site");
  // Site-independent filters first.
  std::vector<std::size_t> pass;
  for (std::size_t i = 0; i < entries.size(); ++i) {
    const CatalogueEntry& e = entries[i];
    std::string why;
    if (!e.usable_for_design) why = "not usable for design: " + e.note;
    else if (!(e.Mw >= f.Mw_min && e.Mw <= f.Mw_max)) why = "Mw " + fmt(e.Mw) + " outside " + fmt(f.Mw_min) + "-" + fmt(f.Mw_max);
    else if (!(e.distance_km >= f.R_min_km && e.distance_km <= f.R_max_km))
      why = e.distance_kind + " " + fmt(e.distance_km) + " km outside " + fmt(f.R_min_km) + "-" + fmt(f.R_max_km) + " km";
    else if (!f.countries.empty() && !in_list(f.countries, e.country)) why = "country " + e.country + " not selected";
    if (why.empty()) pass.push_back(i);
    else out.rejected.push_back({i, e.id, 0.0, why});
  }
  // Site class, relaxed in steps while too few remain.
  const std::vector<std::vector<std::string>> steps = site_class_ladder(f.site_classes, f.relax_site_class);
  std::vector<std::size_t> kept;
  for (std::size_t s = 0; s < steps.size(); ++s) {
    kept.clear();
    for (std::size_t i : pass)
      if (steps[s].empty() || in_list(steps[s], entries[i].site_class)) kept.push_back(i);
    out.site_classes = steps[s];
    if (kept.size() >= f.min_candidates || s + 1 == steps.size()) break;
  }
  if (!f.site_classes.empty() && out.site_classes != f.site_classes) {
    std::string req, got;
    for (const auto& c : f.site_classes) req += c;
    for (const auto& c : out.site_classes) got += c;
    out.warnings.push_back("site class relaxed from " + req + " to " + (got.empty() ? std::string("any class") : got) +
                           ": fewer than " + std::to_string(f.min_candidates) + " candidates of class " + req +
                           " pass the other filters");
  }
  for (std::size_t i : pass) {
    if (std::find(kept.begin(), kept.end(), i) != kept.end()) out.kept.push_back(entries[i]);
    else out.rejected.push_back({i, entries[i].id, 0.0, "site class " + entries[i].site_class + " not accepted"});
  }
  std::sort(out.rejected.begin(), out.rejected.end(),
            [](const RejectedRecord& a, const RejectedRecord& b) { return a.index < b.index; });
  return out;
}

}  // namespace assess
