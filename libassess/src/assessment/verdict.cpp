// verdict.cpp: the summary by approach (seed Fig. 8 table) and the overall
// verdict per code. Rules (docs/theory/facade.md §6):
//  - NTC 2018 §8.7.1 / Circ. 2019 C8.7.1 and NTC 2008 Circ. 617/2009 C8A.4 ask
//    that the most unfavourable mechanism be checked: each (code, approach)
//    row is the check with the largest D/C over every candidate, limit state
//    and location (ground, height);
//  - a failing check always outranks a satisfied one (a collapse with a small
//    mean D/C, a non-finite D/C), a check without a verdict outranks a
//    satisfied one;
//  - the overall verdict of a code is "satisfied" only if every check of that
//    code is satisfied; "seed" rows (the energy D/C of the seed paper) are
//    informative and never enter a code's verdict.
#include "assess/assessment/verdict.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <tuple>

namespace assess {
namespace {

// Severity of a row: 2 fails, 1 no verdict, 0 satisfied.
int severity(const CheckRow& r) { return r.no_verdict ? 1 : (r.satisfied ? 0 : 2); }

double dc_key(double dc) { return std::isfinite(dc) ? dc : std::numeric_limits<double>::infinity(); }

bool worse(const CheckRow& a, const CheckRow& b) {
  const int sa = severity(a), sb = severity(b);
  if (sa != sb) return sa > sb;
  return dc_key(a.dc) > dc_key(b.dc);
}

int approach_rank(const std::string& kind) {
  if (kind == "strength") return 0;
  if (kind == "displacement") return 1;
  if (kind == "dynamic") return 2;
  return 3;
}

}  // namespace

Verdict build_verdict(const std::vector<CheckRow>& rows) {
  Verdict v;
  // Group key: code order of first appearance, approach rank, clause (dynamic kinds only).
  std::vector<std::string> codes;
  for (const CheckRow& r : rows) {
    bool seen = false;
    for (const std::string& c : codes) seen = seen || c == r.code;
    if (!seen) codes.push_back(r.code);
  }
  auto code_rank = [&](const std::string& c) {
    for (std::size_t i = 0; i < codes.size(); ++i)
      if (codes[i] == c) return int(i);
    return int(codes.size());
  };
  using Key = std::tuple<int, int, std::string, std::string>;
  std::map<Key, std::pair<CheckRow, std::pair<int, int>>> groups;  // worst row, (checks, failing)
  for (const CheckRow& r : rows) {
    const bool per_clause = r.kind != "strength" && r.kind != "displacement";
    const Key k{code_rank(r.code), approach_rank(r.kind), r.kind, per_clause ? r.clause : std::string()};
    auto it = groups.find(k);
    if (it == groups.end()) {
      groups.emplace(k, std::make_pair(r, std::make_pair(1, severity(r) == 2 ? 1 : 0)));
      continue;
    }
    ++it->second.second.first;
    it->second.second.second += severity(r) == 2 ? 1 : 0;
    if (worse(r, it->second.first)) it->second.first = r;
  }
  for (const auto& [k, g] : groups) {
    const CheckRow& r = g.first;
    VerdictRow x;
    x.code = r.code;
    x.approach = r.kind;
    x.limit_state = r.limit_state;
    x.location = r.location;
    x.candidate = r.candidate;
    x.clause = r.clause;
    x.dc = r.dc;
    x.no_verdict = r.no_verdict;
    x.satisfied = r.satisfied && !r.no_verdict && std::isfinite(r.dc);
    x.note = r.note;
    x.checks = g.second.first;
    x.failing = g.second.second;
    v.rows.push_back(x);
  }
  for (const std::string& c : codes) {
    if (c == "seed") continue;
    CodeVerdict cv;
    cv.code = c;
    for (const CheckRow& r : rows) {
      if (r.code != c) continue;
      ++cv.checks;
      const int s = severity(r);
      cv.failing += s == 2 || !std::isfinite(r.dc) ? 1 : 0;
      cv.no_verdict += s == 1 ? 1 : 0;
      cv.max_dc = std::max(cv.max_dc, dc_key(r.dc));
    }
    cv.satisfied = cv.checks > 0 && cv.failing == 0;
    v.overall.push_back(cv);
  }
  return v;
}

}  // namespace assess
