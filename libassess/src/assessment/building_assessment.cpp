// building_assessment.cpp: every mechanism of a building through
// assess_facade and assess_ties, the safety indices zetaE = PGA_C / PGA_D and
// TR_C / TR_D, the governing mechanism per approach and the building's index
// before and after the tie rods (docs/theory/building.md).
#include "assess/assessment/building_assessment.hpp"

#include "assess/hazard/hazard_curve.hpp"
#include "assess/hazard/site.hpp"
#include "assess/kinematic/code_checks.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"
#include "support/parallel_for.hpp"
#include "support/root_find.hpp"

#include <algorithm>
#include <cstdio>
#include <cmath>
#include <limits>
#include <map>
#include <memory>

namespace assess {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
constexpr double nan = std::numeric_limits<double>::quiet_NaN();

const char* method_name(const std::string& approach) {
  return approach == "strength" ? "linear" : approach == "displacement" ? "nonlinear" : "dynamic";
}

// The check input of a candidate, as run_kinematic_case builds it.
CheckInput check_input(const FacadeAssessment& a, const CandidateResult& cr) {
  CheckInput in = a.kase.checks;
  for (const auto& [ls, act] : a.kinematic.actions) in.hazard[ls] = act.hazard;
  in.site = a.kase.site->conditions;
  in.building = a.kase.building;
  in.Z = cr.Z;
  return in;
}

// NTC 2008 rows carry no PGA capacity: it is found with the reading of the NTC
// 2018 rows (docs/theory/kinematic.md §PGA), F0 and TC* of SLV held fixed, by
// re-running the checks of code_checks.cpp (no formula is repeated here):
// strength, q x the ag (g) on rock at which the demand without q reaches a0*
// (the row's D/C reaches 1/q); displacement, the ag at which the row's D/C
// reaches 1. inf if never reached below 20 g.
double ag_capacity_2008(const FacadeAssessment& a, const CandidateResult& cr, const CheckRow& row) {
  CheckInput in = check_input(a, cr);
  in.codes = {CodeEdition::NTC2008};
  in.sld = false;
  auto dc = [&](double ag) {
    in.hazard[LimitState::SLV].ag_g = ag;
    for (const CheckRow& r : run_code_checks(cr.result, in))
      if (r.code == row.code && r.limit_state == row.limit_state && r.kind == row.kind && r.location == row.location)
        return r.dc;
    return nan;
  };
  const bool strength = row.kind == "strength";
  const double target = strength ? 1.0 / in.q : 1.0, factor = strength ? in.q : 1.0;
  double lo = 1e-6, hi = 1e-3;
  while (dc(hi) < target) {
    lo = hi;
    hi *= 2.0;
    if (hi > 20.0) return inf;
  }
  return factor * detail::brent_root([&](double ag) { return dc(ag) - target; }, lo, hi, 1e-12);
}

}  // namespace

const SafetyIndex* BuildingMechanismResult::index(const std::string& code, const std::string& approach) const {
  for (const SafetyIndex& s : indices)
    if (s.code == code && s.approach == approach) return &s;
  return nullptr;
}

const BuildingGoverning* BuildingAssessment::governing_of(const std::string& code, const std::string& approach) const {
  for (const BuildingGoverning& g : governing)
    if (g.code == code && g.approach == approach) return &g;
  return nullptr;
}

std::vector<SafetyIndex> safety_indices(const FacadeAssessment& a) {
  std::vector<SafetyIndex> out;
  if (!a.kase.site) return out;
  std::unique_ptr<HazardCurve> curve;
  std::string curve_note;
  try {
    curve = std::make_unique<HazardCurve>(site_ag_hazard_curve(Site(*a.kase.site)));
  } catch (const InputError& e) {
    curve_note = e.what();
  }
  std::vector<std::string> codes;
  for (const char* c : {"NTC2018", "NTC2008"})
    for (CodeEdition e : a.kase.checks.codes)
      if (to_string(e) == c) codes.push_back(c);
  for (const std::string& code : codes) {
    for (const char* approach : {"strength", "displacement", "dynamic"}) {
      SafetyIndex s;
      s.code = code;
      s.approach = approach;
      for (const MethodVerdict& m : a.verdict.methods)
        if (m.code == code && m.method == method_name(approach)) {
          s.has_checks = m.checks > 0;
          s.dc = m.max_dc;
          s.satisfied = m.satisfied;
          s.checks = m.checks;
          s.failing = m.failing;
          s.no_verdict = m.no_verdict;
          if (m.governing >= 0) {
            s.dc_candidate = a.verdict.rows[std::size_t(m.governing)].candidate;
            for (const CandidateResult& cr : a.kinematic.candidates)
              if (cr.label == s.dc_candidate) {
                s.dc_alpha0 = cr.result.alpha0;
                s.dc_a0_star = cr.result.a0_star;
              }
          }
        }
      if (s.approach == "dynamic") {
        if (!s.has_checks) continue;
        s.note = "no PGA capacity: the dynamic check runs the records scaled to the SLV spectrum and gives a D/C, "
                 "not the PGA at which the mechanism fails (an incremental analysis would: assess fragility --ida)";
        out.push_back(s);
        continue;
      }
      // zetaE: the lowest PGA_C / PGA_D over the approach's SLV and SLC checks
      // of every candidate (the mechanism's governing check of the approach).
      double best = inf;
      bool any = false;
      for (const CandidateResult& cr : a.kinematic.candidates)
        for (const CheckRow& r : cr.checks) {
          if (r.code != code || r.kind != s.approach || (r.limit_state != "SLV" && r.limit_state != "SLC")) continue;
          const double cap = r.has_pga ? r.ag_capacity_g : ag_capacity_2008(a, cr, r);
          const double dem = r.has_pga ? r.ag_demand_g : a.kinematic.actions.at(LimitState::SLV).hazard.ag_g;
          const double ratio = cap / dem;
          if (!any || ratio < best) {
            any = true;
            best = ratio;
            s.ag_capacity_g = cap;
            s.ag_demand_g = dem;
            s.limit_state = r.limit_state;
            s.location = r.location;
            s.candidate = r.candidate;
          }
        }
      if (!any) {
        if (!s.has_checks) continue;
        s.note = "no check of this approach at SLV or SLC";
        out.push_back(s);
        continue;
      }
      s.defined = true;
      s.zeta = best;
      const LimitState ls = s.limit_state == "SLC" ? LimitState::SLC : LimitState::SLV;
      if (a.actions.count(ls)) s.TR_demand = a.actions.at(ls).TR;
      if (curve) {
        if (!std::isfinite(s.ag_capacity_g)) {
          s.TR_capacity = inf;
        } else {
          s.TR_capacity = 1.0 / curve->lambda(s.ag_capacity_g * units::g);
          s.TR_extrapolated = s.TR_capacity < tr_min_years || s.TR_capacity > tr_max_years;
        }
        s.TR_ratio = s.TR_capacity / s.TR_demand;
      } else {
        s.note = "no return period: " + curve_note;
      }
      out.push_back(s);
    }
  }
  return out;
}

std::size_t governing_mechanism_kinematic(const BuildingCase& b, const std::string& approach) {
  std::vector<double> zeta(b.mechanisms.size(), inf);
  detail::parallel_for(b.mechanisms.size(), [&](std::size_t i) {
    CaseFile k = b.mechanisms[i].kase;
    k.dynamic = nlohmann::json();  // kinematic checks only
    if (k.method == "dynamic") k.method = "nonlinear";
    const std::vector<SafetyIndex> idx = safety_indices(assess_facade(k));
    for (const char* code : {"NTC2018", "NTC2008"}) {
      for (const SafetyIndex& s : idx)
        if (s.code == code && s.approach == approach && s.defined) zeta[i] = s.zeta;
      if (zeta[i] < inf) break;
    }
  });
  std::size_t best = 0;
  for (std::size_t i = 1; i < zeta.size(); ++i)
    if (zeta[i] < zeta[best]) best = i;
  return best;
}

BuildingAssessment assess_building(BuildingCase building, const FacadeOptions& options) {
  BuildingAssessment out;
  out.building = std::move(building);
  BuildingCase& b = out.building;
  const std::size_t n = b.mechanisms.size();
  out.results.resize(n);
  std::vector<std::string> errors(n);
  std::vector<bool> todo(n, true);
  // Runs the mechanisms still to do, in parallel; each error kept in its slot.
  auto run_all = [&] {
    std::vector<std::size_t> idx;
    for (std::size_t i = 0; i < n; ++i)
      if (todo[i]) idx.push_back(i);
    detail::parallel_for(idx.size(), [&](std::size_t k) {
      const std::size_t i = idx[k];
      try {
        out.results[i].a = assess_facade(b.mechanisms[i].kase, options);
        errors[i].clear();
      } catch (const InputError& e) {
        errors[i] = e.what();
      }
    });
    std::fill(todo.begin(), todo.end(), false);
  };
  run_all();
  // A shared selection without a compatible set over the union range: its
  // members select their own records (docs/theory/building.md §3).
  // The same when the shared set's mean spectrum leaves the -10 %/+30 % band
  // over the union range (NTC 2018 §3.2.3.6): the ranges do not allow one set.
  bool again = false;
  for (std::size_t s = 0; s < b.selections.size(); ++s) {
    bool failed = false, off_band = false;
    for (std::size_t i : b.selections[s].members) {
      failed = failed || errors[i].find("no compatible set") != std::string::npos;
      const FacadeAssessment& a = out.results[i].a;
      off_band = off_band || (errors[i].empty() && a.selection && !a.selection->band_satisfied);
    }
    if (!failed && !off_band) continue;
    fall_back_to_own_selection(b, s);
    char range[64];
    std::snprintf(range, sizeof range, "%.3f-%.3f s", b.selections[s].T_min, b.selections[s].T_max);
    b.selections[s].note = std::string(failed ? "no compatible set" : "the set's mean spectrum leaves the -10 %/+30 % band") +
                           " over the union range " + range + ": each mechanism selected its own records";
    for (std::size_t i : b.selections[s].members) todo[i] = true;
    again = true;
  }
  if (again) run_all();
  for (std::size_t i = 0; i < n; ++i)
    if (!errors[i].empty()) throw InputError(building_path_message(b, b.mechanisms[i], errors[i]));

  // Issue 23: the tie rods of each mechanism, as `assess run` of its case does
  // them (after the record sets are final): given ties decide the assessment's
  // dynamic rows, so the safety indices below are computed after this.
  // Issue 37: a wall's ties act on every mechanism of the wall they cross:
  // those mechanisms are assessed (and designed) together, one group per wall.
  std::vector<std::vector<std::size_t>> groups;
  {
    std::map<std::size_t, std::size_t> wall_group;
    for (std::size_t i = 0; i < n; ++i) {
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
  }
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

  for (std::size_t i = 0; i < n; ++i) {
    BuildingMechanismResult& r = out.results[i];
    r.indices = safety_indices(r.a);
    if (r.ties) {
      r.zeta_before = r.ties->zetaE_before;
      r.zeta_after = r.ties->zetaE_after;
      r.passes_before = r.ties->passes_before;
      r.passes_after = r.ties->passes_after;
    } else {
      r.zeta_before = r.zeta_after = zeta_E(r.a.kinematic, r.a.kase.method);
      r.passes_before = r.passes_after = every_kinematic_check_satisfied(r.a.kinematic);
    }
    for (const std::string& w : r.a.warnings) out.warnings.push_back(building_path_message(b, b.mechanisms[i], w));
  }
  const FacadeAssessment& a0 = out.results.front().a;
  out.site_description = a0.site_description;
  out.VR = a0.VR;
  if (a0.actions.count(LimitState::SLV)) {
    out.TR_SLV = a0.actions.at(LimitState::SLV).TR;
    out.ag_SLV_g = a0.actions.at(LimitState::SLV).hazard.ag_g;
  }
  for (const char* code : {"NTC2018", "NTC2008"}) {
    bool present = false;
    for (const BuildingMechanismResult& r : out.results)
      for (const SafetyIndex& s : r.indices) present = present || s.code == code;
    if (present) out.codes.push_back(code);
  }
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
          better = s->zeta < g.zeta;
        } else {
          better = (std::isfinite(s->dc) ? s->dc : inf) > g.dc;
        }
        if (better) {
          g.mechanism = int(i);
          g.zeta = s->zeta;
          g.dc = std::isfinite(s->dc) ? s->dc : inf;
        }
      }
      if (g.assessed > 0) out.governing.push_back(g);
    }
  // The building's index before and after the ties: the smallest mechanism
  // zetaE (docs/theory/building.md §8). Ties: the first in the file.
  BuildingTieIndex& t = out.tie_index;
  for (std::size_t i = 0; i < n; ++i) {
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
  out.verdict = building_verdict(out);
  return out;
}

BuildingVerdict building_verdict(const BuildingAssessment& b) {
  BuildingVerdict v;
  for (std::size_t i = 0; i < b.results.size(); ++i) {
    const BuildingMechanismResult& r = b.results[i];
    const MethodVerdict* m = r.a.verdict.conclusion();
    if (!m) continue;
    ++v.mechanisms;
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
