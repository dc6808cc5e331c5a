// verdict.hpp: the verdict an engineer signs: for each code edition and each
// approach (strength, displacement, dynamic) the governing check — the largest
// D/C over every candidate mechanism, limit state and location — and an
// overall verdict per code that is "not satisfied" as soon as any check of
// that code fails (docs/theory/facade.md §6). Built once here; the terminal,
// JSON and HTML reports only format it.
#pragma once

#include "assess/kinematic/code_checks.hpp"

#include <string>
#include <vector>

namespace assess {

/// The governing check of one (code, approach).
struct VerdictRow {
  std::string code;         ///< "NTC2008" | "NTC2018" | "seed" (the seed paper's energy measure, not a code check)
  std::string approach;     ///< "strength" | "displacement" | "dynamic" | "dynamic energy"
  std::string limit_state;  ///< "SLD" | "SLV" | "SLC"
  std::string location;     ///< "ground" | "height"
  std::string candidate;    ///< the mechanism candidate of the row
  std::string clause;
  double dc = 0.0;          ///< demand / capacity (-)
  bool satisfied = false;   ///< dc <= 1 and a verdict could be given
  bool no_verdict = false;  ///< the check could not give a verdict (`note` says why)
  NoteText note;            ///< "overturned in 1 of 2 analyses", the record-count rule ... (as data)
  int checks = 0;           ///< how many checks this row governs
  int failing = 0;          ///< how many of them fail
  Outcome outcome() const { return outcome_of(satisfied, no_verdict); }
};

/// The overall verdict of one code edition.
struct CodeVerdict {
  std::string code;        ///< "NTC2008" | "NTC2018"
  bool satisfied = false;  ///< every check of the code satisfied (and at least one check)
  int checks = 0;          ///< checks of the code (every candidate)
  int failing = 0;         ///< of which not satisfied
  int no_verdict = 0;      ///< of which without a verdict (not counted as satisfied)
  double max_dc = 0.0;     ///< the largest D/C
  Outcome outcome() const { return summary_outcome(checks, failing, no_verdict); }
};

/// The verdict of one method of one code edition (issue 24; docs/theory/facade.md §6).
/// Circ. 2019 C8.7.1.2 offers the linear kinematic analysis (C8.7.1.2.1.7,
/// strength), the non-linear one (C8.7.1.2.1.8, displacement) and the dynamic
/// one (C8.7.1.2.1.9) as alternative procedures; Circ. 2009 C8A.4 the linear
/// and the non-linear. Each method's verdict is the worst of its checks, over
/// every candidate, limit state and location.
struct MethodVerdict {
  std::string code;        ///< "NTC2018" | "NTC2008"
  std::string method;      ///< "linear" | "nonlinear" | "dynamic"
  bool satisfied = false;  ///< every check of the method satisfied (and at least one)
  int checks = 0, failing = 0, no_verdict = 0;
  double max_dc = 0.0;     ///< largest D/C (-); inf if one is not finite
  int governing = -1;      ///< index in Verdict::rows of its governing row(s): the worst; -1 if none
  /// No check fails but some give no verdict: the method has no verdict
  /// (shown as such, never as "not satisfied" beside a D/C <= 1; issue 28).
  bool undecided() const { return failing == 0 && no_verdict > 0; }
  /// Its verdict in three states: not satisfied if a check fails, else no
  /// verdict if one has none, else satisfied.
  Outcome outcome() const { return summary_outcome(checks, failing, no_verdict); }
};

/// "linear" (rows of kind "strength"), "nonlinear" ("displacement"), "dynamic" ("dynamic"); "" otherwise.
std::string method_of_kind(const std::string& kind);
/// The accepted method names, in the order of the reports.
const std::vector<std::string>& method_names();

struct Verdict {
  std::vector<VerdictRow> rows;      ///< code order as given, then approach order
  /// One per code edition present in the rows: every check of the code (all
  /// methods together). Listed for reference; the conclusion is the adopted
  /// method's verdict (methods, adopted).
  std::vector<CodeVerdict> overall;
  /// Per code and method present, code order as given, then linear, non-linear, dynamic.
  std::vector<MethodVerdict> methods;
  /// The method the engineer adopts (case key "method"; default "nonlinear").
  std::string adopted = "nonlinear";
  /// The code edition of the conclusion: NTC 2018 when checked, else the first
  /// code (NTC 2008 rows are otherwise "a titolo di confronto").
  std::string conclusion_code;
  /// The adopted method's verdict under conclusion_code; nullptr if that
  /// method has no check (e.g. no site).
  const MethodVerdict* conclusion() const;
};

/// Builds the summary from every check row (all candidates' kinematic rows,
/// the dynamic rows, and "seed" energy rows, which are listed but never enter
/// a verdict). Rows of kind "dynamic" are grouped per clause (one per
/// restitution value). `adopted`: "linear", "nonlinear" or "dynamic".
Verdict build_verdict(const std::vector<CheckRow>& rows, const std::string& adopted = "nonlinear");

}  // namespace assess
