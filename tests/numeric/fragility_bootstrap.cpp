// fit_fragility on synthetic studies whose outcomes come from a known
// lognormal (no dynamics): the MSA fit and its bootstrap band against the
// Fisher standard errors; the IDA moments of the bracketed collapse
// intensities against the drawn ones; censored IDA curves fall back to the
// MLE; failed analyses count as reaching the limit state; determinism of
// the bootstrap (same seed, same bounds).
#include <doctest/doctest.h>

#include "check_close.hpp"

#include <assess/risk/fragility_result.hpp>
#include <assess/support/units.hpp>

#include <cmath>
#include <cstdint>
#include <vector>

using namespace assess;
using assess::test::abs_tol;
using assess::test::rel_tol;

namespace {

std::uint64_t splitmix64(std::uint64_t& s) {
  std::uint64_t z = (s += 0x9e3779b97f4a7c15ULL);
  z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
  z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
  return z ^ (z >> 31);
}
double uniform(std::uint64_t& s) { return (double(splitmix64(s) >> 11) + 0.5) * 0x1.0p-53; }
// Standard normal by Box-Muller.
double normal(std::uint64_t& s) { return std::sqrt(-2 * std::log(uniform(s))) * std::cos(2 * units::pi * uniform(s)); }

// A study with `levels` stripes of `records` records, one polarity, one
// restitution value; the mechanism is never analysed.
FragilityStudy synthetic_study(const std::vector<double>& ims, std::size_t records, FragilityMethod m) {
  FragilityStudy st;
  st.options.method = m;
  st.options.bootstrap = 400;
  st.options.seed = 7;
  st.restitution_labels = {"Housner"};
  st.polarities = {false};
  for (std::size_t r = 0; r < records; ++r) st.record_files.push_back("r" + std::to_string(r));
  for (double im : ims) {
    Stripe s;
    s.im = im;
    s.TR = 100;
    for (std::size_t r = 0; r < records; ++r) s.records.push_back({r, 1.0});
    st.stripes.push_back(s);
  }
  return st;
}

FragilityRow row(std::uint64_t id, std::size_t stripe, bool over) {
  FragilityRow r;
  r.id = id;
  r.stripe = stripe;
  r.overturned = over;
  r.dc_energy = over ? 1.5 : 0.5;
  r.dc_displacement = over ? 2.0 : 0.5;
  return r;
}

}  // namespace

TEST_CASE("MSA: fit within its standard errors, bootstrap band ~ +-1.645 SE, deterministic") {
  const LognormalFragility truth{3.0, 0.45};  // m/s^2, -
  const std::vector<double> ims{1.0, 1.5, 2.0, 2.5, 3.0, 3.5, 4.2, 5.0, 6.0, 7.5};
  const FragilityStudy st = synthetic_study(ims, 40, FragilityMethod::stripes);
  std::uint64_t s = 42;
  std::vector<FragilityRow> rows;
  for (std::size_t i = 0; i < ims.size(); ++i)
    for (std::size_t r = 0; r < 40; ++r) rows.push_back(row(rows.size(), i, uniform(s) < truth.probability(ims[i])));
  const FragilityResult res = fit_fragility(st, rows);
  const FragilityCurve& c = res.curve(0, FragilityState::overturning);
  REQUIRE(c.fit.ok());
  CHECK(std::fabs(std::log(c.fit.fragility.theta / truth.theta)) <= 3 * c.fit.se_ln_theta);
  CHECK(std::fabs(c.fit.fragility.beta - truth.beta) <= 3 * c.fit.se_beta);
  REQUIRE(c.bounds);
  CHECK(c.bounds->fitted == 400);
  // The percentile band of ln theta against the asymptotic +-1.645 SE: the
  // two estimators of the same sampling spread agree within 30 % at n = 400.
  const double band = std::log(c.bounds->theta_hi / c.bounds->theta_lo);
  CHECK_CLOSE(band, 2 * 1.645 * c.fit.se_ln_theta, rel_tol(0.30));
  CHECK(c.bounds->theta_lo < c.fit.fragility.theta);
  CHECK(c.bounds->theta_hi > c.fit.fragility.theta);
  // Same seed, same bounds (the generator is counter-based).
  const FragilityResult again = fit_fragility(st, rows);
  CHECK(again.curve(0, FragilityState::overturning).bounds->theta_lo == c.bounds->theta_lo);
  CHECK(again.curve(0, FragilityState::overturning).bounds->beta_hi == c.bounds->beta_hi);
  // No hazard curve in this study: no risk figure.
  CHECK_FALSE(c.has_risk);

  // A failed analysis counts as reaching the limit state.
  std::vector<FragilityRow> bad = rows;
  bad[0].ok = false;
  bad[0].overturned = false;
  const FragilityResult rb = fit_fragility(st, bad);
  CHECK(rb.curve(0, FragilityState::overturning).stripes[0].k == res.curve(0, FragilityState::overturning).stripes[0].k + (rows[0].overturned ? 0 : 1));
  CHECK(rb.curve(0, FragilityState::overturning).stripes[0].failed == 1);
  CHECK(rb.failed == 1);
}

TEST_CASE("IDA: moments of the bracketed collapse intensities; censored curves fall back to the MLE") {
  // 30 records with im_c ~ lognormal(theta 3, beta 0.4), levels 3 % apart.
  const LognormalFragility truth{3.0, 0.4};
  std::vector<double> ims;
  for (double im = 0.5; im < 40.0; im *= 1.03) ims.push_back(im);
  const std::size_t R = 30;
  std::uint64_t s = 2024;
  std::vector<double> imc;
  for (std::size_t r = 0; r < R; ++r) imc.push_back(truth.theta * std::exp(truth.beta * normal(s)));
  const FragilityStudy st = synthetic_study(ims, R, FragilityMethod::ida);
  std::vector<FragilityRow> rows;
  for (std::size_t i = 0; i < ims.size(); ++i)
    for (std::size_t r = 0; r < R; ++r) rows.push_back(row(rows.size(), i, ims[i] >= imc[r]));
  const FragilityResult res = fit_fragility(st, rows);
  const FragilityCurve& c = res.curve(0, FragilityState::overturning);
  REQUIRE(c.fit.ok());
  REQUIRE(c.collapse_im.size() == R);
  // Each im_c is bracketed by two levels 3 % apart and reported at their
  // geometric mean: |ln error| <= ln(1.03)/2 per record, so the mean of ln
  // and the standard deviation move by at most that much.
  double m = 0;
  for (double v : imc) m += std::log(v) / R;
  double ss = 0;
  for (double v : imc) ss += (std::log(v) - m) * (std::log(v) - m);
  const double sd = std::sqrt(ss / (R - 1));
  const double level_half = 0.5 * std::log(1.03);
  CHECK_CLOSE(std::log(c.fit.fragility.theta), m, abs_tol(level_half));
  CHECK_CLOSE(c.fit.fragility.beta, sd, abs_tol(level_half));
  CHECK(c.method.find("moments") != std::string::npos);

  // Levels that stop below the strongest record: censored, MLE on the counts.
  std::vector<double> low;
  for (double im : ims)
    if (im < 3.5) low.push_back(im);
  const FragilityStudy sl = synthetic_study(low, R, FragilityMethod::ida);
  std::vector<FragilityRow> rl;
  for (std::size_t i = 0; i < low.size(); ++i)
    for (std::size_t r = 0; r < R; ++r) rl.push_back(row(rl.size(), i, low[i] >= imc[r]));
  const FragilityResult resl = fit_fragility(sl, rl);
  const FragilityCurve& cl = resl.curve(0, FragilityState::overturning);
  CHECK(cl.collapse_im.empty());
  CHECK(cl.method.find("censored MLE") != std::string::npos);
  REQUIRE(cl.fit.ok());
  CHECK(std::fabs(std::log(cl.fit.fragility.theta / truth.theta)) <= 3 * cl.fit.se_ln_theta);
}
