// fragility_result.cpp: counts, fits, bootstrap and risk of a study
// (docs/theory/fragility.md §1, §3, §4).
//
// Notation: unit = one record of one stripe (a group of the job); its
// outcome for a curve is (n_u, k_u) over the polarities of that record and
// one restitution value. The bootstrap over records resamples the units of
// each stripe with replacement (stripes), or the records of the fixed set
// (IDA), and refits.
#include "assess/risk/fragility_result.hpp"

#include "assess/risk/collapse_rate.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>

namespace assess {

namespace {

std::uint64_t splitmix64(std::uint64_t x) {
  x += 0x9e3779b97f4a7c15ULL;
  x = (x ^ (x >> 30)) * 0xbf58476d1ce4e5b9ULL;
  x = (x ^ (x >> 27)) * 0x94d049bb133111ebULL;
  return x ^ (x >> 31);
}

// Counter-based draw: uniform index in [0, n) for (seed, replicate, draw).
std::size_t draw(std::uint64_t seed, std::uint64_t rep, std::uint64_t i, std::size_t n) {
  const std::uint64_t u = splitmix64(splitmix64(splitmix64(seed) ^ rep) ^ i);
  return std::size_t((u >> 11) * 0x1.0p-53 * double(n)) % n;
}

double percentile(std::vector<double> v, double q) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  const double x = q * double(v.size() - 1);
  const std::size_t i = std::size_t(std::floor(x));
  const double f = x - double(i);
  return i + 1 < v.size() ? v[i] * (1 - f) + v[i + 1] * f : v.back();
}

bool reached(const FragilityRow& r, FragilityState s) {
  if (!r.ok) return true;  // a number that cannot be trusted counts as failure
  switch (s) {
    case FragilityState::overturning: return r.overturned;
    case FragilityState::energy: return r.overturned || r.dc_energy >= 1.0;
    case FragilityState::displacement: return r.overturned || r.dc_displacement >= 1.0;
  }
  return true;
}

// Per unit (stripe, record) and curve: analyses and exceedances.
struct Unit {
  std::size_t stripe = 0, record = 0;  // record: position in the stripe
  int n = 0, k = 0, failed = 0;
};

// IDA: per (record position, polarity) curve, the collapse intensity or -1
// when censored (never reached, or reached at the lowest level).
struct IdaOutcome {
  std::vector<std::vector<double>> im_c;  // [record][polarity]
  bool censored = false;
};

FragilityFit fit_units(const FragilityStudy& st, const std::vector<Unit>& units_) {
  std::vector<StripeCount> c(st.stripes.size());
  for (std::size_t i = 0; i < st.stripes.size(); ++i) c[i].im = st.stripes[i].im;
  for (const Unit& u : units_) c[u.stripe].n += u.n, c[u.stripe].k += u.k;
  return fit_lognormal_mle(c);
}

}  // namespace

std::string to_string(FragilityState s) {
  switch (s) {
    case FragilityState::overturning: return "overturning";
    case FragilityState::energy: return "energy D/C >= 1";
    case FragilityState::displacement: return "d* >= d_SLV";
  }
  return "?";
}

FragilityResult fit_fragility(const FragilityStudy& st, const std::vector<FragilityRow>& rows) {
  const std::uint64_t N = st.size(), G = st.group_size();
  if (rows.size() != N)
    throw InputError("fragility results: " + std::to_string(rows.size()) + " rows for a study of " +
                     std::to_string(N) + " analyses (run it to the end, or --resume)");
  for (std::uint64_t i = 0; i < N; ++i)
    if (rows[i].id != i) throw InputError("fragility results: row " + std::to_string(i) + " has id " +
                                          std::to_string(rows[i].id) + " (rows must be in id order)");
  FragilityResult res;
  res.analyses = int(N);
  for (const auto& r : rows) res.failed += r.ok ? 0 : 1;
  const bool ida = st.options.method == FragilityMethod::ida;
  const double half = 0.5 * (1.0 - st.options.confidence);
  const std::size_t E = st.restitutions(), P = st.polarities.size();

  // Plot grid of the band: from half the lowest to twice the highest level.
  std::vector<double> grid;
  const double g_lo = 0.5 * st.stripes.front().im, g_hi = 2.0 * st.stripes.back().im;
  for (int i = 0; i <= 80; ++i) grid.push_back(g_lo * std::pow(g_hi / g_lo, i / 80.0));

  for (std::size_t e = 0; e < E; ++e)
    for (FragilityState state : all_fragility_states) {
      FragilityCurve cv;
      cv.state = state;
      cv.restitution = e;
      // Units and stripe counts.
      std::vector<Unit> units_;
      for (std::uint64_t g = 0; g < st.groups(); ++g) {
        const auto [si, ri] = st.group(g);
        Unit u{si, ri, 0, 0, 0};
        for (std::size_t p = 0; p < P; ++p) {
          const FragilityRow& r = rows[g * G + p * E + e];
          ++u.n;
          u.k += reached(r, state) ? 1 : 0;
          u.failed += r.ok ? 0 : 1;
        }
        units_.push_back(u);
      }
      cv.stripes.resize(st.stripes.size());
      for (std::size_t i = 0; i < st.stripes.size(); ++i) cv.stripes[i].im = st.stripes[i].im, cv.stripes[i].TR = st.stripes[i].TR;
      for (const Unit& u : units_) {
        cv.stripes[u.stripe].n += u.n;
        cv.stripes[u.stripe].k += u.k;
        cv.stripes[u.stripe].failed += u.failed;
      }

      // IDA: the collapse intensities of each (record, polarity) curve.
      auto ida_fit = [&](const std::vector<std::size_t>& recs, std::vector<double>* out_im) -> FragilityFit {
        // recs: positions in the fixed set (with repetition for the bootstrap).
        std::vector<double> imc;
        std::vector<CensoredIntensity> intervals;
        bool censored = false;
        for (std::size_t rp : recs)
          for (std::size_t p = 0; p < P; ++p) {
            std::size_t first = st.stripes.size();
            for (std::size_t si = 0; si < st.stripes.size(); ++si) {
              const std::uint64_t g = si * st.stripes[0].records.size() + rp;
              if (reached(rows[g * G + p * E + e], state)) {
                first = si;
                break;
              }
            }
            const double lo = first == 0 ? 0.0 : st.stripes[first - 1].im;
            const double hi = first == st.stripes.size() ? std::numeric_limits<double>::infinity() : st.stripes[first].im;
            intervals.push_back({lo, hi});
            if (first == 0 || first == st.stripes.size()) censored = true;
            else imc.push_back(std::sqrt(lo * hi));
          }
        if (censored) return fit_lognormal_censored(intervals);
        if (out_im) *out_im = imc;
        return fit_lognormal_ida(imc);
      };

      std::vector<std::size_t> all_recs;
      if (ida)
        for (std::size_t r = 0; r < st.stripes[0].records.size(); ++r) all_recs.push_back(r);
      if (ida) {
        cv.fit = ida_fit(all_recs, &cv.collapse_im);
        cv.method = cv.collapse_im.empty()
                        ? "IDA, interval-censored MLE of the collapse intensities: some curves never (or already at the lowest level) reach the limit state"
                        : "IDA, moments of ln im_c (Baker 2015 Eqs. 2-3)";
      } else {
        cv.fit = fit_units(st, units_);
        cv.method = "MSA, MLE on the stripe counts (Baker 2015 Eq. 11)";
      }

      // Risk.
      if (cv.fit.ok() && st.hazard) {
        cv.has_risk = true;
        cv.lambda = collapse_rate(cv.fit.fragility, *st.hazard);
        cv.return_period = 1.0 / cv.lambda;
        cv.p_vn = probability_in(cv.lambda, st.VN);
      } else if (!cv.fit.ok()) {
        cv.note = to_string(cv.fit.status) + ": " + cv.fit.message;
      }

      // Bootstrap over records.
      if (st.options.bootstrap > 0 && cv.fit.ok()) {
        BootstrapBounds b;
        b.replicates = st.options.bootstrap;
        std::vector<double> th, be, la;
        std::vector<std::vector<double>> band(grid.size());
        const std::uint64_t seed = st.options.seed ^ (std::uint64_t(e) << 32) ^ (std::uint64_t(state) << 48);
        for (int rep = 0; rep < b.replicates; ++rep) {
          FragilityFit f;
          if (ida) {
            std::vector<std::size_t> recs;
            for (std::size_t i = 0; i < all_recs.size(); ++i)
              recs.push_back(all_recs[draw(seed, std::uint64_t(rep), i, all_recs.size())]);
            f = ida_fit(recs, nullptr);
          } else {
            std::vector<Unit> sel;
            std::uint64_t counter = 0;
            for (std::size_t si = 0; si < st.stripes.size(); ++si) {
              std::vector<const Unit*> in;
              for (const Unit& u : units_)
                if (u.stripe == si) in.push_back(&u);
              for (std::size_t i = 0; i < in.size(); ++i) sel.push_back(*in[draw(seed, std::uint64_t(rep), counter++, in.size())]);
            }
            f = fit_units(st, sel);
          }
          if (!f.ok()) continue;
          ++b.fitted;
          th.push_back(f.fragility.theta);
          be.push_back(f.fragility.beta);
          if (st.hazard) la.push_back(collapse_rate(f.fragility, *st.hazard));
          for (std::size_t i = 0; i < grid.size(); ++i) band[i].push_back(f.fragility.probability(grid[i]));
        }
        if (b.fitted > 0) {
          b.theta_lo = percentile(th, half), b.theta_hi = percentile(th, 1 - half);
          b.beta_lo = percentile(be, half), b.beta_hi = percentile(be, 1 - half);
          b.lambda_lo = percentile(la, half), b.lambda_hi = percentile(la, 1 - half);
          b.band_im = grid;
          for (auto& v : band) b.band_lo.push_back(percentile(v, half)), b.band_hi.push_back(percentile(v, 1 - half));
        }
        if (b.fitted < b.replicates)
          cv.note += (cv.note.empty() ? "" : "; ") + std::to_string(b.replicates - b.fitted) + " of " +
                     std::to_string(b.replicates) + " bootstrap replicates could not be fitted (degenerate resamples)";
        cv.bounds = b;
      }
      int failed = 0;
      for (const auto& s : cv.stripes) failed += s.failed;
      if (failed > 0)
        cv.note += (cv.note.empty() ? "" : "; ") + std::to_string(failed) +
                   " failed analyses counted as reaching the limit state";
      res.curves.push_back(std::move(cv));
    }
  // Governing overturning curve: no risk figure governs, else the largest lambda.
  double worst = -1.0;
  for (std::size_t e = 0; e < E; ++e) {
    const FragilityCurve& c = res.curves[e * 3];
    const double v = c.has_risk ? c.lambda : std::numeric_limits<double>::infinity();
    if (v > worst) worst = v, res.governing = e * 3;
  }
  return res;
}

}  // namespace assess
