// fragility_result.hpp: the fragility curves of a study from its analyses:
// per restitution value and per limit state (overturning; energy D/C >= 1,
// seed §3.2; d* >= d_SLV, Circ. 2019 C8.7.1.2.1.9), the stripe counts, the
// lognormal fit (MLE on the counts for stripes, Baker 2015 Eq. 11; moments of
// the collapse intensities for an IDA, Baker 2015 Eqs. 2-3), bootstrap
// bounds over records, and the risk: lambda_c on the site's hazard curve,
// the probability over VN and the return period. docs/theory/fragility.md.
#pragma once

#include "assess/risk/fragility_job.hpp"
#include "assess/risk/fragility_study.hpp"
#include "assess/risk/lognormal_fragility.hpp"

#include <optional>
#include <string>
#include <vector>

namespace assess {

/// The limit states whose fragility is fitted.
enum class FragilityState {
  overturning,   ///< the integrator's overturning criterion (theta_u or pi/2, as in the case)
  energy,        ///< energy demand/capacity >= 1 (seed §3.2)
  displacement,  ///< peak d* >= d_SLV (Circ. 2019 C8.7.1.2.1.9, d_SLV of C8.7.1.2.1.6)
};
std::string to_string(FragilityState s);
inline constexpr FragilityState all_fragility_states[] = {FragilityState::overturning, FragilityState::energy,
                                                          FragilityState::displacement};

/// The counts of one stripe.
struct StripeOutcome {
  double im = 0.0;  ///< m/s^2
  double TR = 0.0;  ///< years
  int n = 0;        ///< analyses
  int k = 0;        ///< reaching the limit state (failed analyses count as reaching it)
  int failed = 0;   ///< analyses that failed (integrator error), counted in k
};

/// Percentile bounds from the bootstrap over records.
struct BootstrapBounds {
  int replicates = 0;      ///< asked for
  int fitted = 0;          ///< replicates whose fit is ok
  double theta_lo = 0, theta_hi = 0;   ///< m/s^2
  double beta_lo = 0, beta_hi = 0;     ///< -
  double lambda_lo = 0, lambda_hi = 0; ///< 1/year (0 when no hazard curve)
  std::vector<double> band_im, band_lo, band_hi;  ///< pointwise band of P(C|im)
};

/// One fragility curve and its risk.
struct FragilityCurve {
  FragilityState state = FragilityState::overturning;
  std::size_t restitution = 0;
  std::vector<StripeOutcome> stripes;
  /// IDA: collapse intensity of each (record, polarity) (m/s^2): the
  /// geometric mean of the last level without and the first with the limit
  /// state; empty if some curve is censored (then the fit is the MLE on the
  /// levels' counts).
  std::vector<double> collapse_im;
  std::string method;  ///< "MLE on stripe counts (Baker 2015 Eq. 11)" or "IDA moments (Baker 2015 Eqs. 2-3)"
  FragilityFit fit;
  std::optional<BootstrapBounds> bounds;
  bool has_risk = false;       ///< fit ok and hazard curve available
  double lambda = 0.0;         ///< mean annual frequency (1/year)
  double return_period = 0.0;  ///< 1/lambda (years)
  double p_vn = 0.0;           ///< 1 - exp(-lambda VN) (fraction)
  std::string note;            ///< why there is no risk figure, or remarks
};

struct FragilityResult {
  std::vector<FragilityCurve> curves;  ///< restitution-major: [restitution * 3 + state]
  int analyses = 0, failed = 0;
  /// Index of the governing overturning curve: the largest lambda among the
  /// restitution values (the worst carries the summary); a curve without a
  /// risk figure governs (it cannot be trusted).
  std::size_t governing = 0;
  const FragilityCurve& curve(std::size_t restitution, FragilityState s) const {
    return curves[restitution * 3 + std::size_t(s)];
  }
};

/// Fits the curves of a study from its complete results (every id once).
/// @throws InputError if rows are missing or do not belong to the study.
FragilityResult fit_fragility(const FragilityStudy& study, const std::vector<FragilityRow>& rows);

}  // namespace assess
