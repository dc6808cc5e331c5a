// probabilistic_result.hpp: an additional probabilistic result shown in the
// façade report beside the code's checks, never as one of them: the governing
// overturning fragility of `assess fragility` (issue 16; risk module,
// docs/theory/fragility.md) at the site, with its mean annual frequency
// lambda_c = integral P(C | im) |d lambda(im)|, the return period 1/lambda_c
// and the probability over the nominal life, P = 1 - exp(-lambda_c VN), next
// to the code's SLV return period TR = -VR / ln(1 - P_VR) [NTC 2018 3.2.0].
// The report layer only formats it; the front end fills it from the fragility
// summary (risk/fragility_report.hpp: probabilistic_result).
#pragma once

#include <nlohmann/json.hpp>

#include <cmath>
#include <string>

namespace assess {

struct ProbabilisticResult {
  std::string source;          ///< where it was read (DIR/summary.json)
  std::string method;          ///< "stripes" (multiple-stripe analysis) or "ida"
  std::string restitution;     ///< the governing restitution value's label
  std::string model;           ///< the dynamic model (rocking body / chain, floor motions)
  int analyses = 0, failed = 0;
  bool has_risk = false;       ///< false: `note` says why there is no risk figure
  std::string note;
  double median_pga = NAN;     ///< median of the overturning fragility, PGA on the site's ground (m/s^2)
  double beta = NAN;           ///< its lognormal dispersion (-)
  double lambda = NAN;         ///< mean annual frequency of overturning (1/year)
  double return_period = NAN;  ///< 1/lambda (years)
  double p_vn = NAN;           ///< probability of overturning in VN (-)
  double VN = NAN;             ///< nominal life (years)
  double TR_SLV = NAN;         ///< the code's SLV return period at the site (years)
  double pga_SLV = NAN;        ///< its PGA on the site's ground (m/s^2)
  double p_at_SLV = NAN;       ///< P(overturning | PGA of SLV) from the fragility (-)
};

/// The façade report's JSON of it ("fragility" of `assess run --json`): SI
/// values with the unit in each key, the g values beside, and "kind" saying
/// that it is an additional probabilistic result, not a code check.
nlohmann::json probabilistic_result_json(const ProbabilisticResult& r);

}  // namespace assess
