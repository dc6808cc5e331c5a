// acceptability.hpp: the checks of acceptability an engineer makes of a
// program's results (NTC 2018 §10.2, "giudizio motivato di accettabilità";
// issue 36, item 2; docs/theory/facade.md §10), computed here and printed by
// the relazione's §10.2 chapter:
//  - alpha0 of the candidate that decides, redone by an independent closed
//    form where one exists: the equilibrium of the virtual work with each
//    body turning about its instantaneous centre of rotation, found from the
//    constraints' geometry alone (one body about its ground hinge; two bodies
//    hinged together, the second on a slider: the centre on the line of the
//    two hinges and the slider's normal), never through the chain's solver;
//  - the order of magnitude of the displacement capacity: d0* used against
//    the wall's thickness at the hinge (an overturning whose d0* exceeds the
//    thickness assumes weights beyond the wall turning with it);
//  - the methods compared: the linear, non-linear and dynamic verdicts of
//    NTC 2018 agree or not.
#pragma once

#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace assess {

struct FacadeAssessment;
class Chain;

struct AcceptabilityCheck {
  /// "alpha0_closed_form", "displacement_vs_thickness", "methods_agree".
  std::string key;
  std::string candidate;  ///< the candidate checked (its label)
  /// False when the check has no closed form or no meaning for this
  /// mechanism; `why_not` says why ("bodies", "topology", "ties", "plan",
  /// "curve", "methods").
  bool applicable = true;
  std::string why_not;
  double value = std::numeric_limits<double>::quiet_NaN();      ///< the engine's number (alpha0 (-); d0* (m))
  double reference = std::numeric_limits<double>::quiet_NaN();  ///< the check's (closed-form alpha0; thickness (m))
  double tolerance = std::numeric_limits<double>::quiet_NaN();  ///< relative tolerance of a closed form (-)
  bool passed = false;
  /// methods_agree: each method of NTC 2018 with its D/C and outcome ("linear", dc, satisfied?).
  std::vector<std::pair<std::string, double>> methods;
  std::vector<int> method_outcomes;  ///< Outcome of each, as an int (kinematic/outcome.hpp)
};

/// alpha0 of `chain` by the instantaneous centres of its bodies (see above);
/// NaN when the chain is not one body about a ground hinge or two bodies
/// hinged together with a slider, or is drawn in plan. `why` says which.
double closed_form_alpha0(const Chain& chain, std::string* why = nullptr);

/// The wall's thickness (m) at its ground hinge: the chord of the hinged
/// block's section just above the hinge; NaN without a ground hinge or in plan.
double thickness_at_hinge(const Chain& chain);

/// The checks of the assessment `a`, on the candidate whose check governs the adopted method.
std::vector<AcceptabilityCheck> acceptability_checks(const FacadeAssessment& a);

}  // namespace assess
