// sensitivity.hpp: how the adopted verdict moves with the readings a
// verificatore questions first (issue 28, item 4: "Valutazione dei
// risultati"): the confidence factor FC (C8.5.4, Tab. C8.5.IV: LC1 1.35,
// LC2 1.20, LC3 1.00), and the readings of the limit state whose check
// governs the method (issue 36): the SLV displacement capacity d_SLV = 0.40
// d0* (Circ. 2019 C8.7.1.2.1.6) taken at 0.30 and 0.50 d0* and the
// mechanism's damping xi at SLV (C8.7.1.2.1.8: 5 % and 10 % beside the
// case's value); at SLC d_SLC = 0.60 d0* at 0.50 and 0.70 d0*, xi 5 % and 15 %.
// Each value is a real recomputation of the adopted method's checks (every
// candidate, NTC 2018), never a scaling: the D/C of the method is the largest
// over its checks, as the verdict takes it. A dynamic adopted method moves
// only with d_SLV (its demand is the analyses' displacement, unchanged).
#pragma once

#include <string>
#include <vector>

namespace assess {

struct FacadeAssessment;

struct SensitivityRow {
  std::string parameter;  ///< "FC" | "dSLV_over_d0" | "dSLC_over_d0" | "xi_SLV_pct" | "xi_SLC_pct"
  double value = 0.0;     ///< the value tried (-, -, %)
  bool adopted = false;   ///< the value of the case
  double dc = 0.0;        ///< the adopted method's D/C with it (-; +inf: collapse or no capacity)
  bool satisfied = false; ///< check_satisfied(dc)
};

/// The adopted method's D/C (NTC 2018) under each value tried, in the order
/// FC, d_SLV/d0*, xi; empty when the adopted method has no NTC 2018 checks.
/// Computed once by the assessment (FacadeAssessment::sensitivity, issue 41:
/// no report recomputes a check).
std::vector<SensitivityRow> adopted_sensitivity(const FacadeAssessment& a);

}  // namespace assess
