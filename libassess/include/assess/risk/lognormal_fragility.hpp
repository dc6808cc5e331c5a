// lognormal_fragility.hpp: a lognormal fragility function
// P(C | im) = Phi(ln(im/theta) / beta) and its two estimators of Baker (2015),
// "Efficient analytical fragility function fitting using dynamic structural
// analysis", Earthquake Spectra 31(1):579-599:
//  - maximum likelihood on the binomial counts of a multiple-stripe analysis
//    (Baker 2015 Eqs. 10-11), and
//  - the method of moments on the collapse intensities of an IDA (Baker 2015
//    Eqs. 2-3).
// See docs/theory/fragility.md §1.
#pragma once

#include <string>
#include <vector>

namespace assess {

/// P(C | im) = Phi(ln(im/theta)/beta) (Baker 2015 Eq. 1).
struct LognormalFragility {
  double theta = 0.0;  ///< median intensity (same unit as im, here m/s^2)
  double beta = 0.0;   ///< dispersion: standard deviation of ln IM_c (-)
  /// Probability of the limit state at intensity im (same unit as theta).
  double probability(double im) const;
};

/// Standard normal cumulative distribution Phi(x).
double normal_cdf(double x);

/// One stripe of a multiple-stripe analysis: n analyses at intensity im, k of
/// which reached the limit state. Counts are real numbers so that expected
/// counts (n P) can be fitted too; 0 <= k <= n.
struct StripeCount {
  double im = 0.0;  ///< intensity (> 0)
  double n = 0.0;   ///< analyses
  double k = 0.0;   ///< analyses that reached the limit state
};

/// Outcome of a fit.
struct FragilityFit {
  enum class Status {
    ok,
    no_exceedance,   ///< k = 0 everywhere: theta is above every stripe, no finite estimate
    all_exceedance,  ///< k = n everywhere: theta is below every stripe
    separated,       ///< the counts are (nearly) perfectly separated: beta -> 0, theta only bracketed
    too_few,         ///< fewer than 2 stripes (MLE) or 2 intensities (IDA)
    no_trend,        ///< the fraction does not grow with the intensity (beta > 20 or theta not finite)
    not_converged,
  };
  Status status = Status::too_few;
  LognormalFragility fragility;  ///< set when status == ok
  double se_ln_theta = 0.0;      ///< asymptotic standard error of ln(theta) (-)
  double se_beta = 0.0;          ///< asymptotic standard error of beta (-)
  double log_likelihood = 0.0;   ///< without the binomial constants (MLE only)
  int iterations = 0;
  std::string message;           ///< why it is not ok (one line)
  bool ok() const { return status == Status::ok; }
};

std::string to_string(FragilityFit::Status s);

/// Maximum-likelihood lognormal fit to stripe counts (Baker 2015 Eq. 11):
/// maximises sum_j [k_j ln Phi(u_j) + (n_j - k_j) ln(1 - Phi(u_j))],
/// u_j = ln(im_j/theta)/beta, by Fisher scoring of the equivalent probit
/// model Phi(a + b ln im) (b = 1/beta, a = -ln(theta)/beta) with step
/// halving. The standard errors come from the inverse Fisher information
/// by the delta method. Stripes with n = 0 are ignored.
/// @throws InputError for an invalid stripe (im <= 0, n < 0, k outside [0, n], NaN)
FragilityFit fit_lognormal_mle(const std::vector<StripeCount>& stripes);

/// IDA fit from the collapse intensities of the records (Baker 2015 Eqs. 2-3):
/// ln theta = mean of ln im_c, beta = sample standard deviation (n - 1) of
/// ln im_c; standard errors beta/sqrt(n) and beta/sqrt(2(n-1)).
/// @throws InputError for an intensity <= 0 or NaN
FragilityFit fit_lognormal_ida(const std::vector<double>& collapse_im);

/// An interval (lo, hi] that holds a collapse intensity: lo = 0 when the
/// first level already collapses, hi = +infinity when no level does.
struct CensoredIntensity {
  double lo = 0.0;
  double hi = 0.0;
};

/// IDA fit when some collapse intensities are censored: maximum likelihood of
/// the interval-censored lognormal sample, ln L = sum_i ln[Phi((ln hi_i - ln
/// theta)/beta) - Phi((ln lo_i - ln theta)/beta)] (each record's IDA curve is
/// one observation), maximised by Nelder-Mead in (ln theta, ln beta); standard
/// errors from the inverse of the observed information (central-difference
/// Hessian). @throws InputError for lo >= hi, lo < 0 or NaN
FragilityFit fit_lognormal_censored(const std::vector<CensoredIntensity>& intervals);

}  // namespace assess
