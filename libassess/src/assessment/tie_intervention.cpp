// tie_intervention.cpp: the stato di fatto and the stato di progetto of the
// tie rods, and the design of the smallest commercial rod and plate
// (docs/theory/ties.md §5, §6).
#include "assess/assessment/tie_intervention.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <map>
#include <memory>
#include <optional>

namespace assess {
namespace {

// The checks' inputs of one candidate (as run_kinematic_case builds them).
CheckInput check_input(const CaseFile& c, const KinematicCaseResult& r, const CandidateResult& cr) {
  CheckInput in = c.checks;
  for (const auto& a : r.actions) in.hazard[a.first] = a.second.hazard;
  in.site = c.site->conditions;
  in.building = c.building;
  in.Z = cr.Z;
  return in;
}

// What each level did in the analyses of a state (per tie).
struct LevelDynamics {
  double max_force = 0.0, max_elongation = 0.0;
  int runs = 0, yielded = 0, broken = 0;
  std::string component;  // how it broke first
};

std::map<std::string, LevelDynamics> level_dynamics(const std::vector<TieDynamicRun>& runs) {
  std::map<std::string, LevelDynamics> out;
  for (const TieDynamicRun& r : runs) {
    if (r.failed) continue;
    for (const TieLevelRun& l : r.levels) {
      LevelDynamics& d = out[l.name];
      ++d.runs;
      d.max_force = std::max(d.max_force, l.max_force);
      d.max_elongation = std::max(d.max_elongation, l.max_elongation);
      d.yielded += l.yielded ? 1 : 0;
      if (l.broken && d.broken++ == 0) d.component = l.component;
    }
  }
  return out;
}

// The results of the levels c.ties[first, last) in the state `r` of case c
// (its governing candidate): the force each check needs, what the level
// develops (at the displacement demand, in the dynamics when given) and its checks.
// The code in force: NTC 2018 when the case checks it (NTC 2008 for comparison only).
bool counts(const CaseFile& c, const std::string& code) {
  bool has_2018 = false;
  for (CodeEdition e : c.checks.codes) has_2018 = has_2018 || e == CodeEdition::NTC2018;
  return !has_2018 || code == "NTC2018";
}

// `required`: compute the force each check needs (a bisection per check); the
// design's trials skip it: their mechanism's checks pass with T_Rd, which
// bounds every required force.
// Issue 37: with dynamic analyses of the state (`dyn`, or `dynamics_follow`
// when they are still to run) a tie's demand is their response (its largest
// force and elongation, and whether it broke): the static displacement demand
// of the capacity-spectrum check, on a curve whose ties may have broken, is
// used only without them (docs/theory/ties.md §3).
std::vector<TieLevelResult> level_results(const CaseFile& c, const KinematicCaseResult& r, std::size_t first,
                                          std::size_t last, const std::map<std::string, LevelDynamics>* dyn,
                                          bool required = true, bool dynamics_follow = false) {
  std::vector<TieLevelResult> out;
  const CandidateResult& cr = r.candidates[r.governing];
  const Chain& chain = c.mechanism.candidates[r.governing].chain;
  const std::vector<TieRestraint> ties = case_tie_restraints(c, chain);
  const CheckInput in = check_input(c, r, cr);
  // The largest displacement demand d* among the displacement checks of the
  // tied mechanism itself (m; not the bare wall's fallback), and each level's
  // elongation there: a tie that is not ductile must carry P0 + k e
  // elastically (it fails beyond its strength), a ductile one carries at most
  // its strength and elongates.
  KinematicResult tied = cr.result;
  tied.without_ties.reset();
  double d_demand = -1.0;
  for (const CheckRow& row : run_code_checks(tied, in))
    if (row.kind == "displacement" && counts(c, row.code) && std::isfinite(row.demand))
      d_demand = std::max(d_demand, row.demand);
  std::vector<double> elong;
  if (!dyn && !dynamics_follow && d_demand >= 0.0 && cr.result.curve_complete())
    elong = tie_elongations_at(chain, cr.result, ties, d_demand);
  for (std::size_t i = first; i < last; ++i) {
    TieLevelResult L;
    L.tie = c.ties[i];
    L.resistance = tie_resistance(L.tie);
    // Index of this level among the candidate's restraints (levels not on it are skipped).
    std::size_t k = 0, found = ties.size();
    for (std::size_t j = 0; j < c.ties.size(); ++j) {
      if (tie_block(chain, c.ties[j].block, c.ties[j].point) < 0) continue;
      if (j == i) found = k;
      ++k;
    }
    if (found < ties.size()) {
      L.count = ties[found].count;
      KinematicOptions opt = c.options;  // issue 33: the candidate's own bound on its rotation, as in run_kinematic_case
      opt.rotation_cap = c.mechanism.candidates[r.governing].rotation_bound;
      if (required) L.required = required_tie_forces(chain, opt, in, ties, found, L.tie.spacing);
      for (const RequiredTieForce& f : L.required) {
        if (!counts(c, f.code)) continue;
        if (f.reachable) {
          L.demand.static_force = std::max(L.demand.static_force, f.per_tie);
        } else if (L.demand.reachable) {
          L.demand.reachable = false;
          L.demand.unreachable = f.code + " " + f.limit_state + " " + f.kind + " " + f.location + ": " + f.reason;
        }
      }
      if (found < elong.size() && std::isfinite(elong[found])) {
        const double e = std::max(0.0, elong[found]);
        const TieRestraint& R = ties[found];
        L.demand.elongation = e;
        L.demand.curve_force = (R.ductile ? tie_force(R, e) : R.pretension + R.stiffness * e) / R.count;
      }
    }
    if (dyn) {
      const auto it = dyn->find(L.tie.name);
      if (it != dyn->end()) {
        const LevelDynamics& d = it->second;
        L.demand.dynamic_force = d.max_force;
        L.demand.elongation = std::max(L.demand.elongation.value_or(0.0), d.max_elongation);
        L.demand.dynamic_runs = d.runs;
        L.demand.dynamic_breaks = d.broken;
        L.demand.dynamic_component = d.component;
        L.dynamic_runs = d.runs;
        L.dynamic_yielded = d.yielded;
        L.dynamic_broken = d.broken;
      }
    }
    L.checks = tie_checks(L.tie, L.demand);
    L.satisfied = std::all_of(L.checks.begin(), L.checks.end(), [](const TieCheckRow& x) { return x.satisfied; });
    out.push_back(L);
  }
  return out;
}

bool all_satisfied(const std::vector<TieLevelResult>& lv) {
  return std::all_of(lv.begin(), lv.end(), [](const TieLevelResult& l) { return l.satisfied; });
}

// The thread of a designed rod's ends: its own (threaded), or the smallest
// ISO thread up to max_upset_ratio d that satisfies the capacity design with
// its section after the corrosion allowance `corrosion` (m) (upset, welded).
const tie_catalogue::Thread* design_thread(double d, const tie_catalogue::SteelGrade& g, TieEnds ends,
                                           double corrosion) {
  namespace C = tie_catalogue;
  if (ends == TieEnds::Threaded) return C::find_thread(d);
  const double A = units::pi * d * d / 4.0;
  for (const C::Thread& t : C::threads) {
    TieRod r;
    r.thread_area = t.As;
    r.corrosion = corrosion;
    if (t.d >= d - 1e-4 && t.d <= C::max_upset_ratio * d + 1e-4 &&
        C::thread_k2 * g.ftk * r.corroded_thread_area() / C::gamma_M2 >= C::gamma_Rd * C::gamma_ov * A * g.fyk)
      return &t;
  }
  return nullptr;
}

// ---- Issue 37: the search ---------------------------------------------------
// docs/theory/ties.md §5. A commercial choice of rod and anchor, in the order
// of the search: rods smallest first (from the smallest allowed), for each rod
// the rod grades in the order given, for each grade the anchor types in the
// order given (plates, bars), for each type its list smallest first, for each
// anchor the anchor grades in the order given.
struct Choice {
  double d = 0.0;
  const tie_catalogue::SteelGrade* grade = nullptr;
  AnchorType type = AnchorType::Plate;
  double a = 0.0, b = 0.0, t = 0.0;  // plate side and thickness, or bar length and diameter (m)
  const tie_catalogue::SteelGrade* anchor_grade = nullptr;
};

std::vector<Choice> anchor_choices(const TieDesignSpec& spec) {
  namespace C = tie_catalogue;
  std::vector<Choice> out;
  for (AnchorType type : spec.anchors) {
    if (type == AnchorType::Plate) {
      for (const C::Plate& p : C::plates)
        for (const std::string& g : spec.plate_grades)
          out.push_back({0.0, nullptr, type, p.a, p.a, p.t, C::find_grade(g)});
    } else {
      for (const C::Bar& x : C::bars)
        for (const std::string& g : spec.plate_grades)
          out.push_back({0.0, nullptr, type, x.a, x.b, 0.0, C::find_grade(g)});
    }
  }
  return out;
}

std::vector<Choice> choices(const TieDesignSpec& spec, double d_min) {
  namespace C = tie_catalogue;
  std::vector<Choice> out;
  const std::vector<Choice> anchors = anchor_choices(spec);
  for (double d : C::rod_diameters) {
    if (d < d_min - 1e-6) continue;
    for (const std::string& g : spec.grades)
      for (Choice c : anchors) {
        c.d = d;
        c.grade = C::find_grade(g);
        out.push_back(c);
      }
  }
  return out;
}

void set_anchor(Tie& t, const Choice& c) {
  t.anchor.type = c.type;
  t.anchor.a = c.a;
  t.anchor.b = c.b;
  t.anchor.t = c.type == AnchorType::Plate ? c.t : 0.0;
  t.anchor.grade = c.anchor_grade->name;
  t.anchor.fyk = c.anchor_grade->fyk;
}

bool set_rod(Tie& t, const Choice& c, TieEnds ends) {
  namespace C = tie_catalogue;
  const C::Thread* th = design_thread(c.d, *c.grade, ends, t.rod.corrosion);
  if (!th) return false;
  t.rod.diameter = c.d;
  t.rod.area = units::pi * c.d * c.d / 4.0;
  t.rod.grade = c.grade->name;
  t.rod.fyk = c.grade->fyk;
  t.rod.ftk = c.grade->ftk;
  t.rod.eps_uk = c.grade->eps_uk;
  t.rod.gamma_M0 = C::gamma_M0;
  t.rod.E = C::steel_E;
  t.rod.ends = ends;
  t.rod.thread_diameter = th->d;
  t.rod.thread_area = th->As;
  t.rod.nut_width = th->s;
  return true;
}

bool buildable(const Tie& t) {
  try {
    (void)tie_resistance(t);
    return true;
  } catch (const InputError&) {
    return false;
  }
}

// The designed levels with choice c; nullopt when it cannot be built (no
// thread, an anchor no wider than its nut or not within the wall, a
// pretension at or above the tie's strength).
std::optional<std::vector<Tie>> designed_levels(const TieDesignSpec& spec, const Choice& c) {
  std::vector<Tie> levels = spec.levels;
  for (std::size_t i = 0; i < levels.size(); ++i) {
    Tie& t = levels[i];
    t.existing = false;
    if (!set_rod(t, c, spec.ends)) return std::nullopt;
    set_anchor(t, c);
    if (!(i < spec.pretension_given.size() && spec.pretension_given[i])) t.pretension = thermal_pretension(t);
    if (!buildable(t)) return std::nullopt;
  }
  return levels;
}

// The stato di progetto's dynamics of a trial, and whether the design may
// stop: no level broken in any analysis and every dynamic check satisfied.
struct DynamicVerdict {
  bool ok = true;
  std::string component;  // the first broken component
  bool broke = false;
};
DynamicVerdict dynamic_verdict(const TieDynamicResult& d) {
  DynamicVerdict v;
  if (!d.applies) return v;
  for (const TieDynamicRun& r : d.runs)
    for (const TieLevelRun& l : r.levels)
      if (l.broken) {
        v.ok = false;
        if (!v.broke) v.component = l.component;
        v.broke = true;
      }
  for (const TieDynamicSummary& s : d.summaries) v.ok = v.ok && s.satisfied_after;
  return v;
}

// A key of what the analyses of a state depend on: every level's restraint
// law (per tie: point, direction, tributary length, stiffness, strength,
// pretension, ductility, ultimate elongation, governing component). Two
// states with the same key have the same kinematic and dynamic results.
std::string restraint_key(const std::vector<Tie>& ties) {
  std::string k;
  char buf[512];
  for (const Tie& t : ties) {
    const TieResistance r = tie_resistance(t);
    std::snprintf(buf, sizeof buf, "%s|%d|%.17g,%.17g|%.17g,%.17g|%.17g|%.17g|%.17g|%.17g|%d|%.17g|%s;", t.name.c_str(),
                  t.block, t.point.x(), t.point.y(), t.direction.x(), t.direction.y(), t.spacing, r.stiffness,
                  r.design, t.pretension, r.ductile ? 1 : 0, r.ultimate_elongation, r.governing.c_str());
    k += buf;
  }
  return k;
}

// One mechanism of the search (a single case, or a mechanism of a wall).
struct Member {
  const CaseFile* c = nullptr;
  const FacadeAssessment* a = nullptr;  // null: kinematic analyses only
  std::string name;
  CaseFile case_before;
  KinematicCaseResult before;
  // The analyses of a state, by restraint_key.
  struct Cached {
    KinematicCaseResult after;
    std::optional<TieDynamicResult> dynamics;
  };
  std::map<std::string, std::shared_ptr<Cached>> memo;
};

// A state of the wall: the ties of every member in the stato di progetto.
struct Proposal {
  std::optional<Choice> choice;       // the design levels' rod and anchor (none: no level to design)
  std::vector<Tie> design;            // the designed levels (all of the wall's)
  std::vector<TieChange> changes;     // to existing levels
};

// The ties of member m in the proposal: its existing ties (changed or
// removed), its given new ties, the designed levels it holds (by name).
std::vector<Tie> member_ties(const Member& m, const Proposal& p) {
  std::vector<Tie> out;
  for (const Tie& t : m.c->ties) {
    const TieChange* ch = nullptr;
    for (const TieChange& x : p.changes)
      if (x.level == t.name) ch = &x;
    if (!ch) out.push_back(t);
    else if (ch->after) out.push_back(*ch->after);
  }
  for (const Tie& t : m.c->new_ties) out.push_back(t);
  if (m.c->tie_design)
    for (const Tie& d : m.c->tie_design->levels)
      for (const Tie& t : p.design)
        if (t.name == d.name) {
          Tie x = t;  // the wall's level, with this mechanism's anchoring of it (block, defaults)
          x.block = d.block;
          out.push_back(x);
        }
  return out;
}

// What a proposal gives on one member.
struct MemberEval {
  TieInterventionResult T;
  int stage = 0;  // 1 a check of the mechanism, 2 a check of a tie, 3 the dynamics, 4 every check satisfied
  std::vector<std::string> failing_existing;  // existing levels (by name) whose checks fail
  bool only_existing = false;                 // every failure is an existing level's check
  std::string component;                      // the first broken component (stage 3)
  bool broke = false;
  double worst = 0.0;                          // the largest D/C of the mechanism's checks
  int cost = 0;                                // analyses run (not reused): kinematic 1, dynamic set 20
};

// The existing levels (by name) whose checks fail in E.T.levels, into
// E.failing_existing; true when a level that is not existing fails.
bool note_failing_levels(MemberEval& E) {
  E.failing_existing.clear();
  bool others = false;
  for (const TieLevelResult& l : E.T.levels) {
    if (l.satisfied) continue;
    if (l.tie.existing) E.failing_existing.push_back(l.tie.name);
    else others = true;
  }
  return others;
}

// The dynamic stage of a state whose kinematic and tie checks pass: the
// dynamic analyses with the ties (cached by state), the levels checked
// against their dynamic forces (the static demand when the tied dynamics do
// not apply after all), the dynamic verdict. Sets E.stage 2 or 3 on a
// failure; leaves it otherwise.
void dynamic_stage(Member& m, Member::Cached& cache, bool dynamics_follow, MemberEval& E) {
  TieInterventionResult& T = E.T;
  if (!cache.dynamics) {
    cache.dynamics = run_tie_dynamics(*m.a, T);
    E.cost += 20;
  }
  T.dynamics = *cache.dynamics;
  if (!T.dynamics.applies && dynamics_follow) {  // no tied dynamics after all: the static demand
    T.levels = level_results(T.case_after, T.after, 0, T.case_after.ties.size(), nullptr, false);
    const bool others = note_failing_levels(E);
    if (others || !E.failing_existing.empty()) {
      E.stage = 2;
      E.only_existing = !others;
      return;
    }
  }
  if (!T.dynamics.applies) return;
  const std::map<std::string, LevelDynamics> dyn = level_dynamics(T.dynamics.runs);
  T.levels = level_results(T.case_after, T.after, 0, T.case_after.ties.size(), &dyn, false);
  const bool others = note_failing_levels(E);
  const DynamicVerdict v = dynamic_verdict(T.dynamics);
  if (v.ok && !others && E.failing_existing.empty()) return;
  E.stage = 3;
  E.broke = v.broke;
  E.component = v.component;
  E.only_existing = !others && !E.failing_existing.empty();
  // A broken new level or a failed dynamic check is not the existing ties' alone.
  if (v.broke) {
    bool new_broke = false;
    for (const TieDynamicRun& r : T.dynamics.runs)
      for (const TieLevelRun& l : r.levels)
        for (const TieLevelResult& x : T.levels)
          if (l.broken && x.tie.name == l.name && !x.tie.existing) new_broke = true;
    if (new_broke) E.only_existing = false;
  }
  for (const TieDynamicSummary& sm : T.dynamics.summaries)
    if (!sm.satisfied_after && E.failing_existing.empty()) E.only_existing = false;
}

// What proposal p gives on member m, stage by stage to the first that fails:
// the mechanism's checks, its levels' checks, the dynamics (dynamic_stage).
// The analyses of a state are cached by its restraints (Member::memo).
MemberEval evaluate(Member& m, const Proposal& p) {
  MemberEval E;
  TieInterventionResult& T = E.T;
  T.designed = m.c->tie_design.has_value();
  T.intervention = true;
  T.case_before = m.case_before;
  T.before = m.before;
  T.case_after = m.case_before;
  T.case_after.ties = member_ties(m, p);
  T.case_after.new_ties.clear();
  T.case_after.tie_design.reset();
  const std::string key = restraint_key(T.case_after.ties);
  std::shared_ptr<Member::Cached>& cache = m.memo[key];
  if (!cache) {
    cache = std::make_shared<Member::Cached>();
    cache->after = run_kinematic_case(T.case_after, false);  // a trial: no safety indices (finish)
    E.cost += 1;
  }
  T.after = cache->after;
  for (const CandidateResult& cr : T.after.candidates)
    for (const CheckRow& row : cr.checks)
      if (counts(*m.c, row.code)) E.worst = std::max(E.worst, std::isfinite(row.dc) ? row.dc : 1e300);
  const bool kin_ok = every_kinematic_check_satisfied(T.after);
  const bool dynamics_follow = m.a && m.a->dynamics.mechanism && !m.a->dynamics.runs.empty();
  T.levels = level_results(T.case_after, T.after, 0, T.case_after.ties.size(), nullptr, false, dynamics_follow);
  const bool new_fail = note_failing_levels(E);
  if (!kin_ok) {
    E.stage = 1;
    return E;
  }
  if (new_fail || !E.failing_existing.empty()) {
    E.stage = 2;
    E.only_existing = !new_fail;
    return E;
  }
  E.stage = 4;
  if (m.a) dynamic_stage(m, *cache, dynamics_follow, E);
  return E;
}

// The changes tried for the existing levels that fail, in the order of the
// least change (docs/theory/ties.md §5): for each level a new anchor on its
// rod (the design's anchors, smallest first, each anchor grade), then a new
// rod: the designed tie `x` (its rod, ends and anchor) through the same holes,
// or without a level to design the design's rods from the level's own
// diameter up with each anchor (ductile ones first), then its removal; for
// several levels, the tuples of their options by the largest rank, then the
// sum of the ranks.
std::vector<std::vector<TieChange>> change_options(const TieDesignSpec& spec, const std::vector<const Tie*>& failing,
                                                   const std::optional<Choice>& x, std::size_t cap) {
  std::vector<std::vector<TieChange>> per;
  for (const Tie* t : failing) {
    std::vector<TieChange> opts;
    for (const Choice& c : anchor_choices(spec)) {
      Tie y = *t;
      set_anchor(y, c);
      if (buildable(y)) opts.push_back({t->name, "anchor", *t, y});
    }
    std::vector<Choice> rods;
    if (x) rods.push_back(*x);
    else rods = choices(spec, std::max(spec.min_rod_diameter, t->rod.diameter));
    std::vector<TieChange> ductile, elastic;  // a new rod: ductile ones first, as the design
    for (const Choice& c : rods) {
      Tie y = *t;
      y.existing = false;  // a new rod: a new tie through the same holes
      if (!set_rod(y, c, spec.ends)) continue;
      set_anchor(y, c);
      y.pretension = thermal_pretension(y);
      if (!buildable(y)) continue;
      (tie_resistance(y).ductile ? ductile : elastic).push_back({t->name, "rod", *t, y});
    }
    opts.insert(opts.end(), ductile.begin(), ductile.end());
    opts.insert(opts.end(), elastic.begin(), elastic.end());
    opts.push_back({t->name, "removed", *t, std::nullopt});
    per.push_back(std::move(opts));
  }
  std::vector<std::vector<std::size_t>> tuples{{}};
  for (const auto& o : per) {
    std::vector<std::vector<std::size_t>> next;
    for (const auto& tu : tuples)
      for (std::size_t i = 0; i < o.size() && next.size() < cap; ++i) {
        auto y = tu;
        y.push_back(i);
        next.push_back(y);
      }
    tuples = std::move(next);
  }
  std::stable_sort(tuples.begin(), tuples.end(), [](const auto& a, const auto& b) {
    const std::size_t ma = a.empty() ? 0 : *std::max_element(a.begin(), a.end());
    const std::size_t mb = b.empty() ? 0 : *std::max_element(b.begin(), b.end());
    if (ma != mb) return ma < mb;
    std::size_t sa = 0, sb = 0;
    for (std::size_t v : a) sa += v;
    for (std::size_t v : b) sb += v;
    return sa < sb;
  });
  std::vector<std::vector<TieChange>> out;
  for (const auto& tu : tuples) {
    std::vector<TieChange> ch;
    for (std::size_t k = 0; k < tu.size(); ++k) ch.push_back(per[k][tu[k]]);
    out.push_back(std::move(ch));
  }
  return out;
}

std::string changes_text(const std::vector<TieChange>& ch) {
  std::string s;
  for (const TieChange& c : ch) s += (s.empty() ? "" : "; ") + c.level + ": " + describe_change(c);
  return s;
}

// The budget of one design's analyses (docs/theory/ties.md §5): a kinematic
// analysis of a mechanism counts 1, the dynamic analyses of a state 20 (their
// usual cost ratio), a state already analysed nothing; beyond it the search
// stops and says so (no hang on a wall no tie can hold).
constexpr int max_cost = 1000;

// The results of the members in a final state (the accepted proposal, the one
// that came closest, or the only one without a design): every level with the
// force each check needs and its dynamics, both states' checks, zeta_E.
TieInterventionResult finish(Member& m, const Proposal& p, bool designed) {
  TieInterventionResult R;
  if (designed || !m.c->new_ties.empty() || !p.changes.empty()) {
    R = std::move(evaluate(m, p).T);
    R.intervention = true;
  } else {  // one state: the case as it is
    R.case_before = R.case_after = m.case_before;
    R.before = R.after = m.before;
    R.intervention = false;
    if (m.a) R.dynamics = run_tie_dynamics(*m.a, R);
  }
  R.designed = designed;
  if (R.intervention && !R.dynamics.applies && m.a) {
    // The dynamics of the state even when the evaluation stopped before them.
    const std::string key = restraint_key(R.case_after.ties);
    std::shared_ptr<Member::Cached>& cache = m.memo[key];
    if (!cache) {
      cache = std::make_shared<Member::Cached>();
      cache->after = R.after;
    }
    if (!cache->dynamics) cache->dynamics = run_tie_dynamics(*m.a, R);
    R.dynamics = *cache->dynamics;
  }
  // The state adopted, with its checks' safety indices (issue 41; a trial's
  // analysis leaves them out: they cost 0.3 ms a check and only ζE reads them).
  if (R.intervention) R.after = run_kinematic_case(R.case_after, true, &R.after);  // the same analyses, checks again
  R.zetaE_before = zeta_E(R.before, m.c->method);
  const std::size_t n_existing = m.c->ties.size();
  auto dyn_of = [](const std::vector<TieDynamicRun>& runs, bool applies) {
    return applies ? std::optional<std::map<std::string, LevelDynamics>>(level_dynamics(runs)) : std::nullopt;
  };
  const auto dyn_before = dyn_of(R.dynamics.runs_before, R.dynamics.applies);
  const auto dyn_after = dyn_of(R.dynamics.runs, R.dynamics.applies);
  R.levels_before = level_results(R.case_before, R.before, 0, n_existing, dyn_before ? &*dyn_before : nullptr);
  R.levels = R.intervention ? level_results(R.case_after, R.after, 0, R.case_after.ties.size(),
                                            dyn_after ? &*dyn_after : nullptr)
                            : R.levels_before;
  R.passes_before = every_kinematic_check_satisfied(R.before) && all_satisfied(R.levels_before);
  R.passes_after = every_kinematic_check_satisfied(R.after) && all_satisfied(R.levels) &&
                   dynamic_verdict(R.dynamics).ok;
  R.zetaE_after = R.intervention ? zeta_E(R.after, m.c->method) : R.zetaE_before;
  for (const TieChange& ch : p.changes)
    for (const Tie& t : m.c->ties)
      if (t.name == ch.level) R.changes.push_back(ch);
  for (const TieLevelResult& l : R.levels)
    if (l.tie.existing && !l.satisfied) R.failing_existing.push_back(l.tie.name);
  if (designed) {
    bool ductile = true;
    for (const TieLevelResult& l : R.levels)
      if (!l.tie.existing) ductile = ductile && l.resistance.ductile;
    R.regime = ductile ? "ductile" : "elastic";
  }
  return R;
}

// The design of a wall: the union of its members' design levels (by name)
// and the first member's spec; none when no member designs a level.
std::optional<TieDesignSpec> wall_design(const std::vector<Member>& members) {
  std::optional<TieDesignSpec> wall;
  for (const Member& m : members)
    if (m.c->tie_design) {
      if (!wall) {
        wall = *m.c->tie_design;
        wall->levels.clear();
        wall->pretension_given.clear();
      }
      const TieDesignSpec& d = *m.c->tie_design;
      for (std::size_t i = 0; i < d.levels.size(); ++i) {
        bool seen = false;
        for (const Tie& t : wall->levels) seen = seen || t.name == d.levels[i].name;
        if (seen) continue;
        wall->levels.push_back(d.levels[i]);
        wall->pretension_given.push_back(i < d.pretension_given.size() && d.pretension_given[i]);
      }
    }
  return wall;
}

// The search over the members together (docs/theory/ties.md §5): the design's
// rods and anchors in order, ductile ones first (two passes), each with the
// least change to the existing levels that fail, to the first state that
// every member passes and its final results confirm; within a budget of
// analyses (max_cost). It keeps the log of the states tried and the closest.
class WallSearch {
 public:
  WallSearch(std::vector<Member>& members, const TieDesignSpec& wall) : members_(members), wall_(wall) {
    order_.resize(members.size());
    for (std::size_t i = 0; i < order_.size(); ++i) order_[i] = i;
  }

  std::vector<TieInterventionResult> run() {
    const std::vector<std::optional<Choice>> xs = design_choices();
    for (int pass = 0; pass < 2 && !accepted_ && !truncated_; ++pass)
      for (const std::optional<Choice>& x : xs) {
        if (accepted_ || truncated_) break;
        try_choice(x, pass);
      }
    return results();
  }

 private:
  // What a proposal gives on the wall: the first member that fails, its stage.
  struct WallEval {
    int stage = 4;
    std::vector<std::string> failing_existing;
    bool only_existing = true;
    std::string component, mechanism;
    bool broke = false;
    double worst = 0.0;
  };

  std::vector<Member>& members_;
  const TieDesignSpec& wall_;
  int tried_ = 0, evaluations_ = 0, cost_ = 0;
  std::vector<TieTrial> trials_;
  std::map<std::string, int> why_;  // outcome -> count
  std::map<std::string, int> broken_by_;
  std::optional<Proposal> accepted_, closest_;
  std::pair<int, double> closest_score_{-1, 0.0};
  bool truncated_ = false;
  // The members in the order they are evaluated: the one that failed last
  // first (the same results, sooner: a state fails at its first failing member).
  std::vector<std::size_t> order_;
  std::vector<TieInterventionResult> confirmed_;  // the final results of the last state confirmed

  // The designed levels' choices (one without a level to design).
  std::vector<std::optional<Choice>> design_choices() const {
    std::vector<std::optional<Choice>> xs;
    if (wall_.levels.empty()) xs.push_back(std::nullopt);
    else
      for (const Choice& c : choices(wall_, wall_.min_rod_diameter)) xs.push_back(c);
    return xs;
  }

  // Every existing level of the wall, by name (its first member's).
  const Tie* existing_level(const std::string& name) const {
    for (const Member& m : members_)
      for (const Tie& t : m.c->ties)
        if (t.name == name) return &t;
    return nullptr;
  }

  // Evaluates a proposal on every member, in order, to the first that fails.
  WallEval evaluate_all(const Proposal& p) {
    WallEval W;
    ++evaluations_;
    for (std::size_t k = 0; k < order_.size(); ++k) {
      Member& m = members_[order_[k]];
      const MemberEval E = evaluate(m, p);
      cost_ += E.cost;
      W.worst = std::max(W.worst, E.worst);
      for (const std::string& n : E.failing_existing)
        if (std::find(W.failing_existing.begin(), W.failing_existing.end(), n) == W.failing_existing.end())
          W.failing_existing.push_back(n);
      if (E.stage < 4) {
        W.stage = E.stage;
        W.only_existing = E.only_existing;
        W.component = E.component;
        W.broke = E.broke;
        W.mechanism = m.name;
        std::rotate(order_.begin(), order_.begin() + long(k), order_.begin() + long(k) + 1);
        return W;
      }
    }
    return W;
  }

  // The trial's line of the log: the rod and anchor, the changes, the outcome.
  void log(const Proposal& p, const WallEval& W) {
    TieTrial t;
    if (p.choice) {
      const Choice& c = *p.choice;
      t.diameter = c.d;
      t.grade = c.grade->name;
      t.anchor = c.type;
      t.plate = c.a;
      t.plate_t = c.type == AnchorType::Plate ? c.t : c.b;
      t.plate_grade = c.anchor_grade->name;
      t.T_Rd = std::numeric_limits<double>::infinity();
      t.ductile = true;
      for (const Tie& x : p.design) {
        const TieResistance r = tie_resistance(x);
        t.thread = x.rod.thread_diameter;
        if (r.design < t.T_Rd) t.T_Rd = r.design, t.governing = r.governing;
        t.ductile = t.ductile && r.ductile;
      }
    }
    t.changes = changes_text(p.changes);
    t.mechanism = members_.size() > 1 ? W.mechanism : "";
    t.component = W.component;
    t.outcome = W.stage == 4 ? "accepted"
                : W.stage == 1 ? "mechanism"
                : W.only_existing ? "existing"
                : W.stage == 2 ? "tie"
                : W.broke ? "broken" : "dynamic";
    ++why_[t.outcome];
    if (t.outcome == "broken") ++broken_by_[W.component];
    trials_.push_back(t);
  }

  // Evaluates a state, logs it and keeps it when it is the closest yet (the
  // furthest stage, then the smallest D/C).
  WallEval try_state(const Proposal& p) {
    const WallEval W = evaluate_all(p);
    log(p, W);
    const std::pair<int, double> score{W.stage, -W.worst};
    if (score > closest_score_) {
      closest_score_ = score;
      closest_ = p;
    }
    return W;
  }

  // A proposal passes when every member passes and the final results (with
  // the force each check needs) confirm it.
  bool confirm(const Proposal& p) {
    confirmed_.clear();
    for (Member& m : members_) {
      confirmed_.push_back(finish(m, p, true));
      if (!confirmed_.back().passes_after) return false;
    }
    return true;
  }

  // The budget of analyses: once spent, the search stops.
  bool out_of_budget() {
    if (cost_ >= max_cost) truncated_ = true;
    return truncated_;
  }

  // The rod and anchor x (its pass: ductile levels in the first), then, when
  // existing levels fail with it, the changes to them in the order of the
  // least change.
  void try_choice(const std::optional<Choice>& x, int pass) {
    Proposal p;
    p.choice = x;
    if (x) {
      const std::optional<std::vector<Tie>> lv = designed_levels(wall_, *x);
      if (!lv) return;
      p.design = *lv;
      bool ductile = true;
      for (const Tie& t : p.design) ductile = ductile && tie_resistance(t).ductile;
      if ((pass == 0) != ductile) return;
    } else if (pass == 1) {
      return;
    }
    ++tried_;
    if (out_of_budget()) return;
    const WallEval W = try_state(p);
    if (W.stage == 4) {
      if (confirm(p)) accepted_ = p;
      return;
    }
    if (W.failing_existing.empty()) return;
    std::vector<const Tie*> failing;
    for (const std::string& n : W.failing_existing)
      if (const Tie* t = existing_level(n)) failing.push_back(t);
    for (const std::vector<TieChange>& ch : change_options(wall_, failing, x, 4096)) {
      if (out_of_budget()) return;
      Proposal q = p;
      q.changes = ch;
      if (try_state(q).stage == 4 && confirm(q)) {
        accepted_ = q;
        return;
      }
    }
  }

  // Why no state passed: the count of the states by their first failure.
  std::string failure_message() const {
    std::string reasons;
    auto add = [&](const char* key, const std::string& what) {
      const auto it = why_.find(key);
      if (it != why_.end() && it->second > 0)
        reasons += (reasons.empty() ? "" : "; ") + std::to_string(it->second) + " " + what;
    };
    add("mechanism", "with a check of a mechanism not satisfied");
    add("tie", "with a check of a new tie not satisfied");
    add("existing", "with a check of an existing tie not satisfied");
    std::string comps;
    for (const auto& [k, n] : broken_by_) comps += (comps.empty() ? "" : ", ") + k + " " + std::to_string(n);
    add("broken", "with a tie broken in a dynamic analysis (" + comps + ")");
    add("dynamic", "with the dynamic check not satisfied");
    return "no rod and anchor of the lists" +
           std::string(wall_.levels.empty() ? "" : " (rods from " +
                                                      std::to_string(static_cast<int>(std::lround(wall_.min_rod_diameter * 1e3))) +
                                                      " mm)") +
           ", with the least change to the existing ties that fail, makes every check pass (" +
           std::to_string(evaluations_) + " states analysed: " + (reasons.empty() ? "none buildable" : reasons) + ")" +
           (truncated_ ? "; the search stopped at its budget of analyses (" + std::to_string(max_cost) +
                             " units: a kinematic analysis 1, a state's dynamic analyses 20; docs/theory/ties.md "
                             "§5): the later combinations were not tried"
                       : "") +
           "; add ties along the wall or tie levels, use upset ends or bar anchors, or consider another intervention";
  }

  // Each member's results in the state accepted, else the closest (else none).
  std::vector<TieInterventionResult> results() {
    const Proposal final_p = accepted_ ? *accepted_ : closest_ ? *closest_ : Proposal{};
    const std::string message = accepted_ ? "" : failure_message();
    std::vector<TieInterventionResult> out;
    for (std::size_t i = 0; i < members_.size(); ++i) {
      TieInterventionResult R =
          accepted_ && i < confirmed_.size() ? std::move(confirmed_[i]) : finish(members_[i], final_p, true);
      R.found = accepted_.has_value();
      R.message = message;
      R.tried = tried_;
      R.trials = trials_;
      if (members_.size() > 1)
        for (const Member& m : members_) R.wall_members.push_back(m.name);
      out.push_back(std::move(R));
    }
    return out;
  }
};

// The search over the members together (docs/theory/ties.md §5); without a
// design, each mechanism as it is given.
std::vector<TieInterventionResult> search(std::vector<Member>& members) {
  const std::optional<TieDesignSpec> wall = wall_design(members);
  if (wall) return WallSearch(members, *wall).run();
  std::vector<TieInterventionResult> out;
  for (Member& m : members) out.push_back(finish(m, Proposal{}, false));
  return out;
}

std::vector<TieInterventionResult> run_members(const std::vector<const CaseFile*>& cases,
                                               const std::vector<const FacadeAssessment*>& assessments,
                                               const std::vector<std::string>& names) {
  std::vector<Member> members(cases.size());
  for (std::size_t i = 0; i < cases.size(); ++i) {
    const CaseFile& c = *cases[i];
    if (!c.site)
      throw InputError(c.file + ": /site: missing: the ties are designed and checked against the site's hazard");
    Member& m = members[i];
    m.c = &c;
    m.a = assessments[i];
    m.name = names[i];
    // Stato di fatto: the case as read (its existing ties act), no intervention.
    m.case_before = c;
    m.case_before.tie_design.reset();
    m.case_before.new_ties.clear();
    m.before = run_kinematic_case(m.case_before);
  }
  return search(members);
}

TieInterventionResult intervention(const CaseFile& c, const FacadeAssessment* a) {
  return run_members({&c}, {a}, {""}).front();
}

// One analysis as the ties section reports it: each level's outcome per tie;
// over the levels, the largest force per tie, elongation and permanent set,
// and the energy dissipated by one tie of each level, summed.
TieDynamicRun tie_run(const MechanismDynamics& md, const DynamicRun& run, std::size_t i) {
  TieDynamicRun d;
  d.run = i;
  d.record = run.record;
  d.reversed = run.reversed;
  d.e = run.e;
  d.theta_max = run.result.theta_max;
  d.theta_collapse = run.result.theta_u;
  d.overturned = run.result.overturned;
  for (std::size_t l = 0; l < run.result.ties.size() && l < md.ties.size(); ++l) {
    const TiedLevelResult& x = run.result.ties[l];
    const DynamicTie& t = md.ties[l];
    TieLevelRun lr;
    lr.name = t.level.name;
    lr.max_force = x.max_force * t.per_tie;
    lr.max_elongation = x.max_elongation;
    lr.yielded = x.yielded;
    lr.plastic_elongation = x.plastic_elongation;
    lr.broken = x.broken;
    lr.t_broken = x.t_broken;
    if (x.broken) lr.component = x.broken_by_elongation ? "elongation" : t.level.governing;
    d.yielded = d.yielded || x.yielded;
    d.broken = d.broken || x.broken;
    d.max_force = std::max(d.max_force, lr.max_force);
    d.plastic_elongation = std::max(d.plastic_elongation, x.plastic_elongation);
    d.plastic_energy += x.plastic_energy * t.per_tie;
    d.max_elongation = std::max(d.max_elongation, x.max_elongation);
    d.levels.push_back(lr);
  }
  d.d_star = run.d_star;
  d.collapse = run.collapse || !succeeded(run.result);
  d.failed = !succeeded(run.result);
  return d;
}

}  // namespace

bool every_kinematic_check_satisfied(const KinematicCaseResult& r) {
  // The code in force: the NTC 2018 rows when the case checks NTC 2018 (the
  // NTC 2008 rows are reported for comparison, issue 29), else every row.
  bool has_2018 = false;
  for (const CandidateResult& cr : r.candidates)
    for (const CheckRow& row : cr.checks) has_2018 = has_2018 || row.code == "NTC2018";
  for (const CandidateResult& cr : r.candidates)
    for (const CheckRow& row : cr.checks)
      if ((!has_2018 || row.code == "NTC2018") && (!row.satisfied || row.no_verdict)) return false;
  return true;
}

bool has_ties(const CaseFile& c) { return !c.ties.empty() || !c.new_ties.empty() || c.tie_design.has_value(); }

double zeta_E(const KinematicCaseResult& r, const std::string& method) {
  // The approach's index: the lowest of its checks' own (safety_index.hpp, issue 41).
  const CheckRow* row = lowest_index_check(r, "NTC2018", method == "linear" ? "strength" : "displacement");
  return row ? row->index.zeta : std::numeric_limits<double>::quiet_NaN();
}

TieInterventionResult run_tie_intervention(const CaseFile& c) { return intervention(c, nullptr); }

TieInterventionResult run_tie_intervention(const CaseFile& c, const FacadeAssessment& a) { return intervention(c, &a); }

TieDynamicResult run_tie_dynamics(const FacadeAssessment& a, const TieInterventionResult& t) {
  TieDynamicResult R;
  if (!a.dynamics.spec || !a.dynamics.mechanism || a.dynamics.runs.empty()) {
    R.note = a.dynamics.spec && !a.dynamics.note.empty() && !a.dynamics.applies ? a.dynamics.note
                                                                        : NoteText{{"tie.dyn_none", {}}};
    return R;
  }
  // The façade's analyses are the stato di fatto (its existing ties hold the
  // wall); the stato di progetto is the same model, records and polarities,
  // on the same candidate, with every tie of the intervention.
  const std::size_t g = a.kinematic.governing;
  const MechanismDynamics& md = *a.dynamics.mechanism;
  const CandidateResult& before = t.before.candidates.at(g);
  const CandidateResult& after = t.after.candidates.at(g);
  std::optional<MechanismDynamics> other;
  std::vector<DynamicRun> other_runs;
  if (t.intervention) {
    other = md.with_ties(dynamic_ties(md, after, t.case_after.ties));
    if (!other->applies) {
      R.note = other->note;
      return R;
    }
    if (!other->tied()) {
      R.note = {{"tie.dyn_no_block", {}}};
      return R;
    }
    other_runs = dynamic_runs(a, *other, after.result, false);
  }
  const std::vector<DynamicRun>& runs_after = t.intervention ? other_runs : a.dynamics.runs;
  const MechanismDynamics& md_after = t.intervention ? *other : md;
  if (md.tied())
    for (std::size_t i = 0; i < a.dynamics.runs.size(); ++i) R.runs_before.push_back(tie_run(md, a.dynamics.runs[i], i));
  for (std::size_t i = 0; i < runs_after.size(); ++i) R.runs.push_back(tie_run(md_after, runs_after[i], i));
  const std::vector<RestitutionSummary> sb = summarise_runs(a.dynamics.runs, md.e, before.result);
  const std::vector<RestitutionSummary> sa = summarise_runs(runs_after, md.e, after.result);
  for (std::size_t ie = 0; ie < sa.size(); ++ie) {
    TieDynamicSummary s;
    s.e = sa[ie].e;
    s.records = sa[ie].records;
    s.rule = sa[ie].rule;
    s.overturned_before = sb[ie].overturned;
    s.overturned_after = sa[ie].overturned;
    s.d_demand_before = sb[ie].d_demand;
    s.d_demand_after = sa[ie].d_demand;
    s.d_SLV_before = dynamic_d_SLV(before.result);
    s.d_SLV_after = dynamic_d_SLV(after.result);
    s.collapse_before = sb[ie].any_collapse || sb[ie].failed > 0;
    s.collapse_after = sa[ie].any_collapse || sa[ie].failed > 0;
    s.satisfied_before = sb[ie].slv_satisfied;
    s.satisfied_after = sa[ie].slv_satisfied;
    for (const TieDynamicRun& d : R.runs_before) {
      if (a.dynamics.runs[d.run].restitution != ie) continue;
      s.yielded_before += d.yielded ? 1 : 0;
      s.broken_before += d.broken ? 1 : 0;
    }
    for (const TieDynamicRun& d : R.runs) {
      if (runs_after[d.run].restitution != ie) continue;
      s.yielded_after += d.yielded ? 1 : 0;
      s.broken_after += d.broken ? 1 : 0;
      s.max_plastic_elongation = std::max(s.max_plastic_elongation, d.plastic_elongation);
    }
    R.summaries.push_back(s);
  }
  R.applies = true;
  R.note = {{t.intervention ? "tie.dyn_repeated" : "tie.dyn_existing", {}}};
  return R;
}

std::string describe_change(const TieChange& c) {
  char b[256];
  if (!c.after) return "removed";
  const Tie& t = *c.after;
  std::string anchor;
  if (t.anchor.type == AnchorType::Plate)
    std::snprintf(b, sizeof b, "plate %.0f x %.0f x %.0f mm %s", t.anchor.a * 1e3, t.anchor.b * 1e3, t.anchor.t * 1e3,
                  t.anchor.grade.c_str());
  else
    std::snprintf(b, sizeof b, "bar anchor %.0f mm, diam. %.0f mm %s", t.anchor.a * 1e3, t.anchor.b * 1e3,
                  t.anchor.grade.c_str());
  anchor = b;
  if (c.kind == "anchor") return "new anchor: " + anchor;
  std::snprintf(b, sizeof b, "new rod diam. %.0f mm %s, %s ends M%.0f, ", t.rod.diameter * 1e3, t.rod.grade.c_str(),
                to_string(t.rod.ends), t.rod.thread_diameter * 1e3);
  return b + anchor;
}

std::vector<TieInterventionResult> assess_wall_ties(const std::vector<const FacadeAssessment*>& members,
                                                    const std::vector<std::string>& names) {
  std::vector<const CaseFile*> cases;
  for (const FacadeAssessment* a : members) {
    if (a->dynamics.spec && a->dynamics.spec->options.overturn != OverturnCriterion::theta_u)
      throw InputError(a->kase.file + ": /dynamic/overturn_at: a wall held by tie rods (\"ties\" or \"design\") "
                       "collapses where its net restoring moment with the ties at their strength vanishes; \"half_pi\" "
                       "is not available with ties");
    cases.push_back(&a->kase);
  }
  return run_members(cases, members, names);
}

std::optional<TieInterventionResult> assess_ties(const FacadeAssessment& a) {
  if (!has_ties(a.kase)) return std::nullopt;
  if (a.dynamics.spec && a.dynamics.spec->options.overturn != OverturnCriterion::theta_u)
    throw InputError(a.kase.file + ": /dynamic/overturn_at: a wall held by tie rods (\"ties\" or \"design\") "
                     "collapses where its net restoring moment with the ties at their strength vanishes; \"half_pi\" is "
                     "not available with ties");
  return run_tie_intervention(a.kase, a);
}

}  // namespace assess
