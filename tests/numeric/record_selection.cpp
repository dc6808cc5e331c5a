// Spectrum-compatible record selection: synthetic cases with known answers,
// the band check, fewer-than-N handling, exhaustive optimality against an
// independent brute force, and a run on real PEER records.
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/records/record_io.hpp>

#include "assess/support/error.hpp"
#include "assess/records/record.hpp"
#include "assess/records/record_selection.hpp"
#include "assess/records/response_spectrum.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string>

using assess::Record;
using assess::SelectionOptions;
using assess::SelectionResult;
using assess::test::abs_tol;
using assess::test::rel_tol;
namespace units = assess::units;

namespace {

// Scale factors recovered from exactly scaled copies: the spectra are linear
// in the scale, so only round-off separates them (-).
constexpr double kScaleRelTol = 1e-12;
// Mean/target ratio when the target is a scaled copy of a record spectrum:
// round-off only (-).
constexpr double kRatioAbsTol = 1e-12;
// Reported statistics recomputed from the reported spectra: round-off (-).
constexpr double kStatAbsTol = 1e-12;

Record make_record(const std::string& name, double dt, std::vector<double> acc) {
  Record r;
  r.name = name;
  r.dt = dt;
  r.acc = std::move(acc);
  return r;
}

// Synthetic "earthquakes" with different spectral shapes: a dominant
// frequency f1 (Hz) plus a secondary one, under a sine envelope.
Record synthetic(const std::string& name, double f1, double f2, double amp, double dur = 12.0) {
  std::vector<double> a;
  const double dt = 0.01;
  for (double t = 0.0; t <= dur + 1e-12; t += dt)
    a.push_back(amp * std::sin(units::pi * t / dur) *
                (std::sin(2 * units::pi * f1 * t) + 0.6 * std::sin(2 * units::pi * f2 * t + 0.7)));
  return make_record(name, dt, a);
}

// NTC-shaped target, NTC 2018 [3.2.2]: ag = 0.25 g, S = 1.2, F0 = 2.4,
// TB = 0.15 s, TC = 0.45 s, TD = 2.6 s, eta = 1 (m/s^2).
double ntc_like(double T) {
  const double a = 0.25 * units::g * 1.2, F0 = 2.4, TB = 0.15, TC = 0.45, TD = 2.6;
  if (T < TB) return a * (T / TB + (1 - T / TB) / F0) * F0;
  if (T < TC) return a * F0;
  if (T < TD) return a * F0 * TC / T;
  return a * F0 * TC * TD / (T * T);
}

std::vector<Record> varied_candidates() {
  return {synthetic("r0", 1.1, 3.3, 2.0), synthetic("r1", 2.5, 0.7, 1.5), synthetic("r2", 0.8, 4.1, 3.0),
          synthetic("r3", 3.7, 1.6, 1.0), synthetic("r4", 1.9, 5.3, 2.5), synthetic("r5", 0.55, 2.2, 1.2),
          synthetic("r6", 4.6, 1.2, 2.2), synthetic("r7", 1.4, 0.9, 1.8), synthetic("r8", 2.9, 6.0, 0.9)};
}


// The options these tests were written for: the spectral-shape rules only
// (scale <= 5, no mean-scale limit, no PGA guard); the library's limits are
// tested in record_selection_library.cpp.
SelectionOptions shape_only() {
  SelectionOptions o;
  o.max_scale = 5.0;
  o.max_mean_scale = 1e9;
  o.max_pga_ratio = 0.0;
  return o;
}

// Checks the reported statistics against the reported spectra.
void check_consistency(const SelectionResult& res, const SelectionOptions& opts) {
  REQUIRE(!res.records.empty());
  double lo = 1e300, hi = 0.0, ss = 0.0;
  for (std::size_t j = 0; j < res.periods.size(); ++j) {
    double m = 0.0;
    for (const auto& r : res.records) m += r.psa[j];
    m /= double(res.records.size());
    CHECK_CLOSE(res.mean_psa[j], m, rel_tol(kStatAbsTol));
    lo = std::min(lo, m / res.target[j]);
    hi = std::max(hi, m / res.target[j]);
    ss += std::pow(m / res.target[j] - 1.0, 2);
  }
  CHECK_CLOSE(res.min_ratio, lo, abs_tol(kStatAbsTol));
  CHECK_CLOSE(res.max_ratio, hi, abs_tol(kStatAbsTol));
  CHECK_CLOSE(res.rms_deviation, std::sqrt(ss / double(res.periods.size())), abs_tol(kStatAbsTol));
  CHECK(res.band_satisfied == (lo >= 1 - opts.lower_tol && hi <= 1 + opts.upper_tol));
  CHECK(res.band_satisfied == (res.band_violation == 0.0));
  for (const auto& r : res.records) CHECK(r.scale <= opts.max_scale);
}

}  // namespace

TEST_CASE("scaled copies of one record: every set matches the target after scaling") {
  const Record base = synthetic("base", 1.3, 3.1, 1.0);
  std::vector<Record> cands;
  const std::vector<double> c = {0.5, 0.8, 1.0, 1.7, 2.4, 3.0, 4.0, 0.6};
  for (std::size_t k = 0; k < c.size(); ++k) {
    cands.push_back(base.scaled(c[k]));
    cands.back().name = "copy" + std::to_string(k);
  }
  // Target: twice the base record's spectrum.
  auto target = [&](double T) { return 2.0 * assess::spectral_ordinates(base, T).PSA; };
  SelectionOptions opts = shape_only();
  opts.max_scale = 10.0;
  const auto res = assess::select_records(target, cands, opts);
  REQUIRE(res.records.size() == 7);
  CHECK(res.status == SelectionResult::Status::Compatible);
  for (const auto& r : res.records) CHECK_CLOSE(r.scale, 2.0 / c[r.index], rel_tol(kScaleRelTol));
  CHECK_CLOSE(res.min_ratio, 1.0, abs_tol(kRatioAbsTol));
  CHECK_CLOSE(res.max_ratio, 1.0, abs_tol(kRatioAbsTol));
  check_consistency(res, opts);
}

TEST_CASE("target equal to one record's spectrum times 2: that record, factor 2") {
  const auto cands = varied_candidates();
  auto target = [&](double T) { return 2.0 * assess::spectral_ordinates(cands[4], T).PSA; };
  SelectionOptions opts = shape_only();
  opts.n_records = 1;
  const auto res = assess::select_records(target, cands, opts);
  REQUIRE(res.records.size() == 1);
  CHECK(res.records[0].index == 4);
  CHECK(res.records[0].name == "r4");
  CHECK_CLOSE(res.records[0].scale, 2.0, rel_tol(kScaleRelTol));
  CHECK_CLOSE(res.rms_deviation, 0.0, abs_tol(kRatioAbsTol));
  CHECK(res.band_satisfied);
}

TEST_CASE("PGA scaling sets each record's PGA to Se(0)") {
  const auto cands = varied_candidates();
  SelectionOptions opts = shape_only();
  opts.scale_rule = assess::ScaleRule::Pga;
  opts.n_records = 3;
  const auto res = assess::select_records(ntc_like, cands, opts);
  REQUIRE(res.records.size() == 3);
  for (const auto& r : res.records)
    CHECK_CLOSE(r.scale * cands[r.index].pga(), ntc_like(0.0), rel_tol(kScaleRelTol));
  check_consistency(res, opts);
}

TEST_CASE("exhaustive search finds the optimum of an independent brute force; greedy is no better") {
  const auto cands = varied_candidates();
  SelectionOptions opts = shape_only();
  opts.n_records = 3;
  opts.n_periods = 25;
  opts.range = {0.2, 1.5};
  opts.max_scale = 1e3;  // keep all 9 eligible
  const auto res = assess::select_records(ntc_like, cands, opts);
  REQUIRE(res.exhaustive);
  CHECK(res.combinations == 84.0);  // C(9, 3)
  check_consistency(res, opts);

  // Independent brute force over all 3-subsets with log-least-squares factors.
  const auto T = assess::log_spaced_periods(0.2, 1.5, 25);
  std::vector<std::vector<double>> r(cands.size(), std::vector<double>(T.size()));
  for (std::size_t i = 0; i < cands.size(); ++i) {
    const auto rs = assess::response_spectrum(cands[i], T);
    double sl = 0;
    for (std::size_t j = 0; j < T.size(); ++j) {
      r[i][j] = rs.ordinates[j].PSA / ntc_like(T[j]);
      sl += std::log(r[i][j]);
    }
    for (double& x : r[i]) x *= std::exp(-sl / double(T.size()));
  }
  double best_viol = 1e300, best_rms = 1e300;
  for (std::size_t a = 0; a < 9; ++a)
    for (std::size_t b = a + 1; b < 9; ++b)
      for (std::size_t c = b + 1; c < 9; ++c) {
        double viol = 0, ss = 0;
        for (std::size_t j = 0; j < T.size(); ++j) {
          const double m = (r[a][j] + r[b][j] + r[c][j]) / 3;
          viol += std::max(0.0, 0.9 - m) + std::max(0.0, m - 1.3);
          ss += (m - 1) * (m - 1);
        }
        const double rms = std::sqrt(ss / double(T.size()));
        if (viol < best_viol || (viol == best_viol && rms < best_rms)) best_viol = viol, best_rms = rms;
      }
  CHECK_CLOSE(res.band_violation, best_viol, abs_tol(kStatAbsTol));
  CHECK_CLOSE(res.rms_deviation, best_rms, abs_tol(kStatAbsTol));
  CHECK(res.band_satisfied == (best_viol == 0.0));

  SelectionOptions greedy = opts;
  greedy.max_combinations = 1.0;
  const auto g = assess::select_records(ntc_like, cands, greedy);
  CHECK_FALSE(g.exhaustive);
  REQUIRE(g.records.size() == 3);
  // Lexicographic (violation, rms): the greedy set cannot beat the optimum.
  CHECK(g.band_violation >= res.band_violation - kStatAbsTol);
  if (g.band_violation <= res.band_violation + kStatAbsTol)
    CHECK(g.rms_deviation >= res.rms_deviation - kStatAbsTol);
  check_consistency(g, greedy);
}

TEST_CASE("the band check flags a set whose mean leaves -10 %/+30 %") {
  // One narrow-band record cannot follow a broad target over 0.1-3 s.
  const std::vector<Record> cands = {synthetic("narrow", 5.0, 5.5, 1.0)};
  SelectionOptions opts = shape_only();
  opts.n_records = 1;
  opts.range = {0.1, 3.0};
  opts.max_scale = 1e6;
  const auto res = assess::select_records(ntc_like, cands, opts);
  CHECK(res.status == SelectionResult::Status::NotCompatible);
  CHECK_FALSE(res.band_satisfied);
  CHECK((res.min_ratio < 0.9 || res.max_ratio > 1.3));
  CHECK(res.message.find("NOT compatible") != std::string::npos);
  check_consistency(res, opts);
}

TEST_CASE("fewer eligible candidates than N: all are returned and the status says so") {
  auto cands = varied_candidates();
  cands.resize(4);
  cands.push_back(synthetic("tiny", 1.5, 2.5, 1e-4));  // needs a factor >> 5
  SelectionOptions opts = shape_only();  // N = 7
  const auto res = assess::select_records(ntc_like, cands, opts);
  CHECK(res.status == SelectionResult::Status::FewerThanRequested);
  CHECK(res.records.size() == 4);
  REQUIRE(res.rejected.size() == 1);
  CHECK(res.rejected[0].name == "tiny");
  CHECK(res.rejected[0].scale > opts.max_scale);
  CHECK(res.message.find("only 4 of 7") != std::string::npos);
  check_consistency(res, opts);
}

TEST_CASE("selection is deterministic") {
  const auto cands = varied_candidates();
  SelectionOptions opts = shape_only();
  opts.n_records = 4;
  const auto a = assess::select_records(ntc_like, cands, opts);
  const auto b = assess::select_records(ntc_like, cands, opts);
  REQUIRE(a.records.size() == b.records.size());
  for (std::size_t i = 0; i < a.records.size(); ++i) {
    CHECK(a.records[i].index == b.records[i].index);
    CHECK(a.records[i].scale == b.records[i].scale);
  }
}

TEST_CASE("default rocking period range: [0.5 T_first, 1.5 T_last] clipped to [0.1, 4] s") {
  const auto r = assess::rocking_period_range(0.4, 1.2);
  CHECK_CLOSE(r.T_min, 0.2, rel_tol(1e-15));
  CHECK_CLOSE(r.T_max, 1.8, rel_tol(1e-15));
  const auto c = assess::rocking_period_range(0.1, 5.0);
  CHECK(c.T_min == 0.1);
  CHECK(c.T_max == 4.0);
  CHECK_THROWS_AS(assess::rocking_period_range(1.0, 0.5), assess::InputError);
  CHECK_THROWS_AS(assess::rocking_period_range(9.0, 10.0), assess::InputError);
}

TEST_CASE("real PEER records: 7 of 10 selected for an NTC-shaped target, statistics consistent") {
  const std::string dir = std::string(ASSESS_TEST_DATA_DIR) + "/spectra/records/";
  std::vector<Record> cands;
  for (const char* f : {"RSN285_ITALY_A-BAG000.AT2", "RSN285_ITALY_A-BAG270.AT2", "RSN292_ITALY_A-STU000.AT2",
                        "RSN292_ITALY_A-STU270.AT2", "RSN289_1.AT2", "RSN4346_UBMARCHE.P_A-BEV000.AT2",
                        "RSN4346_UBMARCHE.P_A-BEV270.AT2", "RSN125_FRIULI.A_A-TMZ000.AT2",
                        "RSN125_FRIULI.A_A-TMZ270.AT2", "ISE-WE.AT2"})
    cands.push_back(assess::read_record(dir + f));
  SelectionOptions opts = shape_only();
  opts.range = assess::rocking_period_range(0.5, 1.5);
  const auto res = assess::select_records(ntc_like, cands, opts);
  MESSAGE(res.message);
  for (const auto& r : res.records) MESSAGE(r.name << " f = " << r.scale);
  REQUIRE(res.records.size() == 7);
  CHECK(res.exhaustive);
  // Isernia (PGA 0.068 g) would need a factor > 5 and is rejected: C(9, 7).
  REQUIRE(res.rejected.size() == 1);
  CHECK(res.rejected[0].name == "ISE-WE");
  CHECK(res.combinations == 36.0);
  // Regression (measured on these files): the best set is compatible,
  // mean/target in [0.914, 1.28] over 0.25-2.25 s.
  CHECK(res.band_satisfied);
  check_consistency(res, opts);
}

TEST_CASE("invalid options throw InputError") {
  const auto cands = varied_candidates();
  SelectionOptions o;
  o.n_records = 0;
  CHECK_THROWS_AS(assess::select_records(ntc_like, cands, o), assess::InputError);
  o = {};
  o.range = {1.0, 0.5};
  CHECK_THROWS_AS(assess::select_records(ntc_like, cands, o), assess::InputError);
  o = {};
  CHECK_THROWS_AS(assess::select_records([](double) { return 0.0; }, cands, o), assess::InputError);
  CHECK_THROWS_AS(assess::select_records(ntc_like, {}, o), assess::InputError);
}
