// building_assessment.cpp: every mechanism of a building through
// assess_facade and assess_ties, the safety indices zetaE = PGA_C / PGA_D and
// TR_C / TR_D, the governing mechanism per approach and the building's index
// before and after the tie rods (docs/theory/building.md).
#include "assess/assessment/building_assessment.hpp"

#include "assess/kinematic/code_checks.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"
#include "support/parallel_for.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

namespace assess {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();

}  // namespace

const SafetyIndex* BuildingMechanismResult::index(const std::string& code, const std::string& approach) const {
  for (const SafetyIndex& s : a.indices)
    if (s.code == code && s.approach == approach) return &s;
  return nullptr;
}

const BuildingGoverning* BuildingAssessment::governing_of(const std::string& code, const std::string& approach) const {
  for (const BuildingGoverning& g : governing)
    if (g.code == code && g.approach == approach) return &g;
  return nullptr;
}

std::size_t governing_mechanism_kinematic(const BuildingCase& b, const std::string& approach) {
  std::vector<double> zeta(b.mechanisms.size(), inf);
  detail::parallel_for(b.mechanisms.size(), [&](std::size_t i) {
    CaseFile k = b.mechanisms[i].kase;
    k.dynamic = nlohmann::json();  // kinematic checks only
    if (k.method == "dynamic") k.method = "nonlinear";
    FacadeOptions kinematic_only;
    kinematic_only.sensitivity = false;
    kinematic_only.review = false;
    const FacadeAssessment a = assess_facade(k, kinematic_only);
    for (const char* code : {"NTC2018", "NTC2008"}) {
      for (const SafetyIndex& s : a.indices)
        if (s.code == code && s.approach == approach && s.defined) zeta[i] = s.index.zeta;
      if (zeta[i] < inf) break;
    }
  });
  std::size_t best = 0;
  for (std::size_t i = 1; i < zeta.size(); ++i)
    if (zeta[i] < zeta[best]) best = i;
  return best;
}

namespace {

// The mechanisms' warnings, each located in the building's file and tagged
// with its mechanism; a warning several mechanisms give in the same words is
// listed once with their ids ("[M1, M2, M5]"), not once per mechanism.
std::vector<std::string> merged_warnings(const BuildingCase& b, const std::vector<BuildingMechanismResult>& results) {
  std::vector<std::string> text;              // in order of first appearance
  std::vector<std::vector<std::size_t>> who;  // the mechanisms giving each
  for (std::size_t i = 0; i < results.size(); ++i)
    for (const std::string& w : results[i].a.warnings) {
      const std::size_t k = std::size_t(std::find(text.begin(), text.end(), w) - text.begin());
      if (k == text.size()) text.push_back(w), who.emplace_back();
      if (who[k].empty() || who[k].back() != i) who[k].push_back(i);
    }
  std::vector<std::string> out;
  for (std::size_t k = 0; k < text.size(); ++k) {
    const std::string one = building_path_message(b, b.mechanisms[who[k].front()], text[k]);
    if (who[k].size() == 1) {
      out.push_back(one);
      continue;
    }
    const BuildingMechanism& first = b.mechanisms[who[k].front()];
    const std::string tag = " [" + first.id + " \"" + first.name + "\"]";  // building_path_message's
    std::string ids;
    for (std::size_t i : who[k]) ids += (ids.empty() ? "" : ", ") + b.mechanisms[i].id;
    out.push_back(one.substr(0, one.size() - tag.size()) + " [" + ids + "]");
  }
  return out;
}

}  // namespace

namespace {

// Every mechanism in parallel, each error kept in its slot and the first
// thrown located in the building's file. The record sets are final:
// parse_building decided each shared selection (building_case.hpp).
void assess_mechanisms(BuildingAssessment& out, const FacadeOptions& options) {
  const BuildingCase& b = out.building;
  const std::size_t n = b.mechanisms.size();
  std::vector<std::string> errors(n);
  detail::parallel_for(n, [&](std::size_t i) {
    try {
      out.results[i].a = assess_facade(b.mechanisms[i].kase, options);
    } catch (const InputError& e) {
      errors[i] = e.what();
    }
  });
  for (std::size_t i = 0; i < n; ++i)
    if (!errors[i].empty()) throw InputError(building_path_message(b, b.mechanisms[i], errors[i]));
}

// Issue 37: a wall's ties act on every mechanism of the wall they cross: those
// mechanisms are assessed (and designed) together, one group per wall; a
// mechanism with ties of its own is a group alone.
std::vector<std::vector<std::size_t>> tie_groups(const BuildingCase& b) {
  std::vector<std::vector<std::size_t>> groups;
  std::map<std::size_t, std::size_t> wall_group;
  for (std::size_t i = 0; i < b.mechanisms.size(); ++i) {
    const BuildingMechanism& m = b.mechanisms[i];
    if (!has_ties(m.kase)) continue;
    if (!m.wall_ties) {
      groups.push_back({i});
      continue;
    }
    const auto it = wall_group.find(m.wall_index);
    if (it == wall_group.end()) {
      wall_group[m.wall_index] = groups.size();
      groups.push_back({i});
    } else {
      groups[it->second].push_back(i);
    }
  }
  return groups;
}

// Issue 23: the tie rods of each mechanism, as `assess run` of its case does
// them (after the record sets are final), one group at a time in parallel.
void assess_tie_groups(BuildingAssessment& out, const std::vector<std::vector<std::size_t>>& groups) {
  const BuildingCase& b = out.building;
  std::vector<std::string> group_errors(groups.size());
  std::vector<std::size_t> group_failing(groups.size(), 0);
  detail::parallel_for(groups.size(), [&](std::size_t g) {
    const std::vector<std::size_t>& members = groups[g];
    try {
      if (members.size() == 1) {
        out.results[members[0]].ties = assess_ties(out.results[members[0]].a);
        return;
      }
      std::vector<const FacadeAssessment*> as;
      std::vector<std::string> names;
      for (std::size_t i : members) {
        as.push_back(&out.results[i].a);
        names.push_back(b.mechanisms[i].id);
      }
      std::vector<TieInterventionResult> rs = assess_wall_ties(as, names);
      for (std::size_t k = 0; k < members.size(); ++k) out.results[members[k]].ties = std::move(rs[k]);
    } catch (const InputError& e) {
      group_errors[g] = e.what();
      group_failing[g] = members.front();
    }
  });
  for (std::size_t g = 0; g < groups.size(); ++g)
    if (!group_errors[g].empty())
      throw InputError(building_path_message(b, b.mechanisms[group_failing[g]], group_errors[g]));
}

// Each mechanism's zetaE and pass before and after the ties (without ties: the same).
void mechanism_tie_indices(BuildingAssessment& out) {
  for (std::size_t i = 0; i < out.results.size(); ++i) {
    BuildingMechanismResult& r = out.results[i];
    if (r.ties) {
      r.zeta_before = r.ties->zetaE_before;
      r.zeta_after = r.ties->zetaE_after;
      r.passes_before = r.ties->passes_before;
      r.passes_after = r.ties->passes_after;
    } else {
      r.zeta_before = r.zeta_after = zeta_E(r.a.kinematic, r.a.kase.method);
      r.passes_before = r.passes_after = every_kinematic_check_satisfied(r.a.kinematic);
    }
  }
}

// The governing mechanism of each code and approach: the lowest zetaE
// (strength, displacement), the largest D/C (dynamic, or without a zetaE);
// ties: the first in the file. With the counts of satisfied, failing and
// undecided mechanisms.
std::vector<BuildingGoverning> governing_mechanisms(const BuildingAssessment& out) {
  std::vector<BuildingGoverning> governing;
  const std::size_t n = out.results.size();
  for (const std::string& code : out.codes)
    for (const char* approach : {"strength", "displacement", "dynamic"}) {
      BuildingGoverning g;
      g.code = code;
      g.approach = approach;
      for (std::size_t i = 0; i < n; ++i) {
        const SafetyIndex* s = out.results[i].index(code, approach);
        if (!s || !s->has_checks) continue;
        ++g.assessed;
        if (s->satisfied) ++g.satisfied;
        else if (s->failing == 0 && s->no_verdict > 0) ++g.no_verdict;
        else ++g.failing;
        // Lowest zetaE (strength, displacement); largest D/C (dynamic; or
        // when no zetaE is defined). Ties: the first in the file.
        bool better;
        if (g.mechanism < 0) {
          better = true;
        } else if (s->defined) {
          better = s->index.zeta < g.zeta;
        } else {
          better = (std::isfinite(s->dc) ? s->dc : inf) > g.dc;
        }
        if (better) {
          g.mechanism = int(i);
          g.zeta = s->index.zeta;
          g.dc = std::isfinite(s->dc) ? s->dc : inf;
        }
      }
      if (g.assessed > 0) governing.push_back(g);
    }
  return governing;
}

// The building's index before and after the ties: the smallest mechanism
// zetaE (docs/theory/building.md §8). Ties: the first in the file.
BuildingTieIndex building_tie_index(const BuildingAssessment& out) {
  BuildingTieIndex t;
  for (std::size_t i = 0; i < out.results.size(); ++i) {
    const BuildingMechanismResult& r = out.results[i];
    t.any_ties = t.any_ties || r.ties.has_value();
    t.passing_before += r.passes_before;
    t.passing_after += r.passes_after;
    if (!std::isnan(r.zeta_before) && (t.mechanism_before < 0 || r.zeta_before < t.zeta_before)) {
      t.zeta_before = r.zeta_before;
      t.mechanism_before = int(i);
    }
    if (!std::isnan(r.zeta_after) && (t.mechanism_after < 0 || r.zeta_after < t.zeta_after)) {
      t.zeta_after = r.zeta_after;
      t.mechanism_after = int(i);
    }
  }
  return t;
}

}  // namespace

BuildingAssessment assess_building(BuildingCase building, const FacadeOptions& options) {
  BuildingAssessment out;
  out.building = std::move(building);
  const BuildingCase& b = out.building;
  out.results.resize(b.mechanisms.size());
  assess_mechanisms(out, options);

  // The tie rods (issues 23, 37): given ties decide the assessment's dynamic
  // rows, so the building's indices below are taken after this.
  assess_tie_groups(out, tie_groups(b));
  mechanism_tie_indices(out);
  out.warnings = merged_warnings(b, out.results);
  const FacadeAssessment& a0 = out.results.front().a;
  out.site_description = a0.site.description;
  out.VR = a0.site.VR;
  if (a0.site.actions.count(LimitState::SLV)) {
    out.TR_SLV = a0.site.actions.at(LimitState::SLV).TR;
    out.ag_SLV_g = a0.site.actions.at(LimitState::SLV).hazard.ag_g;
  }
  for (const char* code : {"NTC2018", "NTC2008"}) {
    bool present = false;
    for (const BuildingMechanismResult& r : out.results)
      for (const SafetyIndex& s : r.a.indices) present = present || s.code == code;
    if (present) out.codes.push_back(code);
  }
  out.governing = governing_mechanisms(out);
  out.tie_index = building_tie_index(out);
  out.verdict = building_verdict(out);
  return out;
}

BuildingVerdict building_verdict(const BuildingAssessment& b) {
  BuildingVerdict v;
  for (std::size_t i = 0; i < b.results.size(); ++i) {
    const BuildingMechanismResult& r = b.results[i];
    const MethodVerdict* m = r.a.verdict.conclusion();
    ++v.mechanisms;
    // No check by the adopted method (a dynamic method where the dynamic
    // analysis does not apply): no verdict, never a silent pass (issue 41).
    if (!m) {
      v.undecided.push_back(int(i));
      continue;
    }
    if (m->undecided()) v.undecided.push_back(int(i));
    else if (!m->satisfied) v.failing.push_back(int(i));
    const double dc = std::isfinite(m->max_dc) ? m->max_dc : inf;
    if (v.dc_mechanism < 0 || dc > v.max_dc) {
      v.max_dc = dc;
      v.dc_mechanism = int(i);
    }
    if (!std::isnan(r.zeta_before) && (v.zeta_mechanism < 0 || r.zeta_before < v.zeta)) {
      v.zeta = r.zeta_before;
      v.zeta_mechanism = int(i);
    }
  }
  v.satisfied = v.mechanisms > 0 && v.failing.empty() && v.undecided.empty();
  return v;
}

}  // namespace assess
