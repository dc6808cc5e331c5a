// outcome.hpp: the three states of a verdict (issue 41): a check, a method, a
// mechanism or a building is satisfied, not satisfied, or has no verdict (with
// its reason beside it). "No verdict" is never "not satisfied": a dynamic
// check on fewer than 3 records without a collapse (NTC 2018 §7.3.5) cannot
// show the wall safe or unsafe. Every writer reads the state from here; the
// words and colours of each state live in the report's messages (one place
// per language).
#pragma once

namespace assess {

enum class Outcome { satisfied, not_satisfied, no_verdict };

/// The state of a verdict stored as two flags (a check's `satisfied` and `no_verdict`).
constexpr Outcome outcome_of(bool satisfied, bool no_verdict) {
  return no_verdict ? Outcome::no_verdict : satisfied ? Outcome::satisfied : Outcome::not_satisfied;
}

/// The state of a summary: not satisfied as soon as one of its parts fails,
/// else no verdict as soon as one has none, else satisfied (at least one part).
constexpr Outcome summary_outcome(int parts, int failing, int without_verdict) {
  if (failing > 0) return Outcome::not_satisfied;
  if (without_verdict > 0) return Outcome::no_verdict;
  return parts > 0 ? Outcome::satisfied : Outcome::no_verdict;
}

/// "satisfied", "not satisfied", "no verdict": the JSON's `outcome` values.
constexpr const char* to_string(Outcome o) {
  return o == Outcome::satisfied ? "satisfied" : o == Outcome::not_satisfied ? "not satisfied" : "no verdict";
}

}  // namespace assess
