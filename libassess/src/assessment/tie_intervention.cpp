// tie_intervention.cpp: the stato di fatto and the stato di progetto of the
// tie rods, and the design of the smallest commercial rod and plate
// (docs/theory/ties.md §5, §6).
#include "assess/assessment/tie_intervention.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>

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
std::vector<TieLevelResult> level_results(const CaseFile& c, const KinematicCaseResult& r, std::size_t first,
                                          std::size_t last, const std::map<std::string, LevelDynamics>* dyn,
                                          bool required = true) {
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
  if (d_demand >= 0.0 && cr.result.curve_complete()) elong = tie_elongations_at(chain, cr.result, ties, d_demand);
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
// ISO thread up to max_upset_ratio d that satisfies the capacity design (upset).
const tie_catalogue::Thread* design_thread(double d, const tie_catalogue::SteelGrade& g, TieEnds ends) {
  namespace C = tie_catalogue;
  if (ends == TieEnds::Threaded) return C::find_thread(d);
  const double A = units::pi * d * d / 4.0;
  for (const C::Thread& t : C::threads)
    if (t.d >= d - 1e-4 && t.d <= C::max_upset_ratio * d + 1e-4 &&
        C::thread_k2 * g.ftk * t.As / C::gamma_M2 >= C::gamma_Rd * C::gamma_ov * A * g.fyk)
      return &t;
  return nullptr;
}

// The designed levels with rod (d, grade, ends) and plate p; nullopt when the
// combination cannot be built (no thread, a plate no wider than its nut, a
// pretension at or above the tie's strength).
std::optional<std::vector<Tie>> designed_levels(const TieDesignSpec& spec, double d, const std::string& grade,
                                                const tie_catalogue::Plate& p) {
  namespace C = tie_catalogue;
  const C::SteelGrade& g = *C::find_grade(grade);
  const C::Thread* th = design_thread(d, g, spec.ends);
  if (!th) return std::nullopt;
  std::vector<Tie> levels = spec.levels;
  for (Tie& t : levels) {
    t.existing = false;
    t.rod.diameter = d;
    t.rod.area = units::pi * d * d / 4.0;
    t.rod.grade = grade;
    t.rod.fyk = g.fyk;
    t.rod.ftk = g.ftk;
    t.rod.elongation = g.elongation;
    t.rod.gamma_M0 = C::gamma_M0;
    t.rod.E = C::steel_E;
    t.rod.ends = spec.ends;
    t.rod.thread_diameter = th->d;
    t.rod.thread_area = th->As;
    t.rod.nut_width = th->s;
    t.anchor.type = AnchorType::Plate;
    t.anchor.a = t.anchor.b = p.a;
    t.anchor.t = p.t;
    t.anchor.grade = grade == "B450C" ? "S275" : grade;
    t.anchor.fyk = C::find_grade(t.anchor.grade)->fyk;
    try {
      (void)tie_resistance(t);
    } catch (const InputError&) {
      return std::nullopt;
    }
  }
  return levels;
}

// The stato di progetto's dynamics of a trial, and whether the design may
// stop: no level broken in any analysis and every dynamic check satisfied.
struct DynamicVerdict {
  bool ok = true;
  bool plate_may_help = false;  // a broken masonry or plate component: a larger plate may hold
};
DynamicVerdict dynamic_verdict(const TieDynamicResult& d) {
  DynamicVerdict v;
  if (!d.applies) return v;
  for (const TieDynamicRun& r : d.runs)
    for (const TieLevelRun& l : r.levels)
      if (l.broken) {
        v.ok = false;
        v.plate_may_help = v.plate_may_help || l.component == "bearing" || l.component == "punching" ||
                           l.component == "anchor bending";
      }
  for (const TieDynamicSummary& s : d.summaries) v.ok = v.ok && s.satisfied_after;
  return v;
}

TieInterventionResult intervention(const CaseFile& c, const FacadeAssessment* a) {
  if (!c.site) throw InputError(c.file + ": /site: missing: the ties are designed and checked against the site's hazard");
  TieInterventionResult R;
  R.designed = c.tie_design.has_value();
  R.intervention = R.designed || !c.new_ties.empty();
  // Stato di fatto: the case as read (its existing ties act), no intervention.
  R.case_before = c;
  R.case_before.tie_design.reset();
  R.case_before.new_ties.clear();
  R.before = run_kinematic_case(R.case_before);
  R.zetaE_before = zeta_E(R.before, c.method);
  const std::size_t n_existing = c.ties.size();

  // The dynamics of a state (after): the façade's model with its levels.
  auto state_dynamics = [&](TieInterventionResult& T) {
    if (a) T.dynamics = run_tie_dynamics(*a, T);
  };
  auto dyn_of = [](const std::vector<TieDynamicRun>& runs, bool applies) {
    return applies ? std::optional<std::map<std::string, LevelDynamics>>(level_dynamics(runs)) : std::nullopt;
  };

  if (!R.designed) {
    R.case_after = R.case_before;
    for (const Tie& t : c.new_ties) R.case_after.ties.push_back(t);
    R.after = R.intervention ? run_kinematic_case(R.case_after) : R.before;
    state_dynamics(R);
  } else {
    const TieDesignSpec& spec = *c.tie_design;
    // Smallest rod first (from the minimum diameter), then grade, then plate
    // (smallest first): the first combination with every check of the
    // mechanism and of the ties satisfied, whose ties are ductile or stay
    // elastic, and, with a dynamic section, break in no analysis with every
    // dynamic check satisfied. A broken thread or rod is not helped by a
    // larger plate: the next rod is tried.
    bool done = false;
    // Why the combinations were rejected (for the message when none passes),
    // and the one that came closest (the furthest stage, then the smallest D/C).
    int n_layout = 0, n_kinematic = 0, n_checks = 0, n_broken = 0, n_dynamic = 0;
    std::map<std::string, int> broken_by;
    std::optional<TieInterventionResult> closest;
    std::pair<int, double> closest_score{-1, 0.0};
    auto consider = [&](TieInterventionResult& T, int stage) {
      double worst = 0.0;
      for (const CandidateResult& cr : T.after.candidates)
        for (const CheckRow& row : cr.checks)
          if (counts(c, row.code)) worst = std::max(worst, std::isfinite(row.dc) ? row.dc : 1e300);
      const std::pair<int, double> score{stage, -worst};
      if (score > closest_score) {
        closest_score = score;
        closest = std::move(T);
      }
    };
    // A plate whose masonry (local compression, punching) limits the tie and
    // fails is not helped by a larger rod (the same strength, a stiffer tie).
    std::vector<char> dead(tie_catalogue::plates.size(), 0);
    for (double d : tie_catalogue::rod_diameters) {
      if (d < spec.min_rod_diameter - 1e-6) continue;
      for (const std::string& grade : spec.grades) {
        for (std::size_t ip = 0; ip < tie_catalogue::plates.size(); ++ip) {
          if (dead[ip]) continue;
          const tie_catalogue::Plate& p = tie_catalogue::plates[ip];
          const std::optional<std::vector<Tie>> levels = designed_levels(spec, d, grade, p);
          if (!levels) continue;
          ++R.tried;
          const TieResistance res = tie_resistance(levels->front());
          const bool masonry = res.governing == "bearing" || res.governing == "punching";
          TieTrial trial{d, grade, levels->front().rod.thread_diameter, p.a, p.t, res.design, res.governing,
                         res.ductile, "", ""};
          auto log = [&](const char* outcome, const std::string& component = "") {
            trial.outcome = outcome;
            trial.component = component;
            R.trials.push_back(trial);
          };
          TieInterventionResult T;
          T.designed = T.intervention = true;
          T.case_before = R.case_before;
          T.before = R.before;
          T.case_after = R.case_before;
          for (const Tie& t : c.new_ties) T.case_after.ties.push_back(t);  // given new ties, if any
          for (const Tie& t : *levels) T.case_after.ties.push_back(t);
          // The layout first (no analysis needed), then the mechanism's checks.
          bool layout = true;
          for (const Tie& t : *levels)
            for (const TieCheckRow& row : tie_checks(t, TieDemand{}))
              if ((row.check == "cone spacing" || row.check == "edge distance") && !row.satisfied) layout = false;
          if (!layout) {  // the layout does not depend on the rod: this plate is out for good
            ++n_layout;
            log("layout");
            dead[ip] = 1;
            continue;
          }
          T.after = run_kinematic_case(T.case_after);
          if (!every_kinematic_check_satisfied(T.after)) {
            ++n_kinematic;
            log("mechanism");
            if (masonry) dead[ip] = 1;
            consider(T, 1);
            if (res.governing == "rod" || res.governing == "thread") break;  // a larger plate gives the same T_Rd
            continue;
          }
          T.levels = level_results(T.case_after, T.after, n_existing, T.case_after.ties.size(), nullptr, false);
          if (!all_satisfied(T.levels)) {
            ++n_checks;
            log("tie");
            if (masonry) dead[ip] = 1;
            consider(T, 2);
            // The same T_Rd with a larger plate, and no ductility to gain from one (the thread's is fixed).
            if ((res.governing == "rod" || res.governing == "thread") && (res.ductile || res.thread < res.hierarchy_demand))
              break;
            continue;
          }
          state_dynamics(T);
          const DynamicVerdict v = dynamic_verdict(T.dynamics);
          if (!v.ok) {
            bool broke = false;
            std::string comp;
            for (const TieDynamicRun& r : T.dynamics.runs)
              for (const TieLevelRun& l : r.levels)
                if (l.broken && !broke) {
                  broke = true;
                  comp = l.component;
                  ++broken_by[l.component];
                }
            ++(broke ? n_broken : n_dynamic);
            log(broke ? "broken" : "dynamic", comp);
            if (masonry) dead[ip] = 1;
            consider(T, 3);
            if (v.plate_may_help) continue;
            break;  // the thread, the rod or the wall itself: the next rod or grade
          }
          log("accepted");
          R.case_after = std::move(T.case_after);
          R.after = std::move(T.after);
          R.dynamics = std::move(T.dynamics);
          done = true;
          break;
        }
        if (done) break;
      }
      if (done) break;
    }
    R.found = done;
    if (!done) {
      std::string why;
      auto add = [&](int n, const std::string& what) {
        if (n > 0) why += (why.empty() ? "" : "; ") + std::to_string(n) + " " + what;
      };
      add(n_layout, "with the punching wedges of adjacent ties overlapping or beyond the wall's ends");
      add(n_kinematic, "with a check of the mechanism not satisfied");
      add(n_checks, "with a check of the tie not satisfied (it would not stay elastic at the displacement demand)");
      std::string comps;
      for (const auto& [k, n] : broken_by) comps += (comps.empty() ? "" : ", ") + k + " " + std::to_string(n);
      add(n_broken, "with the tie broken in a dynamic analysis (" + comps + ")");
      add(n_dynamic, "with the dynamic check not satisfied");
      R.message = "no rod of the list (from " + std::to_string(static_cast<int>(std::lround(spec.min_rod_diameter * 1e3))) +
                  " mm) with a plate of the list makes every check pass with a tie that is ductile or stays elastic in "
                  "every analysis (" + std::to_string(R.tried) + " combinations: " + (why.empty() ? "none buildable" : why) +
                  "); add ties along the wall or tie levels, use upset ends, or consider another intervention";
      // Show the combination that came closest, so that the reader sees how far it is.
      if (closest) {
        R.case_after = std::move(closest->case_after);
        R.after = std::move(closest->after);
        R.dynamics = std::move(closest->dynamics);
      } else {
        R.case_after = R.case_before;
        for (const Tie& t : c.new_ties) R.case_after.ties.push_back(t);
        R.after = run_kinematic_case(R.case_after);
        state_dynamics(R);
      }
    }
  }
  // Each state's levels, with the dynamics of that state.
  const auto dyn_before = dyn_of(R.dynamics.runs_before, R.dynamics.applies);
  const auto dyn_after = dyn_of(R.dynamics.runs, R.dynamics.applies);
  R.levels_before = level_results(R.case_before, R.before, 0, n_existing, dyn_before ? &*dyn_before : nullptr);
  R.levels = R.intervention ? level_results(R.case_after, R.after, 0, R.case_after.ties.size(),
                                            dyn_after ? &*dyn_after : nullptr)
                            : R.levels_before;
  R.passes_before = every_kinematic_check_satisfied(R.before) && all_satisfied(R.levels_before);
  R.passes_after = every_kinematic_check_satisfied(R.after) && all_satisfied(R.levels);
  R.zetaE_after = R.intervention ? zeta_E(R.after, c.method) : R.zetaE_before;
  if (R.designed) {
    bool ductile = true;
    for (const TieLevelResult& l : R.levels)
      if (!l.tie.existing) ductile = ductile && l.resistance.ductile;
    R.regime = ductile ? "ductile" : "elastic";
  }
  return R;
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
  if (!a.dynamic || !a.mechanism_dynamics || a.runs.empty()) {
    R.note = a.dynamic && !a.dynamic_note.empty() && !a.dynamic_applies ? a.dynamic_note
                                                                        : "no dynamic analysis in the case";
    return R;
  }
  // The façade's analyses are the stato di fatto (its existing ties hold the
  // wall); the stato di progetto is the same model, records and polarities,
  // on the same candidate, with every tie of the intervention.
  const std::size_t g = a.kinematic.governing;
  const MechanismDynamics& md = *a.mechanism_dynamics;
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
      R.note = "the new ties hold no block of the mechanism analysed dynamically";
      return R;
    }
    other_runs = dynamic_runs(a, *other, after.result, false);
  }
  const std::vector<DynamicRun>& runs_after = t.intervention ? other_runs : a.runs;
  const MechanismDynamics& md_after = t.intervention ? *other : md;
  if (md.tied())
    for (std::size_t i = 0; i < a.runs.size(); ++i) R.runs_before.push_back(tie_run(md, a.runs[i], i));
  for (std::size_t i = 0; i < runs_after.size(); ++i) R.runs.push_back(tie_run(md_after, runs_after[i], i));
  const std::vector<RestitutionSummary> sb = summarise_runs(a.runs, md.e, before.result);
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
      if (a.runs[d.run].restitution != ie) continue;
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
  R.note = t.intervention ? "the façade's analyses (the stato di fatto) repeated with the ties of the intervention"
                          : "the façade's analyses are those of the wall with its existing ties";
  return R;
}

std::optional<TieInterventionResult> assess_ties(const FacadeAssessment& a) {
  if (!has_ties(a.kase)) return std::nullopt;
  if (a.dynamic && a.dynamic->options.overturn != OverturnCriterion::theta_u)
    throw InputError(a.kase.file + ": /dynamic/overturn_at: a wall held by tie rods (\"ties\" or \"design\") "
                     "collapses where its net restoring moment with the ties at their strength vanishes; \"half_pi\" is "
                     "not available with ties");
  return run_tie_intervention(a.kase, a);
}

}  // namespace assess
