// tie_intervention.cpp: before/after of the ties and the design of the
// smallest commercial rod and plate (docs/theory/ties.md §5).
#include "assess/assessment/tie_intervention.hpp"

#include "assess/dynamics/tied_rocking.hpp"
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

bool all_pass(const KinematicCaseResult& r) {
  for (const CandidateResult& cr : r.candidates)
    for (const CheckRow& row : cr.checks)
      if (!row.satisfied || row.no_verdict) return false;
  return true;
}

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
      L.required = required_tie_forces(chain, c.options, in, ties, found, L.tie.spacing);
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
  R.passes_before = all_pass(R.before);
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
      if (!all_pass(after)) return false;
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
  R.passes_after = all_pass(R.after) &&
                   std::all_of(R.levels.begin(), R.levels.end(), [](const TieLevelResult& l) { return l.satisfied; });
  R.zetaE_after = zeta_E(R.after, c.method);
  return R;
}

}  // namespace assess

// ---- dynamics with the ties (docs/theory/ties.md §6) ------------------------

namespace assess {

TieDynamicResult run_tie_dynamics(const FacadeAssessment& a, const TieInterventionResult& t) {
  TieDynamicResult R;
  if (!a.dynamic || !a.mechanism_dynamics || a.runs.empty()) {
    R.note = "no dynamic analysis in the case";
    return R;
  }
  const MechanismDynamics& md = *a.mechanism_dynamics;
  const CandidateResult& after = t.after.candidates[t.after.governing];
  if (md.sidedness != Sidedness::one_sided || (!md.single_body() && !md.chain)) {
    R.note = "the tied dynamic analysis covers one-sided rocking (a body or a chain)";
    return R;
  }
  if (after.result.ties.empty() || t.after.governing != a.kinematic.governing) {
    R.note = "the tied dynamic analysis needs the ties on the mechanism analysed dynamically";
    return R;
  }
  if (a.base_motions.size() != a.records.size()) {
    R.note = "the base motions of the records are not available";
    return R;
  }
  // Every level: one body per unit depth of wall, a chain the whole level;
  // per_tie[i] turns the analysis' forces and energies into those of one tie;
  // e_u[i] is the rod's ultimate elongation eps_ud L (tie_checks).
  std::vector<TieRestraint> levels;
  std::vector<RockingTie> body_ties;
  std::vector<double> per_tie, e_u;
  for (const TieWork& w : after.result.ties) {
    const TieRestraint& r = w.tie;
    levels.push_back(r);
    double f = r.count > 0.0 ? 1.0 / r.count : 0.0;
    if (md.single_body()) {
      const ChainRockingBody& body = *md.body;
      RockingTie tie;
      tie.point = r.point - body.hinge;
      tie.direction = r.direction;
      tie.stiffness = r.stiffness / body.length;
      tie.capacity = r.capacity / body.length;
      tie.pretension = std::min(r.pretension, r.capacity) / body.length;
      body_ties.push_back(tie);
      f *= body.length;
    }
    per_tie.push_back(f);
    double eu = std::numeric_limits<double>::infinity();
    for (const TieLevelResult& L : t.levels)
      if (L.tie.name == r.name) eu = L.resistance.ultimate_elongation;
    e_u.push_back(eu);
  }
  const KinematicResult& kin = after.result;
  R.runs.resize(a.runs.size());
  detail::parallel_for(a.runs.size(), [&](std::size_t i) {
    const DynamicRun& run = a.runs[i];
    const Record& rec = a.base_motions[run.record];
    const double f = a.records[run.record].scale * (run.reversed ? -1.0 : 1.0);
    std::vector<double> ug;
    ug.reserve(rec.acc.size() + static_cast<std::size_t>(a.free_tail_s / rec.dt) + 1);
    for (double v : rec.acc) ug.push_back(f * v);
    for (double s = 0.0; s < a.free_tail_s; s += rec.dt) ug.push_back(0.0);
    HybridOdeOptions o;
    o.rel_tol = a.dynamic->options.rel_tol;
    o.abs_tol = a.dynamic->options.abs_tol;
    const TiedRockingResult tr =
        md.single_body() ? analyse_tied_rocking(md.rocking[run.restitution], body_ties, ug, rec.dt, 1e300, false, o)
                         : analyse_tied_chain(*md.chain, levels, md.e[run.restitution], ug, rec.dt, 1e300, false, o);
    TieDynamicRun& d = R.runs[i];
    d.run = i;
    d.theta_max = tr.theta_max;
    d.theta_collapse = tr.theta_collapse;
    d.overturned = tr.overturned;
    d.yielded = tr.yielded;
    // Over the levels: the largest force per tie, elongation and permanent
    // set; the energy dissipated by one tie of each level, summed.
    for (std::size_t l = 0; l < tr.levels.size(); ++l) {
      const TiedLevelResult& x = tr.levels[l];
      d.max_force = std::max(d.max_force, x.max_force * per_tie[l]);
      d.plastic_elongation = std::max(d.plastic_elongation, x.plastic_elongation);
      d.plastic_energy += x.plastic_energy * per_tie[l];
      d.max_elongation = std::max(d.max_elongation, x.max_elongation);
      d.ruptured = d.ruptured || x.max_elongation > e_u[l];
    }
    d.failed = !(tr.termination == HybridTermination::completed || tr.termination == HybridTermination::finished ||
                 tr.termination == HybridTermination::stopped_by_event);
    const double dc = md.control_displacement(kin, tr.theta_max);
    d.d_star = dc * kin.d_star_per_dk;
    d.collapse = d.overturned || d.ruptured || dc >= kin.dk0 || d.failed;
  });
  // Per restitution value: the rule of NTC 2018 §7.3.5 on the envelope of the polarities.
  // Before: the façade's runs (never with ties) against the mechanism without
  // the ties of `t` (the façade's kinematic part has the case's given ties).
  const KinematicResult& kin_before = t.before.candidates[t.before.governing].result;
  for (const RestitutionSummary& s0 : a.summaries) {
    TieDynamicSummary s;
    s.e = s0.e;
    s.records = s0.records;
    s.rule = s0.rule;
    s.overturned_before = s0.overturned;
    s.d_SLV_before = kin_before.d_SLV;
    std::map<std::size_t, double> env0;
    bool failed0 = false;
    for (const DynamicRun& run : a.runs) {
      if (run.restitution != s0.restitution) continue;
      failed0 = failed0 || !(run.result.termination == RockingTermination::completed ||
                             run.result.termination == RockingTermination::overturned);
      s.collapse_before = s.collapse_before || run.result.overturned || run.d_control >= kin_before.dk0;
      env0[run.record] = std::max(env0[run.record], run.d_star);
    }
    double mean0 = 0.0, mx0 = 0.0;
    for (const auto& kv : env0) {
      mean0 += kv.second / double(env0.size());
      mx0 = std::max(mx0, kv.second);
    }
    s.d_demand_before = s.rule == "mean" ? mean0 : mx0;
    s.collapse_before = s.collapse_before || failed0;
    s.satisfied_before = s.rule != "none" && !s.collapse_before && s.d_demand_before <= s.d_SLV_before;
    s.d_SLV_after = kin.d_SLV;
    std::map<std::size_t, double> env;
    for (const TieDynamicRun& d : R.runs) {
      const DynamicRun& run = a.runs[d.run];
      if (run.restitution != s0.restitution) continue;
      s.overturned_after += d.overturned ? 1 : 0;
      s.collapse_after = s.collapse_after || d.collapse;
      s.yielded += d.yielded ? 1 : 0;
      s.ruptured += d.ruptured ? 1 : 0;
      s.max_plastic_elongation = std::max(s.max_plastic_elongation, d.plastic_elongation);
      env[run.record] = std::max(env[run.record], d.d_star);
    }
    double mean = 0.0, mx = 0.0;
    for (const auto& kv : env) {
      mean += kv.second / double(env.size());
      mx = std::max(mx, kv.second);
    }
    s.d_demand_after = s.rule == "mean" ? mean : mx;
    s.satisfied_after = s.rule != "none" && !s.collapse_after && s.d_demand_after <= s.d_SLV_after;
    R.summaries.push_back(s);
  }
  R.applies = true;
  R.note = "the façade's analyses repeated with the tie as a one-sided elastic-perfectly-plastic restraint";
  return R;
}

void apply_given_ties_to_dynamic_checks(FacadeAssessment& a, const TieInterventionResult& t) {
  if (t.designed) return;
  const std::string gov = a.kinematic.candidates[a.kinematic.governing].label;
  bool changed = false;
  std::size_t k = 0;  // the governing candidate's dynamic rows, one per restitution value, in order
  for (CheckRow& r : a.checks) {
    if (r.kind != "dynamic") continue;
    changed = true;
    if (r.candidate == gov && t.dynamics.applies && k < t.dynamics.summaries.size()) {
      const TieDynamicSummary& x = t.dynamics.summaries[k++];
      r.demand = x.d_demand_after;
      r.capacity = x.d_SLV_after;
      r.dc = x.d_SLV_after > 0.0 ? x.d_demand_after / x.d_SLV_after : std::numeric_limits<double>::infinity();
      r.satisfied = x.satisfied_after;
      r.no_verdict = x.rule == "none" && !x.collapse_after && x.satisfied_after;
      if (r.no_verdict) r.satisfied = false;
      r.clause += ", with the ties (tied one-sided rocking, issue 23)";
      r.note = std::string(x.collapse_after ? "collapse with the ties" : "no collapse with the ties") +
               " (overturned in " + std::to_string(x.overturned_after) + "); rod yielded in " +
               std::to_string(x.yielded) + ", broke in " + std::to_string(x.ruptured) + " analyses; " +
               std::to_string(x.records) + " records: " + x.rule;
      continue;
    }
    r.satisfied = false;
    r.no_verdict = true;
    r.note = r.candidate == gov ? "no verdict: the case has ties and the tied dynamic analysis does not apply (" +
                                      t.dynamics.note + "); the analysis without the ties is not a check of the tied wall"
                                : "no verdict: analysed without the ties, which the case gives (the tied dynamic "
                                  "analysis covers the governing candidate only)";
  }
  if (!changed) return;
  update_verdict(a);
  a.warnings.push_back(a.kase.file + ": /ties: the case gives tie rods: the dynamic check rows use the analyses with "
                       "the ties (tied one-sided rocking); the analyses and histories listed in the dynamic section are "
                       "those without the ties (before), shown for comparison");
}

std::optional<TieInterventionResult> assess_ties(FacadeAssessment& a) {
  if (!has_ties(a.kase)) return std::nullopt;
  TieInterventionResult t = run_tie_intervention(a.kase);
  t.dynamics = run_tie_dynamics(a, t);
  apply_given_ties_to_dynamic_checks(a, t);
  return t;
}

}  // namespace assess
