// collapse_rate.hpp: the mean annual frequency of a limit state,
// lambda_c = integral of P(C | im) |d lambda(im)| (the risk integral, e.g.
// Cornell et al. 2002, J. Struct. Eng. 128(4), Eq. 4 with the fragility in
// place of the demand term), the probability over a time span (Poisson) and
// the return period. See docs/theory/fragility.md §3.
#pragma once

#include "assess/hazard/hazard_curve.hpp"
#include "assess/risk/lognormal_fragility.hpp"

#include <vector>

namespace assess {

/// lambda_c = int_0^inf P(C|im) |d lambda/d im| d im (1/year). Computed as
/// int lambda(im) dP(im) (integration by parts; both boundary terms vanish),
/// with im = theta exp(beta z): lambda_c = int phi(z) lambda(theta e^{beta z}) dz,
/// trapezoidal rule on z in [-12, 12] with 4801 points (the integrand is
/// smooth and decays like a Gaussian; the rule is exact to ~1e-12 relative
/// for a power-law hazard). beta = 0 gives lambda(theta).
double collapse_rate(const LognormalFragility& fragility, const HazardCurve& hazard);

/// The same with a fragility given as a function (used for the plot of the
/// integrand): P(C|im) |d lambda/d im| at each im (1/year per m/s^2).
std::vector<double> risk_integrand(const LognormalFragility& fragility, const HazardCurve& hazard,
                                   const std::vector<double>& im);

/// Closed form for a power-law hazard lambda = k0 im^-k and a lognormal
/// fragility (Cornell et al. 2002, Eq. 11 with the demand term dropped):
/// lambda_c = k0 theta^-k exp(k^2 beta^2 / 2) (1/year).
double collapse_rate_power_law(double k0, double k, const LognormalFragility& fragility);

/// Probability of at least one occurrence in t years for a Poisson process of
/// rate lambda (1/year): 1 - exp(-lambda t) (fraction).
double probability_in(double lambda_per_year, double t_years);

}  // namespace assess
