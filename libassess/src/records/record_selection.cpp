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

#include "assess/support/error.hpp"
#include "support/parallel_for.hpp"
#include "assess/records/response_spectrum.hpp"

#include <algorithm>
#include <cmath>
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

class SetScorer {
 public:
  SetScorer(const std::vector<std::vector<double>>& ratios, double lo, double hi)
      : r_(ratios), lo_(lo), hi_(hi) {}

  /// Score of the set given by indices into ratios.
  Score score(const std::vector<std::size_t>& set) const {
    const std::size_t n = r_.front().size();
    Score s;
    for (std::size_t j = 0; j < n; ++j) {
      double m = 0.0;
      for (std::size_t i : set) m += r_[i][j];
      m /= double(set.size());
      s.violation += std::max(0.0, lo_ - m) + std::max(0.0, m - hi_);
      s.rms += (m - 1.0) * (m - 1.0);
    }
    s.rms = std::sqrt(s.rms / double(n));
    return s;
  }

 private:
  const std::vector<std::vector<double>>& r_;
  double lo_, hi_;
};

/// C(n, k) as a double (exact up to 2^53, then approximate: only compared
/// with max_combinations).
double binomial(std::size_t n, std::size_t k) {
  if (k > n) return 0.0;
  double c = 1.0;
  for (std::size_t i = 1; i <= k; ++i) c = c * double(n - k + i) / double(i);
  return std::round(c);
}

/// Every k-subset of {0..n-1} in lexicographic order; keeps the best.
std::vector<std::size_t> exhaustive_search(const SetScorer& sc, std::size_t n, std::size_t k,
                                           double& evaluated) {
  std::vector<std::size_t> idx(k), best;
  for (std::size_t i = 0; i < k; ++i) idx[i] = i;
  Score best_score;
  evaluated = 0.0;
  while (true) {
    const Score s = sc.score(idx);
    evaluated += 1.0;
    if (best.empty() || s.better_than(best_score)) best = idx, best_score = s;
    // next combination
    std::size_t i = k;
    while (i > 0 && idx[i - 1] == n - k + i - 1) --i;
    if (i == 0) break;
    ++idx[i - 1];
    for (std::size_t j = i; j < k; ++j) idx[j] = idx[j - 1] + 1;
  }
  return best;
}

/// Greedy forward selection, then best-improvement swaps until none helps.
std::vector<std::size_t> greedy_search(const SetScorer& sc, std::size_t n, std::size_t k,
                                       double& evaluated) {
  std::vector<std::size_t> set;
  std::vector<bool> used(n, false);
  evaluated = 0.0;
  while (set.size() < k) {
    std::size_t best_i = n;
    Score best_s;
    for (std::size_t i = 0; i < n; ++i) {
      if (used[i]) continue;
      set.push_back(i);
      const Score s = sc.score(set);
      evaluated += 1.0;
      set.pop_back();
      if (best_i == n || s.better_than(best_s)) best_i = i, best_s = s;
    }
    set.push_back(best_i);
    used[best_i] = true;
  }
  Score current = sc.score(set);
  for (bool improved = true; improved;) {
    improved = false;
    std::size_t best_pos = k, best_i = n;
    Score best_s = current;
    for (std::size_t pos = 0; pos < k; ++pos) {
      const std::size_t old = set[pos];
      for (std::size_t i = 0; i < n; ++i) {
        if (used[i]) continue;
        set[pos] = i;
        const Score s = sc.score(set);
        evaluated += 1.0;
        if (s.better_than(best_s)) best_s = s, best_pos = pos, best_i = i;
      }
      set[pos] = old;
    }
    if (best_pos < k) {
      used[set[best_pos]] = false;
      used[best_i] = true;
      set[best_pos] = best_i;
      current = best_s;
      improved = true;
    }
  }
  std::sort(set.begin(), set.end());
  return set;
}

std::string fmt(double x, int prec = 3) {
  std::ostringstream os;
  os.precision(prec);
  os << x;
  return os.str();
}

}  // namespace

PeriodRange rocking_period_range(double T_first, double T_last) {
  if (!(T_first > 0.0) || !(T_last >= T_first) || !std::isfinite(T_last))
    throw InputError("rocking_period_range: need 0 < T_first <= T_last (s)");
  constexpr double lower_factor = 0.5, upper_factor = 1.5, floor_s = 0.1, cap_s = 4.0;
  PeriodRange r;
  r.T_min = std::clamp(lower_factor * T_first, floor_s, cap_s);
  r.T_max = std::clamp(upper_factor * T_last, floor_s, cap_s);
  if (!(r.T_max > r.T_min))
    throw InputError("rocking_period_range: mechanism periods " + fmt(T_first) + "-" + fmt(T_last) +
                     " s fall outside [0.1, 4] s");
  return r;
}

void SelectionOptions::validate() const {
  if (n_records < 1) throw InputError("n_records must be >= 1");
  if (!(range.T_min > 0.0) || !(range.T_max > range.T_min) || !std::isfinite(range.T_max))
    throw InputError("period range must satisfy 0 < T_min < T_max (s)");
  if (!(lower_tol >= 0.0 && lower_tol < 1.0)) throw InputError("lower_tol must be in [0, 1) (fraction)");
  if (!(upper_tol >= 0.0) || !std::isfinite(upper_tol)) throw InputError("upper_tol must be >= 0 (fraction)");
  if (!(max_scale > 0.0)) throw InputError("max_scale must be > 0 (-)");
  if (n_periods < 2) throw InputError("n_periods must be >= 2");
  if (!(damping_ratio >= 0.0) || !std::isfinite(damping_ratio))
    throw InputError("damping_ratio must be a finite fraction >= 0");
  if (!(max_combinations >= 1.0)) throw InputError("max_combinations must be >= 1");
}

std::string to_string(SelectionResult::Status s) {
  switch (s) {
    case SelectionResult::Status::Compatible: return "compatible";
    case SelectionResult::Status::NotCompatible: return "not compatible";
    case SelectionResult::Status::FewerThanRequested: return "fewer than requested";
  }
  return "?";
}

std::vector<double> selection_periods(const SelectionOptions& opts) {
  opts.validate();
  return log_spaced_periods(opts.range.T_min, opts.range.T_max, opts.n_periods);
}

SelectionResult select_records(const std::function<double(double)>& target,
                               const std::vector<Record>& candidates, const SelectionOptions& opts) {
  const std::vector<double> periods = selection_periods(opts);
  const ResponseOptions ro{opts.damping_ratio, ResponseOptions{}.min_steps_per_period};
  std::vector<ResponseSpectrum> spectra(candidates.size());
  detail::parallel_for(candidates.size(),
                       [&](std::size_t i) { spectra[i] = response_spectrum(candidates[i], periods, ro); });
  return select_records(target, candidates, opts, spectra);
}

SelectionResult select_records(const std::function<double(double)>& target, const std::vector<Record>& candidates,
                               const SelectionOptions& opts, const std::vector<ResponseSpectrum>& spectra) {
  opts.validate();
  if (candidates.empty()) throw InputError("select_records: no candidate records");
  SelectionResult res;
  res.periods = log_spaced_periods(opts.range.T_min, opts.range.T_max, opts.n_periods);
  if (spectra.size() != candidates.size())
    throw InputError("select_records: " + std::to_string(spectra.size()) + " spectra for " +
                     std::to_string(candidates.size()) + " candidates");
  for (const ResponseSpectrum& rs : spectra)
    if (rs.ordinates.size() != res.periods.size())
      throw InputError("select_records: a candidate spectrum has " + std::to_string(rs.ordinates.size()) +
                       " ordinates, expected one per check period (" + std::to_string(res.periods.size()) + ")");
  for (double T : res.periods) {
    const double se = target(T);
    if (!(se > 0.0) || !std::isfinite(se))
      throw InputError("select_records: target spectrum must be > 0 (m/s^2) on the range, got " + fmt(se) +
                       " at T = " + fmt(T) + " s");
    res.target.push_back(se);
  }
  const double pga_target = opts.scale_rule == ScaleRule::Pga ? target(0.0) : 0.0;
  if (opts.scale_rule == ScaleRule::Pga && !(pga_target > 0.0))
    throw InputError("select_records: PGA scaling needs Se(0) > 0 (m/s^2)");

  // Scale factors and scaled ratios of the eligible candidates.
  const std::size_t nT = res.periods.size();
  std::vector<std::size_t> eligible;
  std::vector<double> scale;
  std::vector<std::vector<double>> ratios, psa;
  for (std::size_t i = 0; i < candidates.size(); ++i) {
    const ResponseSpectrum& rs = spectra[i];
    std::vector<double> rho(nT);
    double sum_log = 0.0;
    bool zero = false;
    for (std::size_t j = 0; j < nT; ++j) {
      rho[j] = rs.ordinates[j].PSA / res.target[j];
      zero = zero || !(rho[j] > 0.0);
      if (!zero) sum_log += std::log(rho[j]);
    }
    double f = 0.0;
    if (opts.scale_rule == ScaleRule::LeastSquares) f = zero ? 0.0 : std::exp(-sum_log / double(nT));
    else f = candidates[i].pga() > 0.0 ? pga_target / candidates[i].pga() : 0.0;
    if (!(f > 0.0) || f > opts.max_scale) {
      res.rejected.push_back({i, candidates[i].name, f,
                              f > 0.0 ? "scale factor " + fmt(f) + " > max " + fmt(opts.max_scale)
                                      : "zero spectrum"});
      continue;
    }
    for (double& r : rho) r *= f;
    std::vector<double> p(nT);
    for (std::size_t j = 0; j < nT; ++j) p[j] = f * rs.ordinates[j].PSA;
    eligible.push_back(i);
    scale.push_back(f);
    ratios.push_back(std::move(rho));
    psa.push_back(std::move(p));
  }

  const std::size_t N = static_cast<std::size_t>(opts.n_records);
  std::vector<std::size_t> chosen;  // indices into eligible
  if (eligible.empty()) {
    res.status = SelectionResult::Status::FewerThanRequested;
    res.message = "no candidate can be scaled within max_scale = " + fmt(opts.max_scale);
    return res;
  }
  const SetScorer scorer(ratios, 1.0 - opts.lower_tol, 1.0 + opts.upper_tol);
  if (eligible.size() <= N) {
    for (std::size_t i = 0; i < eligible.size(); ++i) chosen.push_back(i);
    res.exhaustive = true;
    res.combinations = 1.0;
  } else if (binomial(eligible.size(), N) <= opts.max_combinations) {
    chosen = exhaustive_search(scorer, eligible.size(), N, res.combinations);
    res.exhaustive = true;
  } else {
    chosen = greedy_search(scorer, eligible.size(), N, res.combinations);
  }

  res.mean_psa.assign(nT, 0.0);
  for (std::size_t c : chosen) {
    res.records.push_back({eligible[c], candidates[eligible[c]].name, scale[c], psa[c]});
    for (std::size_t j = 0; j < nT; ++j) res.mean_psa[j] += psa[c][j] / double(chosen.size());
  }
  res.min_ratio = 1e300;
  res.max_ratio = 0.0;
  for (std::size_t j = 0; j < nT; ++j) {
    const double m = res.mean_psa[j] / res.target[j];
    res.min_ratio = std::min(res.min_ratio, m);
    res.max_ratio = std::max(res.max_ratio, m);
  }
  const Score final_score = scorer.score(chosen);
  res.rms_deviation = final_score.rms;
  res.band_violation = final_score.violation;
  res.band_satisfied = res.min_ratio >= 1.0 - opts.lower_tol && res.max_ratio <= 1.0 + opts.upper_tol;
  const std::string band = "mean/target in [" + fmt(res.min_ratio) + ", " + fmt(res.max_ratio) + "] over " +
                           fmt(opts.range.T_min) + "-" + fmt(opts.range.T_max) + " s (band [" +
                           fmt(1.0 - opts.lower_tol) + ", " + fmt(1.0 + opts.upper_tol) + "])";
  if (chosen.size() < N) {
    res.status = SelectionResult::Status::FewerThanRequested;
    res.message = "only " + std::to_string(chosen.size()) + " of " + std::to_string(N) +
                  " requested records can be scaled within max_scale = " + fmt(opts.max_scale) + "; " + band;
  } else {
    res.status = res.band_satisfied ? SelectionResult::Status::Compatible : SelectionResult::Status::NotCompatible;
    res.message = std::string(res.band_satisfied ? "compatible: " : "NOT compatible: ") + band;
  }
  return res;
}

}  // namespace assess
