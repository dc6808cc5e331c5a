// verdict.cpp: the summary by approach (seed Fig. 8 table) and the overall
// verdict per code. Rules (docs/theory/facade.md §6):
//  - NTC 2018 §8.7.1 / Circ. 2019 C8.7.1 and NTC 2008 Circ. 617/2009 C8A.4 ask
//    that the most unfavourable mechanism be checked: each (code, approach)
//    row is the check with the largest D/C over every candidate, limit state
//    and location (ground, height);
//  - a failing check always outranks a satisfied one (a collapse with a small
//    mean D/C, a non-finite D/C), a check without a verdict outranks a
//    satisfied one;
//  - per code and method (linear = strength, non-linear = displacement,
//    dynamic; Circ. 2019 C8.7.1.2 alternatives): "satisfied" only if every
//    check of that method is satisfied; the conclusion is the adopted
//    method's verdict under NTC 2018 (NTC 2008 is for comparison);
//  - "overall" per code (every check of the code) is kept for reference;
//  - "seed" rows (the energy D/C of the seed paper) are informative and never
//    enter a verdict.
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

std::string method_of_kind(const std::string& kind) {
  if (kind == "strength") return "linear";
  if (kind == "displacement") return "nonlinear";
  if (kind == "dynamic") return "dynamic";
  return "";
}

const std::vector<std::string>& method_names() {
  static const std::vector<std::string> m{"linear", "nonlinear", "dynamic"};
  return m;
}

const MethodVerdict* Verdict::conclusion() const {
  for (const MethodVerdict& m : methods)
    if (m.code == conclusion_code && m.method == adopted) return &m;
  return nullptr;
}

Verdict build_verdict(const std::vector<CheckRow>& rows, const std::string& adopted) {
  Verdict v;
  v.adopted = adopted;
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
    cv.satisfied = cv.outcome() == Outcome::satisfied;
    v.overall.push_back(cv);
    for (const std::string& method : method_names()) {
      MethodVerdict mv;
      mv.code = c;
      mv.method = method;
      for (const CheckRow& r : rows) {
        if (r.code != c || method_of_kind(r.kind) != method) continue;
        ++mv.checks;
        const int s = severity(r);
        mv.failing += s == 2 || !std::isfinite(r.dc) ? 1 : 0;
        mv.no_verdict += s == 1 ? 1 : 0;
        mv.max_dc = std::max(mv.max_dc, dc_key(r.dc));
      }
      if (mv.checks == 0) continue;
      mv.satisfied = mv.outcome() == Outcome::satisfied;
      // Its governing row: the worst summary row of the method (failing first, then the largest D/C).
      for (std::size_t i = 0; i < v.rows.size(); ++i) {
        const VerdictRow& x = v.rows[i];
        if (x.code != c || method_of_kind(x.approach) != method) continue;
        if (mv.governing < 0) {
          mv.governing = int(i);
          continue;
        }
        const VerdictRow& g = v.rows[std::size_t(mv.governing)];
        const int sx = x.no_verdict ? 1 : (x.satisfied ? 0 : 2), sg = g.no_verdict ? 1 : (g.satisfied ? 0 : 2);
        if (sx > sg || (sx == sg && dc_key(x.dc) > dc_key(g.dc))) mv.governing = int(i);
      }
      v.methods.push_back(mv);
    }
  }
  for (const std::string& c : codes)
    if (c == "NTC2018") v.conclusion_code = c;
  if (v.conclusion_code.empty())
    for (const std::string& c : codes)
      if (c != "seed" && v.conclusion_code.empty()) v.conclusion_code = c;
  return v;
}

}  // namespace assess
