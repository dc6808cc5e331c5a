// judgement.hpp: the engineer's judgement of the adopted verdict (issue 28,
// item 4; issue 36, item 4), decided once here and carried as data: the
// relazione's evaluation, its conclusions, the building's interventions and
// conclusions and the terminal summary all read it, so that a verdict the
// judgement calls not robust is never concluded as a plain "VERIFICATO".
// Robust when the method's verdict is given, its margin is at least 10 %,
// the other methods of the same edition agree, no computed alternative of a
// modelling choice changes it (modelling_choices.hpp), every check of
// acceptability passes (acceptability.hpp), and, for a satisfied kinematic
// verdict, no dynamic analysis collapses (docs/theory/facade.md §10).
#pragma once

#include "assess/kinematic/outcome.hpp"

#include <limits>
#include <string>
#include <vector>

namespace assess {

struct FacadeAssessment;

struct Judgement {
  std::string method;                  ///< the adopted method
  std::string code;                    ///< its edition ("NTC2018")
  Outcome outcome = Outcome::no_verdict;
  double dc = std::numeric_limits<double>::quiet_NaN();  ///< its largest D/C (-)
  bool robust = false;
  bool thin = false;                   ///< |1 - D/C| < 0.10
  /// The other methods of the edition whose verdict differs (their names).
  std::vector<std::string> disagree;
  /// The indices in FacadeAssessment::choices of the alternatives of the
  /// adopted method that change its verdict.
  std::vector<std::size_t> flips;
  /// The keys of the checks of acceptability that fail.
  std::vector<std::string> implausible;
  int collapses = 0, analyses = 0;     ///< dynamic analyses with a collapse / in all (NTC 2018 rows)
  /// The collapses count against a satisfied kinematic verdict.
  bool collapses_count() const { return collapses > 0 && method != "dynamic"; }
};

/// The judgement of `a`'s adopted verdict from its verdict, a.choices and
/// a.acceptability (computed before it).
Judgement judge(const FacadeAssessment& a);

}  // namespace assess
