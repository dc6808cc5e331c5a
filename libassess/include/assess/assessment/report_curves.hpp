// report_curves.hpp: the curves a report draws, computed by the assessment so
// that the report never recomputes physics: the site's spectra, the records'
// spectra, the moment-rotation curve, the floor spectra and the ADRS demands.
#pragma once

#include "assess/hazard/seismic_action.hpp"

#include <map>
#include <string>
#include <vector>

namespace assess {

/// The demand curve of one displacement check of the governing candidate in
/// the ADRS plane (issue 24): the check's own demand function of the secant
/// period (kinematic/code_checks.hpp displacement_demand, at its damping and,
/// at height, on the floor spectrum), Sd = d(T), Sa = d(T) (2 pi / T)^2.
struct AdrsDemand {
  std::string code, limit_state, location;  ///< as in its CheckRow
  double xi_pct = 5.0;                      ///< damping of the demand (%)
  std::vector<double> Sd;                   ///< m, at ReportCurves::adrs_periods
  std::vector<double> Sa;                   ///< m/s^2
};

/// The curves of FacadeAssessment for the report.
struct ReportCurves {
  std::vector<double> periods;                         ///< s (0 first, then log-spaced to 4 s)
  std::map<LimitState, std::vector<double>> site_Se;   ///< 5 % elastic Se at `periods` (m/s^2)
  std::vector<std::vector<double>> record_psa;         ///< scaled 5 % PSA of each record at `periods` (m/s^2)
  std::vector<double> mean_psa;                        ///< their mean (m/s^2)
  std::vector<double> mr_theta, mr_moment;             ///< moment-rotation curve of the body: rad, N m/m
                                                       ///< (chain: q and the generalised force per unit length)
  /// Mechanism at height with ground records filtered to the floor: the 5 %
  /// spectrum of the floor motions (mean over the records, scaled, m/s^2) and
  /// the code's floor spectrum S_eZ(T) [C7.2.6] at 5 % for the SLV hazard, at `periods`.
  std::vector<double> floor_mean_psa, code_floor_Se;
  /// The ADRS demand curves of the governing candidate's displacement checks (issue 24), at adrs_periods (s).
  std::vector<AdrsDemand> adrs;
  std::vector<double> adrs_periods;
  /// The same for every candidate (index as in kinematic.candidates; issue 28:
  /// the relazione develops each candidate that governs a method).
  std::vector<std::vector<AdrsDemand>> candidate_adrs;
};

}  // namespace assess
