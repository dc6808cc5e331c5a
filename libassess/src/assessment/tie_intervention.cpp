// tie_intervention.cpp: before/after of the ties and the design of the
// smallest commercial rod and plate (docs/theory/ties.md §5).
#include "assess/assessment/tie_intervention.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/support/error.hpp"
#include "assess/support/units.hpp"
#include "support/parallel_for.hpp"

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

// Levels' results on the governing candidate of `after`.
std::vector<TieLevelResult> level_results(const CaseFile& c, const KinematicCaseResult& after,
                                          const std::vector<Tie>& levels, std::size_t first_level) {
  std::vector<TieLevelResult> out;
  const CandidateResult& cr = after.candidates[after.governing];
  const Chain& chain = c.mechanism.candidates[after.governing].chain;
  const std::vector<TieRestraint> ties = case_tie_restraints(c, chain);
  const CheckInput in = check_input(c, after, cr);
  // The largest displacement demand d* among the displacement checks (m).
  double d_demand = -1.0;
  for (const CheckRow& row : cr.checks)
    if (row.kind == "displacement") d_demand = std::max(d_demand, row.demand);
  std::vector<double> elong;
  if (d_demand >= 0.0 && cr.result.curve_complete()) elong = tie_elongations_at(chain, cr.result, ties, d_demand);
  for (std::size_t i = 0; i < levels.size(); ++i) {
    TieLevelResult L;
    L.tie = levels[i];
    L.resistance = tie_resistance(L.tie);
    // Index of this level among the candidate's restraints (levels not on it are skipped).
    std::size_t k = 0, found = ties.size();
    for (std::size_t j = 0; j < c.ties.size(); ++j) {
      const int b = tie_block(chain, c.ties[j].block, c.ties[j].point);
      if (b < 0) continue;
      if (j == first_level + i) found = k;
      ++k;
    }
    if (found < ties.size()) {
      L.count = ties[found].count;
      KinematicOptions opt = c.options;  // issue 33: the candidate's own bound on its rotation, as in run_kinematic_case
      opt.rotation_cap = c.mechanism.candidates[after.governing].rotation_bound;
      L.required = required_tie_forces(chain, opt, in, ties, found, L.tie.spacing);
      for (const RequiredTieForce& f : L.required) L.N_Ed = std::max(L.N_Ed, f.per_tie);
      if (found < elong.size() && std::isfinite(elong[found])) L.elongation_demand = std::max(0.0, elong[found]);
    }
    L.checks = tie_checks(L.tie, L.N_Ed, L.elongation_demand);
    L.satisfied = std::all_of(L.checks.begin(), L.checks.end(), [](const TieCheckRow& r) { return r.satisfied; });
    out.push_back(L);
  }
  return out;
}

}  // namespace

bool every_kinematic_check_satisfied(const KinematicCaseResult& r) {
  for (const CandidateResult& cr : r.candidates)
    for (const CheckRow& row : cr.checks)
      if (!row.satisfied || row.no_verdict) return false;
  return true;
}

bool has_ties(const CaseFile& c) { return !c.ties.empty() || c.tie_design.has_value(); }

double zeta_E(const KinematicCaseResult& r, const std::string& method) {
  const std::string kind = method == "linear" ? "strength" : "displacement";
  double z = std::numeric_limits<double>::infinity();
  bool any = false;
  for (const CandidateResult& cr : r.candidates)
    for (const CheckRow& row : cr.checks)
      if (row.code == "NTC2018" && row.has_pga && row.kind == kind && row.limit_state != "SLD") {
        any = true;
        z = std::min(z, row.ag_capacity_g / row.ag_demand_g);
      }
  return any ? z : std::numeric_limits<double>::quiet_NaN();
}

TieInterventionResult run_tie_intervention(const CaseFile& c) {
  if (!c.site) throw InputError(c.file + ": /site: missing: the ties are designed and checked against the site's hazard");
  TieInterventionResult R;
  R.designed = c.tie_design.has_value();
  R.case_before = c;
  R.case_before.tie_design.reset();
  if (!R.designed) R.case_before.ties.clear();
  R.before = run_kinematic_case(R.case_before);
  R.passes_before = every_kinematic_check_satisfied(R.before);
  R.zetaE_before = zeta_E(R.before, c.method);

  if (!R.designed) {
    R.case_after = R.case_before;
    R.case_after.ties = c.ties;
    R.after = run_kinematic_case(R.case_after);
    R.levels = level_results(R.case_after, R.after, c.ties, 0);
  } else {
    // Smallest rod first (then grade, then plate); the first combination with
    // every check of the mechanism and of the ties satisfied. For one rod and
    // grade the design strength grows with the plate (bearing, punching and
    // bending all grow with its side and thickness): the largest plate is tried
    // first (if it fails, so do the others), then the smallest passing plate is
    // found by bisection on the cheap criterion (every check of the mechanism
    // and the rods' elongation), and confirmed with the full checks of the ties
    // (required forces), scanning upwards if needed.
    const std::size_t first = c.ties.size();
    auto trial_of = [&](double d, const std::string& grade, const tie_catalogue::Plate& p, std::vector<Tie>& levels) {
      CaseFile trial = R.case_before;
      levels = c.tie_design->levels;
      for (Tie& t : levels) {
        t.rod.diameter = d;
        t.rod.area = units::pi * d * d / 4.0;
        t.rod.grade = grade;
        t.rod.fyk = tie_catalogue::find_grade(grade)->fyk;
        t.rod.gamma_M0 = tie_catalogue::gamma_M0;
        t.rod.E = tie_catalogue::steel_E;
        t.anchor.type = AnchorType::Plate;
        t.anchor.a = t.anchor.b = p.a;
        t.anchor.t = p.t;
        t.anchor.grade = grade == "B450C" ? "S275" : grade;
        t.anchor.fyk = tie_catalogue::find_grade(t.anchor.grade)->fyk;
        trial.ties.push_back(t);
      }
      return trial;
    };
    // Every check of the mechanism, and each designed rod's elongation at the
    // largest displacement demand of the governing candidate within eps_ud L.
    auto cheap_pass = [&](const CaseFile& trial, const KinematicCaseResult& after) {
      if (!every_kinematic_check_satisfied(after)) return false;
      const CandidateResult& cr = after.candidates[after.governing];
      const Chain& chain = trial.mechanism.candidates[after.governing].chain;
      double d_demand = -1.0;
      for (const CheckRow& row : cr.checks)
        if (row.kind == "displacement") d_demand = std::max(d_demand, row.demand);
      if (d_demand < 0.0 || !cr.result.curve_complete()) return true;
      const std::vector<TieRestraint> ties = case_tie_restraints(trial, chain);
      const std::vector<double> e = tie_elongations_at(chain, cr.result, ties, d_demand);
      for (std::size_t j = 0; j < ties.size() && j < e.size(); ++j)
        for (std::size_t i = first; i < trial.ties.size(); ++i)
          if (trial.ties[i].name == ties[j].name && !(e[j] <= tie_resistance(trial.ties[i]).ultimate_elongation))
            return false;
      return true;
    };
    bool done = false;
    const std::size_t np = tie_catalogue::plates.size();
    for (double d : tie_catalogue::rod_diameters) {
      for (const std::string& grade : c.tie_design->grades) {
        auto passes = [&](std::size_t ip) {
          std::vector<Tie> levels;
          const CaseFile trial = trial_of(d, grade, tie_catalogue::plates[ip], levels);
          ++R.tried;
          return cheap_pass(trial, run_kinematic_case(trial));
        };
        if (!passes(np - 1)) continue;
        std::size_t lo = 0, hi = np - 1;  // hi passes
        if (passes(0)) hi = 0;
        while (hi > lo + 1 && hi > 0) {
          const std::size_t mid = (lo + hi) / 2;
          (passes(mid) ? hi : lo) = mid;
        }
        for (std::size_t ip = hi; ip < np && !done; ++ip) {
          std::vector<Tie> levels;
          const CaseFile trial = trial_of(d, grade, tie_catalogue::plates[ip], levels);
          ++R.tried;
          KinematicCaseResult after = run_kinematic_case(trial);
          if (!cheap_pass(trial, after)) continue;
          std::vector<TieLevelResult> lv = level_results(trial, after, levels, first);
          if (!std::all_of(lv.begin(), lv.end(), [](const TieLevelResult& l) { return l.satisfied; })) continue;
          R.case_after = trial;
          R.after = std::move(after);
          R.levels = std::move(lv);
          done = true;
        }
        if (done) break;
      }
      if (done) break;
    }
    R.found = done;
    if (!done) {
      R.message = "no rod of 12-40 mm with a plate of the list (150-700 mm) makes every check pass: the masonry "
                  "behind the anchor or the rod's elongation governs; add tie levels, reduce the spacing or "
                  "consider another intervention";
      // Report the largest combination, so that the reader sees how far it is.
      CaseFile trial = R.case_before;
      std::vector<Tie> levels = c.tie_design->levels;
      for (Tie& t : levels) {
        const double d = tie_catalogue::rod_diameters.back();
        const std::string& grade = c.tie_design->grades.back();
        t.rod.diameter = d;
        t.rod.area = units::pi * d * d / 4.0;
        t.rod.grade = grade;
        t.rod.fyk = tie_catalogue::find_grade(grade)->fyk;
        t.anchor.a = t.anchor.b = tie_catalogue::plates.back().a;
        t.anchor.t = tie_catalogue::plates.back().t;
        t.anchor.grade = grade == "B450C" ? "S275" : grade;
        t.anchor.fyk = tie_catalogue::find_grade(t.anchor.grade)->fyk;
        trial.ties.push_back(t);
      }
      R.case_after = trial;
      R.after = run_kinematic_case(trial);
      R.levels = level_results(trial, R.after, levels, first);
    }
  }
  R.passes_after = every_kinematic_check_satisfied(R.after) &&
                   std::all_of(R.levels.begin(), R.levels.end(), [](const TieLevelResult& l) { return l.satisfied; });
  R.zetaE_after = zeta_E(R.after, c.method);
  return R;
}

}  // namespace assess

// ---- dynamics with the ties (docs/theory/ties.md §6) ------------------------

namespace assess {

namespace {

// One tied analysis as the ties section reports it: over the levels, the
// largest force per tie, elongation and permanent set; the energy dissipated
// by one tie of each level, summed.
TieDynamicRun tie_run(const MechanismDynamics& md, const DynamicRun& run, std::size_t i) {
  TieDynamicRun d;
  d.run = i;
  d.theta_max = run.result.theta_max;
  d.theta_collapse = run.result.theta_u;
  d.overturned = run.result.overturned;
  for (std::size_t l = 0; l < run.result.ties.size() && l < md.ties.size(); ++l) {
    const TiedLevelResult& x = run.result.ties[l];
    d.yielded = d.yielded || x.yielded;
    d.max_force = std::max(d.max_force, x.max_force * md.ties[l].per_tie);
    d.plastic_elongation = std::max(d.plastic_elongation, x.plastic_elongation);
    d.plastic_energy += x.plastic_energy * md.ties[l].per_tie;
    d.max_elongation = std::max(d.max_elongation, x.max_elongation);
  }
  d.ruptured = run.ruptured;
  d.d_star = run.d_star;
  d.collapse = run.collapse || !succeeded(run.result);
  d.failed = !succeeded(run.result);
  return d;
}

}  // namespace

TieDynamicResult run_tie_dynamics(const FacadeAssessment& a, const TieInterventionResult& t) {
  TieDynamicResult R;
  if (!a.dynamic || !a.mechanism_dynamics || a.runs.empty()) {
    R.note = a.dynamic && !a.dynamic_note.empty() && !a.dynamic_applies ? a.dynamic_note
                                                                        : "no dynamic analysis in the case";
    return R;
  }
  // The façade's analyses are those of its case: with the given ties, if any.
  // The other side (for given ties, the wall without them; for a design, the
  // wall with the designed levels) is the same model, records and polarities,
  // on the same candidate, with the other tie levels.
  const std::size_t g = a.kinematic.governing;
  const MechanismDynamics& md = *a.mechanism_dynamics;
  const CandidateResult& before = t.before.candidates.at(g);
  const CandidateResult& after = t.after.candidates.at(g);
  const MechanismDynamics other =
      t.designed ? md.with_ties(dynamic_ties(md, after, t.case_after.ties)) : md.with_ties({});
  if (!other.applies) {
    R.note = other.note;
    return R;
  }
  if (t.designed && !other.tied()) {
    R.note = "the designed ties hold no block of the mechanism analysed dynamically";
    return R;
  }
  const std::vector<DynamicRun> other_runs = dynamic_runs(a, other, (t.designed ? after : before).result, false);
  const std::vector<DynamicRun>& runs_before = t.designed ? a.runs : other_runs;
  const std::vector<DynamicRun>& runs_after = t.designed ? other_runs : a.runs;
  const MechanismDynamics& md_after = t.designed ? other : md;
  for (std::size_t i = 0; i < runs_after.size(); ++i) R.runs.push_back(tie_run(md_after, runs_after[i], i));
  const std::vector<RestitutionSummary> sb = summarise_runs(runs_before, md.e, before.result);
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
    s.d_SLV_before = before.result.d_SLV;
    s.d_SLV_after = after.result.d_SLV;
    s.collapse_before = sb[ie].any_collapse || sb[ie].failed > 0;
    s.collapse_after = sa[ie].any_collapse || sa[ie].failed > 0;
    s.satisfied_before = sb[ie].slv_satisfied;
    s.satisfied_after = sa[ie].slv_satisfied;
    s.ruptured = sa[ie].ruptured;
    for (const TieDynamicRun& d : R.runs) {
      if (runs_after[d.run].restitution != ie) continue;
      s.yielded += d.yielded ? 1 : 0;
      s.max_plastic_elongation = std::max(s.max_plastic_elongation, d.plastic_elongation);
    }
    R.summaries.push_back(s);
  }
  R.applies = true;
  R.note = t.designed ? "the façade's analyses repeated with the designed ties as one-sided elastic-perfectly-plastic "
                        "restraints"
                      : "the façade's analyses are those of the wall with its ties (one-sided elastic-perfectly-plastic "
                        "restraints); before: the same analyses without them";
  return R;
}

std::optional<TieInterventionResult> assess_ties(const FacadeAssessment& a) {
  if (!has_ties(a.kase)) return std::nullopt;
  TieInterventionResult t = run_tie_intervention(a.kase);
  t.dynamics = run_tie_dynamics(a, t);
  return t;
}

}  // namespace assess
