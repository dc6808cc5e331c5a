// SelectionCandidates (records/selection_candidates.hpp): spectra computed once
// and reused by every selection give the direct selection bit for bit; the
// exhaustive search (with its cuts) against an independent brute force under
// group and mean-scale limits, including the count of feasible sets; options
// that do not match the precomputed spectra are refused.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include "assess/records/record.hpp"
#include "assess/records/record_selection.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/records/selection_candidates.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

using assess::CandidateInfo;
using assess::Record;
using assess::SelectionCandidates;
using assess::SelectionOptions;
using assess::SelectionResult;
using assess::test::abs_tol;
namespace units = assess::units;

namespace {

// Band violation and RMS of mean/Se - 1 recomputed by the brute force from
// the same spectra, summed in another order: round-off only (-).
constexpr double kStatAbsTol = 1e-12;

// Synthetic accelerograms of different spectral shapes (m/s^2): dominant
// frequency f1 (Hz), secondary f2, under a sine envelope of 10 s.
Record synthetic(const std::string& name, double f1, double f2, double amp) {
  Record r;
  r.name = name;
  r.dt = 0.01;
  const double dur = 10.0;
  for (double t = 0.0; t <= dur + 1e-12; t += r.dt)
    r.acc.push_back(amp * std::sin(units::pi * t / dur) *
                    (std::sin(2 * units::pi * f1 * t) + 0.6 * std::sin(2 * units::pi * f2 * t + 0.7)));
  return r;
}

std::vector<Record> twelve_records() {
  const double f1[] = {1.1, 2.5, 0.8, 3.7, 1.9, 0.55, 4.6, 1.4, 2.9, 0.7, 1.6, 3.1};
  const double f2[] = {3.3, 0.7, 4.1, 1.6, 5.3, 2.2, 1.2, 0.9, 6.0, 2.8, 4.4, 1.0};
  const double amp[] = {2.0, 1.5, 3.0, 1.0, 2.5, 1.2, 2.2, 1.8, 0.9, 1.6, 2.1, 1.3};
  std::vector<Record> v;
  for (int i = 0; i < 12; ++i) v.push_back(synthetic("s" + std::to_string(i), f1[i], f2[i], amp[i]));
  return v;
}

// Events of three records each (e0..e3); station names in pairs (st0..st5),
// a station being the pair (event, station name) as in the selection.
std::vector<CandidateInfo> grouped(std::size_t n) {
  std::vector<CandidateInfo> info(n);
  for (std::size_t i = 0; i < n; ++i) {
    info[i].event = "e" + std::to_string(i / 3);
    info[i].station = "st" + std::to_string(i / 2);
  }
  return info;
}

// NTC-shaped target, NTC 2018 [3.2.2] with ag S = a (m/s^2), F0 = 2.4,
// TB = 0.15 s, TC = 0.45 s, TD = 2.6 s, eta = 1.
double ntc_shape(double a, double T) {
  const double F0 = 2.4, TB = 0.15, TC = 0.45, TD = 2.6;
  if (T < TB) return a * (T / TB + (1 - T / TB) / F0) * F0;
  if (T < TC) return a * F0;
  if (T < TD) return a * F0 * TC / T;
  return a * F0 * TC * TD / (T * T);
}

void check_identical(const SelectionResult& a, const SelectionResult& b) {
  CHECK(a.status == b.status);
  CHECK(a.message == b.message);
  CHECK(a.combinations == b.combinations);
  CHECK(a.exhaustive == b.exhaustive);
  CHECK(a.eligible == b.eligible);
  CHECK(a.pool == b.pool);
  CHECK(a.periods == b.periods);
  CHECK(a.target == b.target);
  CHECK(a.mean_psa == b.mean_psa);
  CHECK(a.rms_deviation == b.rms_deviation);
  CHECK(a.band_violation == b.band_violation);
  REQUIRE(a.records.size() == b.records.size());
  for (std::size_t i = 0; i < a.records.size(); ++i) {
    CHECK(a.records[i].index == b.records[i].index);
    CHECK(a.records[i].name == b.records[i].name);
    CHECK(a.records[i].scale == b.records[i].scale);  // to the last bit
    CHECK(a.records[i].psa == b.records[i].psa);
    CHECK(a.records[i].rank == b.records[i].rank);
  }
  REQUIRE(a.rejected.size() == b.rejected.size());
  for (std::size_t i = 0; i < a.rejected.size(); ++i) {
    CHECK(a.rejected[i].index == b.rejected[i].index);
    CHECK(a.rejected[i].reason == b.rejected[i].reason);
  }
}

}  // namespace

TEST_CASE("precomputed candidates: every stripe's selection equals the direct call, bit for bit") {
  const auto recs = twelve_records();
  auto info = grouped(recs.size());
  info[5].max_usable_period_s = 1.0;  // shorter than T_max = 2 s: rejected, no spectrum
  SelectionOptions so;
  so.n_records = 4;
  so.scale_rule = assess::ScaleRule::Pga;  // as the stripes of a fragility study
  so.max_per_event = 2;
  so.max_scale = 8.0;
  const SelectionCandidates cands(recs, info, so);
  REQUIRE(cands.size() == recs.size());
  CHECK_FALSE(cands.candidates()[5].usable);
  CHECK(cands.candidates()[5].psa.empty());
  int compared = 0;
  for (double a : {1.0, 2.0, 3.5, 6.0}) {  // ag S (m/s^2): four stripes
    auto target = [a](double T) { return ntc_shape(a, T); };
    for (double max_comb : {2e6, 20.0, 1.0}) {  // exhaustive, best-pool, greedy
      SelectionOptions o = so;
      o.max_combinations = max_comb;
      o.pool_size = 6;
      CAPTURE(a);
      CAPTURE(max_comb);
      const SelectionResult direct = assess::select_records(target, recs, info, o);
      const SelectionResult reused = assess::select_records(target, cands, o);
      check_identical(direct, reused);
      REQUIRE(!direct.rejected.empty());
      CHECK(direct.rejected.front().index == 5);
      ++compared;
    }
  }
  CHECK(compared == 12);
  // Without grouping info: each record its own event and station.
  SelectionOptions o = so;
  o.scale_rule = assess::ScaleRule::LeastSquares;
  const SelectionCandidates own(recs, o);
  auto target = [](double T) { return ntc_shape(2.5, T); };
  check_identical(assess::select_records(target, recs, o), assess::select_records(target, own, o));
}

TEST_CASE("exhaustive search under group and mean-scale limits: the independent brute force's set and count") {
  const auto recs = twelve_records();
  const auto info = grouped(recs.size());
  // A narrow band (no set inside: the violation decides) and a wide one
  // (sets inside: the RMS decides).
  for (const double band : {0.1, 1.0}) {
    SelectionOptions o;
    o.n_records = 5;
    o.n_periods = 30;
    o.range = {0.2, 2.0};
    o.max_scale = 1e3;
    o.max_pga_ratio = 0.0;
    o.max_per_event = 2;
    o.max_per_station = 1;
    o.lower_tol = 0.5 * band;
    o.upper_tol = band;
    CAPTURE(band);
    auto target = [](double T) { return ntc_shape(3.0, T); };

    // Independent ratios: log-least-squares factor per record (record_selection.hpp).
    const auto T = assess::log_spaced_periods(o.range.T_min, o.range.T_max, o.n_periods);
    const std::size_t n = recs.size(), nT = T.size();
    std::vector<std::vector<double>> r(n, std::vector<double>(nT));
    std::vector<double> f(n);
    for (std::size_t i = 0; i < n; ++i) {
      const auto rs = assess::response_spectrum(recs[i], T);
      double sl = 0;
      for (std::size_t j = 0; j < nT; ++j) sl += std::log(rs.ordinates[j].PSA / target(T[j]));
      f[i] = std::exp(-sl / double(nT));
      for (std::size_t j = 0; j < nT; ++j) r[i][j] = f[i] * rs.ordinates[j].PSA / target(T[j]);
    }
    // A mean-scale limit that binds: the mean factor of all twelve.
    double fsum = 0;
    for (double x : f) fsum += x;
    o.max_mean_scale = fsum / double(n);

    double count = 0, best_v = 1e300, best_rms = 1e300;
    std::vector<std::size_t> best;
    std::vector<std::size_t> idx = {0, 1, 2, 3, 4};
    const std::size_t k = idx.size();
    while (true) {
      // Feasible? Events of 3 (max 2), stations of 2 within an event (max 1), sum of factors.
      bool ok = true;
      double s = 0;
      for (std::size_t a = 0; a < k; ++a) {
        s += f[idx[a]];
        int ne = 0, ns = 0;
        for (std::size_t b = 0; b < k; ++b) ne += idx[b] / 3 == idx[a] / 3, ns += idx[b] / 3 == idx[a] / 3 && idx[b] / 2 == idx[a] / 2;
        ok = ok && ne <= 2 && ns <= 1;
      }
      ok = ok && s <= o.max_mean_scale * double(k) * (1 + 1e-12);
      if (ok) {
        count += 1;
        double v = 0, ss = 0;
        for (std::size_t j = 0; j < nT; ++j) {
          double m = 0;
          for (std::size_t i : idx) m += r[i][j];
          m /= double(k);
          v += std::max(0.0, 1 - o.lower_tol - m) + std::max(0.0, m - 1 - o.upper_tol);
          ss += (m - 1) * (m - 1);
        }
        const double rms = std::sqrt(ss / double(nT));
        if (v < best_v || (v == best_v && rms < best_rms)) best_v = v, best_rms = rms, best = idx;
      }
      // Next k-subset in lexicographic order.
      std::size_t p = k;
      while (p > 0 && idx[p - 1] == n - k + p - 1) --p;
      if (p == 0) break;
      ++idx[p - 1];
      for (std::size_t q = p; q < k; ++q) idx[q] = idx[q - 1] + 1;
    }
    REQUIRE(count > 0);
    REQUIRE(count < 792);  // C(12, 5): the limits exclude some sets

    const SelectionResult res = assess::select_records(target, SelectionCandidates(recs, info, o), o);
    MESSAGE(res.message << "; " << count << " feasible sets");
    CHECK(res.band_satisfied == (band > 0.5));
    CHECK(res.exhaustive);
    CHECK(res.combinations == count);
    REQUIRE(res.records.size() == k);
    for (std::size_t a = 0; a < k; ++a) CHECK(res.records[a].index == best[a]);
    CHECK_CLOSE(res.band_violation, best_v, abs_tol(kStatAbsTol));
    CHECK_CLOSE(res.rms_deviation, best_rms, abs_tol(kStatAbsTol));
  }
}

TEST_CASE("options that do not match the precomputed spectra are refused") {
  const auto recs = twelve_records();
  SelectionOptions so;
  so.n_records = 3;
  const SelectionCandidates cands(recs, so);
  auto target = [](double T) { return ntc_shape(2.0, T); };
  SelectionOptions other = so;
  other.range.T_max = 2.5;
  CHECK_THROWS_AS(assess::select_records(target, cands, other), assess::InputError);
  other = so;
  other.n_periods = 41;
  CHECK_THROWS_AS(assess::select_records(target, cands, other), assess::InputError);
  other = so;
  other.damping_ratio = 0.02;
  CHECK_THROWS_AS(assess::select_records(target, cands, other), assess::InputError);
  // The selection limits may differ from one stripe to the next.
  other = so;
  other.n_records = 2;
  other.max_scale = 6.0;
  CHECK_NOTHROW(assess::select_records(target, cands, other));
  CHECK_THROWS_AS(SelectionCandidates(std::vector<Record>{}, so), assess::InputError);
  CHECK_THROWS_AS(SelectionCandidates(recs, std::vector<CandidateInfo>(2), so), assess::InputError);
}
