// safety_index.cpp: the safety index of a mechanism per code and approach,
// the lowest of its checks' own indices (issue 41; docs/theory/building.md §4).
#include "assess/assessment/safety_index.hpp"

namespace assess {

const CheckRow* lowest_index_check(const KinematicCaseResult& k, const std::string& code, const std::string& kind) {
  const CheckRow* best = nullptr;
  for (const CandidateResult& cr : k.candidates)
    for (const CheckRow& r : cr.checks)
      if (r.code == code && r.kind == kind && r.index.defined && (!best || r.index.zeta < best->index.zeta)) best = &r;
  return best;
}

std::vector<SafetyIndex> safety_indices(const KinematicCaseResult& k, const Verdict& v) {
  std::vector<SafetyIndex> out;
  for (const char* code : {"NTC2018", "NTC2008"}) {
    for (const char* approach : {"strength", "displacement", "dynamic"}) {
      const MethodVerdict* m = nullptr;
      for (const MethodVerdict& x : v.methods)
        if (x.code == code && x.method == method_of_kind(approach)) m = &x;
      if (!m || m->checks == 0) continue;
      SafetyIndex s;
      s.code = code;
      s.approach = approach;
      s.has_checks = true;
      s.dc = m->max_dc;
      s.satisfied = m->satisfied;
      s.undecided = m->undecided();
      s.checks = m->checks;
      s.failing = m->failing;
      s.no_verdict = m->no_verdict;
      if (m->governing >= 0) {
        s.dc_candidate = v.rows[std::size_t(m->governing)].candidate;
        for (const CandidateResult& cr : k.candidates)
          if (cr.label == s.dc_candidate) {
            s.dc_alpha0 = cr.result.alpha0;
            s.dc_a0_star = cr.result.a0_star;
          }
      }
      if (const CheckRow* r = approach == std::string("dynamic") ? nullptr : lowest_index_check(k, code, approach)) {
        s.defined = true;
        s.index = r->index;
        s.limit_state = r->limit_state;
        s.location = r->location;
        s.candidate = r->candidate;
        s.note = r->index.note;
      } else {
        s.note = {approach == std::string("dynamic") ? no_dynamic_index() : Note{"index.no_check", {}}};
      }
      out.push_back(s);
    }
  }
  return out;
}

}  // namespace assess
