// sensitivity.cpp: the adopted method's D/C recomputed under the readings
// of sensitivity.hpp (issue 28).
#include "assess/assessment/sensitivity.hpp"

#include "assess/assessment/facade_assessment.hpp"
#include "assess/kinematic/code_rules.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace assess {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

// The largest D/C of the kinematic checks of `method` ("linear" or
// "nonlinear") over every candidate of `k`, NTC 2018 (+inf for a failing
// check whose D/C is not finite).
double method_dc(const KinematicCaseResult& k, const std::string& method) {
  double dc = -inf;
  for (const CandidateResult& cr : k.candidates)
    for (const CheckRow& r : cr.checks)
      if (r.code == "NTC2018" && method_of_kind(r.kind) == method)
        dc = std::max(dc, std::isfinite(r.dc) ? r.dc : inf);
  return dc;
}

SensitivityRow row(const char* parameter, double value, bool adopted, double dc) {
  return SensitivityRow{parameter, value, adopted, dc, check_satisfied(dc, false)};
}

}  // namespace

std::vector<SensitivityRow> adopted_sensitivity(const FacadeAssessment& a) {
  std::vector<SensitivityRow> out;
  const MethodVerdict* m = a.verdict.conclusion();
  if (!m || m->code != "NTC2018" || !a.kase.site) return out;
  const std::string method = m->method;
  if (method == "dynamic") {
    // d_SLV = f d0* in the denominator of every dynamic row: D/C(f) = D/C(0.40) 0.40 / f.
    const double f0 = code_rules::dSLV_over_d0_2018;
    for (double f : {0.30, f0, 0.50}) {
      double dc = -inf;
      for (const CheckRow& r : a.checks)
        if (r.kind == "dynamic") dc = std::max(dc, std::isfinite(r.dc) ? r.dc * f0 / f : inf);
      out.push_back(row("dSLV_over_d0", f, f == f0, dc));
    }
    return out;
  }
  // The checks alone: their safety indices do not enter the D/C. Every
  // reading varied leaves the chains as they are: the code quantities are
  // re-derived on the assessment's marched paths (a damping only re-runs the checks).
  auto rerun = [&](const CaseFile& c) { return method_dc(run_kinematic_case(c, false, &a.kinematic), method); };
  const double FC0 = a.kase.options.FC;
  std::vector<double> fcs{1.00, 1.20, 1.35};
  if (std::find(fcs.begin(), fcs.end(), FC0) == fcs.end()) fcs.push_back(FC0);
  std::sort(fcs.begin(), fcs.end());
  for (double fc : fcs) {
    CaseFile c = a.kase;
    c.options.FC = fc;
    out.push_back(row("FC", fc, fc == FC0, fc == FC0 ? m->max_dc : rerun(c)));
  }
  if (method != "nonlinear") return out;
  // The readings of the limit state whose check governs the method (issue 36:
  // varying d_SLV and xi at SLV where an SLC check governs moved nothing).
  const bool slc = m->governing >= 0 && a.verdict.rows[std::size_t(m->governing)].limit_state == "SLC";
  const double f0 = slc ? a.kase.options.dSLC_over_d0 : a.kase.options.dSLV_over_d0;
  const std::vector<double> fs = slc ? std::vector<double>{0.50, f0, 0.70} : std::vector<double>{0.30, f0, 0.50};
  for (double f : fs) {
    CaseFile c = a.kase;
    (slc ? c.options.dSLC_over_d0 : c.options.dSLV_over_d0) = f;
    out.push_back(row(slc ? "dSLC_over_d0" : "dSLV_over_d0", f, f == f0, f == f0 ? m->max_dc : rerun(c)));
  }
  const double xi0 = slc ? a.kase.checks.damping_SLC_pct : a.kase.checks.damping_SLV_pct;
  std::vector<double> xis{5.0, xi0, slc ? 15.0 : 10.0};
  std::sort(xis.begin(), xis.end());
  xis.erase(std::unique(xis.begin(), xis.end()), xis.end());
  for (double xi : xis) {
    CaseFile c = a.kase;
    (slc ? c.checks.damping_SLC_pct : c.checks.damping_SLV_pct) = xi;
    out.push_back(row(slc ? "xi_SLC_pct" : "xi_SLV_pct", xi, xi == xi0, xi == xi0 ? m->max_dc : rerun(c)));
  }
  return out;
}

}  // namespace assess
