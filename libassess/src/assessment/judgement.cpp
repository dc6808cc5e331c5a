// judgement.cpp: the judgement of the adopted verdict (judgement.hpp; issue
// 36, item 4; docs/theory/facade.md §10).
#include "assess/assessment/judgement.hpp"

#include "assess/assessment/facade_assessment.hpp"

#include <cmath>

namespace assess {

Judgement judge(const FacadeAssessment& a) {
  Judgement j;
  const MethodVerdict* m = a.verdict.conclusion();
  if (!m) return j;
  j.method = m->method;
  j.code = m->code;
  j.outcome = m->outcome();
  j.dc = m->max_dc;
  j.thin = std::isfinite(j.dc) && std::abs(1.0 - j.dc) < 0.10;
  for (const MethodVerdict& o : a.verdict.methods)
    if (o.code == m->code && o.method != m->method && o.outcome() != j.outcome) j.disagree.push_back(o.method);
  for (std::size_t i = 0; i < a.choices.size(); ++i)
    if (a.choices[i].method == m->method && a.choices[i].flips()) j.flips.push_back(i);
  for (const AcceptabilityCheck& x : a.acceptability)
    if (x.applicable && !x.passed && x.key != "methods_agree") j.implausible.push_back(x.key);  // the methods: `disagree`
  for (const CheckRow& r : a.checks)
    if (r.kind == "dynamic" && r.code == m->code) {
      j.collapses += r.collapsed;
      j.analyses += r.analyses;
    }
  const bool steady = !j.thin && j.disagree.empty() && j.flips.empty() && j.implausible.empty();
  if (j.outcome == Outcome::satisfied) j.robust = steady && !j.collapses_count();
  else if (j.outcome == Outcome::not_satisfied) j.robust = steady;
  return j;
}

}  // namespace assess
