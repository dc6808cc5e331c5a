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
  std::string note;         ///< "overturned in 1 of 2 analyses", the record-count rule ...
  int checks = 0;           ///< how many checks this row governs
  int failing = 0;          ///< how many of them fail
};

/// The overall verdict of one code edition.
struct CodeVerdict {
  std::string code;        ///< "NTC2008" | "NTC2018"
  bool satisfied = false;  ///< every check of the code satisfied (and at least one check)
  int checks = 0;          ///< checks of the code (every candidate)
  int failing = 0;         ///< of which not satisfied
  int no_verdict = 0;      ///< of which without a verdict (not counted as satisfied)
  double max_dc = 0.0;     ///< the largest D/C
};

struct Verdict {
  std::vector<VerdictRow> rows;      ///< code order as given, then approach order
  std::vector<CodeVerdict> overall;  ///< one per code edition present in the rows
};

/// Builds the summary from every check row (all candidates' kinematic rows,
/// the dynamic rows, and "seed" energy rows, which are listed but never enter
/// a code's overall verdict). Rows of kind "dynamic" are grouped per clause
/// (one per restitution value).
Verdict build_verdict(const std::vector<CheckRow>& rows);

}  // namespace assess
