// modelling_choices.hpp: every choice of the model that moves a result,
// stated with its alternative computed (issue 36, item 3; docs/theory/facade.md
// §9): the confidence factor (the other knowledge levels), the participating
// mass e* with the blocks' masses distributed or lumped at their centroids, the
// displacement bound of the mechanism (with and without it), the demand at
// height (the checks at the mechanism's height Z or at the ground alone), the
// activation of the side walls' friction and of the floors' seats, the
// capacity and damping readings of the limit state that governs, and the
// windows of the record selection. Each alternative is the same case with
// one key changed (named by its JSON path where the case has one) run again
// through the same code: its D/C is computed, never scaled. The relazione
// prints them in one table ("scelte di modellazione") and beside the
// quantity each one moves; report/ computes none of them.
#pragma once

#include "assess/kinematic/outcome.hpp"

#include <limits>
#include <string>
#include <vector>

namespace assess {

struct FacadeAssessment;

/// One alternative of one modelling choice.
struct ModellingChoice {
  /// "FC", "lumped_masses", "displacement_bound", "height_demand",
  /// "friction_activation", "seat_friction", "dSLV_over_d0", "dSLC_over_d0",
  /// "xi_SLV_pct", "xi_SLC_pct", "selection_window".
  std::string key;
  /// Where the case gives it ("/knowledge_level", "/mechanism/activation",
  /// "/dynamic/select/Mw" ...); "" for a reading of the engine without a key.
  std::string case_key;
  /// The quantity it sets, adopted and in the alternative (unit per key: FC
  /// and e* (-), d0* (m), Z (m), kappa (-), mu (-), d/d0* (-), xi (%); the
  /// selection window: Mw_max and R_max (km) in the _b fields below).
  double adopted = std::numeric_limits<double>::quiet_NaN();
  double alternative = std::numeric_limits<double>::quiet_NaN();
  /// A label of each ("LC2" / "LC1" for FC; "" otherwise).
  std::string adopted_label, alternative_label;
  /// Second numbers of the selection window (Mw_min, R_min (km)) adopted and alternative.
  double adopted_b = std::numeric_limits<double>::quiet_NaN(), alternative_b = std::numeric_limits<double>::quiet_NaN();
  double adopted_c = std::numeric_limits<double>::quiet_NaN(), alternative_c = std::numeric_limits<double>::quiet_NaN();
  double adopted_d = std::numeric_limits<double>::quiet_NaN(), alternative_d = std::numeric_limits<double>::quiet_NaN();
  /// The method whose D/C (NTC 2018) the choice moves: the adopted one, or
  /// "dynamic" for the selection window.
  std::string method;
  double dc = std::numeric_limits<double>::quiet_NaN();              ///< as the case is (-)
  double dc_alternative = std::numeric_limits<double>::quiet_NaN();  ///< with the alternative (-); NaN: not computed
  Outcome outcome = Outcome::no_verdict, outcome_alternative = Outcome::no_verdict;
  /// Why the alternative was not computed ("" when it was): "invalid" (the
  /// case with the alternative is refused), "no_records" (no selection found).
  std::string not_computed;
  bool computed() const { return not_computed.empty(); }
  /// The alternative changes the method's verdict.
  bool flips() const { return computed() && outcome_alternative != outcome; }
};

/// The choices of the assessment `a` that apply to its mechanism, each
/// alternative computed (a has its verdict: assess_facade). The selection
/// window's alternative reruns the whole dynamic analysis: computed when the
/// adopted method is the dynamic one (it can change the verdict) or when
/// `records` asks for it (the relazione's table).
std::vector<ModellingChoice> modelling_choices(const FacadeAssessment& a, bool records = true);

}  // namespace assess
