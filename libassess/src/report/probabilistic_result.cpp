// probabilistic_result.cpp: JSON of the additional probabilistic result of the
// façade report (formatting only; docs/theory/fragility.md §3).
#include "assess/report/probabilistic_result.hpp"

#include "assess/support/units.hpp"

namespace assess {

nlohmann::json probabilistic_result_json(const ProbabilisticResult& r) {
  nlohmann::json j;
  j["kind"] = "additional probabilistic result, not a code check";
  j["source"] = r.source;
  j["method"] = r.method;
  j["model"] = r.model;
  j["restitution"] = r.restitution;
  j["limit_state"] = "overturning";
  j["analyses"] = r.analyses;
  j["failed"] = r.failed;
  j["has_risk"] = r.has_risk;
  if (r.has_risk) {
    j["median_pga_m_s2"] = r.median_pga;
    j["median_pga_g"] = r.median_pga / units::g;
    j["beta"] = r.beta;
    j["lambda_per_year"] = r.lambda;
    j["return_period_years"] = r.return_period;
    j["probability_in_VN"] = r.p_vn;
    if (std::isfinite(r.p_at_SLV)) j["P_overturning_at_SLV_pga"] = r.p_at_SLV;
  } else {
    j["note"] = r.note;
  }
  j["VN_years"] = r.VN;
  j["TR_SLV_years"] = r.TR_SLV;
  j["pga_SLV_m_s2"] = r.pga_SLV;
  return j;
}

}  // namespace assess
