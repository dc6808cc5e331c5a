// modelling_choices.cpp: the alternatives of the modelling choices (issue 36,
// item 3; docs/theory/facade.md §9), each the same case with one key or one
// reading changed, run again through the same code.
#include "assess/assessment/modelling_choices.hpp"

#include "assess/assessment/facade_assessment.hpp"
#include "assess/assessment/sensitivity.hpp"
#include "assess/kinematic/code_rules.hpp"
#include "assess/support/error.hpp"

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace assess {

namespace {

constexpr double inf = std::numeric_limits<double>::infinity();
const double nan = std::numeric_limits<double>::quiet_NaN();

// The largest D/C of a kinematic method ("linear" or "nonlinear") over every
// candidate's NTC 2018 rows, as the verdict takes it (+inf for a row whose
// D/C is not finite; NaN when the method has no row).
double kinematic_method_dc(const KinematicCaseResult& k, const std::string& method) {
  double dc = -inf;
  for (const CandidateResult& cr : k.candidates)
    for (const CheckRow& r : cr.checks)
      if (r.code == "NTC2018" && method_of_kind(r.kind) == method) dc = std::max(dc, std::isfinite(r.dc) ? r.dc : inf);
  return dc == -inf ? nan : dc;
}

// The dynamic method's D/C with the kinematic results `alt`: the analyses are
// the same (their control displacements); each summary's demand d* and its
// capacity d_SLV follow the alternative candidate's d*/d_k and d_SLV
// (C8.7.1.2.1.9: D/C = d*_demand / d_SLV); a collapse or a failed analysis
// stays +inf. The collapse threshold is the case's (docs/theory/facade.md §9).
double dynamic_dc(const FacadeAssessment& a, const KinematicCaseResult& alt) {
  double dc = -inf;
  auto add = [&](const std::vector<RestitutionSummary>& ss, std::size_t ci) {
    if (ci >= alt.candidates.size() || ci >= a.kinematic.candidates.size()) return;
    const KinematicResult& k0 = a.kinematic.candidates[ci].result;
    const KinematicResult& k1 = alt.candidates[ci].result;
    for (const RestitutionSummary& s : ss) {
      if (s.no_verdict && s.collapsed == 0) continue;
      if (s.collapsed > 0 || s.failed > 0 || !std::isfinite(s.d_demand)) {
        dc = inf;
        continue;
      }
      const double d_slv = dynamic_d_SLV(k1);
      const double demand = s.d_demand * k1.d_star_per_dk / k0.d_star_per_dk;
      dc = std::max(dc, d_slv > 0.0 ? demand / d_slv : inf);
    }
  };
  if (a.dynamics.applies) add(a.dynamics.summaries, a.kinematic.governing);
  for (std::size_t k = 0; k < a.other_dynamics.size(); ++k)
    if (a.other_dynamics[k].dynamics.applies) add(a.other_dynamics[k].dynamics.summaries, a.other_dynamics_candidate[k]);
  return dc == -inf ? nan : dc;
}

Outcome outcome_of_dc(double dc) { return outcome_of(check_satisfied(dc, false), false); }

// The candidate whose check governs the adopted method (its row's candidate), else the governing one.
std::size_t method_candidate(const FacadeAssessment& a, const MethodVerdict& m) {
  if (m.governing >= 0) {
    const std::string& label = a.verdict.rows[std::size_t(m.governing)].candidate;
    for (std::size_t i = 0; i < a.kinematic.candidates.size(); ++i)
      if (a.kinematic.candidates[i].label == label) return i;
  }
  return a.kinematic.governing;
}

struct Builder {
  const FacadeAssessment& a;
  const MethodVerdict& m;
  std::vector<ModellingChoice> out;

  ModellingChoice base(const std::string& key, const std::string& case_key) const {
    ModellingChoice c;
    c.key = key;
    c.case_key = case_key;
    c.method = m.method;
    c.dc = m.max_dc;
    c.outcome = m.outcome();
    return c;
  }
  // The adopted method's D/C with the kinematic results of an alternative case.
  void finish(ModellingChoice& c, const KinematicCaseResult& alt) const {
    c.dc_alternative = m.method == "dynamic" ? dynamic_dc(a, alt) : kinematic_method_dc(alt, m.method);
    c.outcome_alternative = m.undecided() && check_satisfied(c.dc_alternative, false) ? Outcome::no_verdict
                                                                                       : outcome_of_dc(c.dc_alternative);
    if (std::isnan(c.dc_alternative)) c.not_computed = "invalid";
  }
  // The case's document with one change, parsed again: the alternative as the engineer would give it.
  bool reparse(const std::function<void(nlohmann::json&)>& edit, CaseFile& out_case) const {
    if (!a.kase.source.is_object()) return false;
    nlohmann::json doc = a.kase.source;
    edit(doc);
    try {
      out_case = parse_case(doc, a.kase.file);
    } catch (const InputError&) {
      return false;
    }
    return true;
  }
};

// The confidence factor and the readings of the limit state that governs
// (sensitivity.hpp: each value a recomputation of the method's checks): the
// assessment's own sensitivity when it computed one (assess_facade), else
// computed here.
void add_sensitivity(Builder& b) {
  const FacadeAssessment& a = b.a;
  const std::vector<SensitivityRow> sensitivity = a.sensitivity.empty() ? adopted_sensitivity(a) : a.sensitivity;
  for (const SensitivityRow& s : sensitivity) {
    if (s.adopted) continue;
    std::string case_key;
    if (s.parameter == "FC") case_key = a.kase.knowledge_level == "given" ? "/FC" : "/knowledge_level";
    else if (s.parameter == "xi_SLV_pct") case_key = "/analysis/damping_SLV_pct";
    else if (s.parameter == "xi_SLC_pct") case_key = "/analysis/damping_SLC_pct";
    ModellingChoice c = b.base(s.parameter, case_key);
    if (s.parameter == "FC") {
      c.adopted = a.kase.options.FC;
      c.adopted_label = a.kase.knowledge_level == "given" ? "" : a.kase.knowledge_level;
      c.alternative_label = s.value == code_rules::confidence_factor(code_rules::KnowledgeLevel::LC1)   ? "LC1"
                            : s.value == code_rules::confidence_factor(code_rules::KnowledgeLevel::LC2) ? "LC2"
                            : s.value == code_rules::confidence_factor(code_rules::KnowledgeLevel::LC3) ? "LC3"
                                                                                                       : "";
    } else if (s.parameter == "dSLV_over_d0") {
      c.adopted = a.kase.options.dSLV_over_d0;
    } else if (s.parameter == "dSLC_over_d0") {
      c.adopted = a.kase.options.dSLC_over_d0;
    } else if (s.parameter == "xi_SLV_pct") {
      c.adopted = a.kase.checks.damping_SLV_pct;
    } else {
      c.adopted = a.kase.checks.damping_SLC_pct;
    }
    c.alternative = s.value;
    c.dc_alternative = s.dc;
    c.outcome_alternative = outcome_of_dc(s.dc);
    b.out.push_back(c);
  }
}

// The choices of the kinematic model of candidate ci: e* with the blocks'
// masses distributed over their areas (adopted) or lumped at their centroids;
// the displacement bound of a one-body mechanism (issue 33; the composite
// wedge's, issue 38, when given): d0* with and without it; the demand at
// height (C8.7.1.2.1.7-8 with the floor spectrum [C7.2.6]) against the
// ground's alone.
void add_kinematic_model(Builder& b, std::size_t ci) {
  const FacadeAssessment& a = b.a;
  const KinematicResult& gk = a.kinematic.candidates[ci].result;
  {
    CaseFile k = a.kase;
    k.options.lumped_masses = true;
    const KinematicCaseResult alt = run_kinematic_case(k, false, &a.kinematic);  // the same paths
    const double e1 = alt.candidates[ci].result.e_star;
    if (std::abs(e1 - gk.e_star) > 1e-9 * gk.e_star) {
      ModellingChoice c = b.base("lumped_masses", "");
      c.adopted = gk.e_star;
      c.alternative = e1;
      b.finish(c, alt);
      b.out.push_back(c);
    }
  }
  if (std::isfinite(gk.d0_star_bound) && gk.d0_star_bound < gk.d0_star) {
    CaseFile k = a.kase;
    for (MechanismCandidate& mc : k.mechanism.candidates) mc.rotation_bound = inf;
    const KinematicCaseResult alt = run_kinematic_case(k, false, &a.kinematic);  // the same paths
    ModellingChoice c = b.base("displacement_bound", "");
    c.adopted = gk.d0_star_bound;
    c.alternative = alt.candidates[ci].result.d0_star;
    b.finish(c, alt);
    b.out.push_back(c);
  }
  if (a.kinematic.candidates[ci].Z > 0.0 && a.kase.building) {
    CaseFile k = a.kase;
    k.Z = 0.0;
    const KinematicCaseResult alt = run_kinematic_case(k, false, &a.kinematic);  // the same analyses
    ModellingChoice c = b.base("height_demand", "/building/Z_m");
    c.adopted = a.kinematic.candidates[ci].Z;
    c.alternative = 0.0;
    b.finish(c, alt);
    b.out.push_back(c);
  }
}

// The activation of the side walls' friction (friction overturning: kappa,
// docs/theory/mechanisms.md §2) and the friction of the floors' seats, each
// the case's document with the value changed.
void add_friction(Builder& b) {
  const FacadeAssessment& a = b.a;
  if (a.kase.mechanism.type != "friction_overturning" || !a.kase.source.contains("mechanism")) return;
  const nlohmann::json& mech = a.kase.source.at("mechanism");
  const double kappa = mech.value("activation", 1.0);
  for (double k1 : {0.5, 0.0}) {
    if (k1 >= kappa) continue;
    CaseFile k;
    ModellingChoice c = b.base("friction_activation", "/mechanism/activation");
    c.adopted = kappa;
    c.alternative = k1;
    if (b.reparse([&](nlohmann::json& d) { d["mechanism"]["activation"] = k1; }, k)) b.finish(c, run_kinematic_case(k, false));
    else c.not_computed = "invalid";
    b.out.push_back(c);
  }
  double mu = 0.0;
  if (mech.contains("floors") && mech.at("floors").is_array())
    for (const auto& f : mech.at("floors")) mu = std::max(mu, f.value("friction", 0.0));
  if (mu > 0.0) {
    CaseFile k;
    ModellingChoice c = b.base("seat_friction", "/mechanism/floors/*/friction");
    c.adopted = mu;
    c.alternative = 0.0;
    auto edit = [](nlohmann::json& d) {
      for (auto& f : d["mechanism"]["floors"])
        if (f.is_object() && f.contains("friction")) f["friction"] = 0.0;
    };
    if (b.reparse(edit, k)) b.finish(c, run_kinematic_case(k, false));
    else c.not_computed = "invalid";
    b.out.push_back(c);
  }
}

// The windows of the record selection (NTC 2018 §3.2.3.6): Mw and distance,
// each widened (Mw by 0.5 each side, the largest distance doubled); the
// whole dynamic analysis run again with the records it selects.
void add_selection_window(Builder& b) {
  const FacadeAssessment& a = b.a;
  const RecordSelectionSpec& rs = *a.dynamics.spec->selection;
  const CatalogueFilters f = catalogue_filters(rs, to_string(a.kase.site->conditions.soil), rs.count);
  ModellingChoice c = b.base("selection_window", "/dynamic/select/Mw, /dynamic/select/distance_km");
  c.method = "dynamic";
  for (const MethodVerdict& x : a.verdict.methods)
    if (x.code == "NTC2018" && x.method == "dynamic") {
      c.dc = x.max_dc;
      c.outcome = x.outcome();
    }
  c.adopted_b = f.Mw_min, c.adopted = f.Mw_max, c.adopted_c = f.R_min_km, c.adopted_d = f.R_max_km;
  c.alternative_b = std::max(2.0, f.Mw_min - 0.5), c.alternative = std::min(10.0, f.Mw_max + 0.5);
  c.alternative_c = 0.0, c.alternative_d = std::min(1000.0, 2.0 * f.R_max_km);
  CaseFile k;
  auto edit = [&](nlohmann::json& d) {
    d["dynamic"]["select"]["Mw"] = nlohmann::json::array({c.alternative_b, c.alternative});
    d["dynamic"]["select"]["distance_km"] = nlohmann::json::array({c.alternative_c, c.alternative_d});
  };
  if (b.reparse(edit, k)) {
    try {
      FacadeOptions o;
      o.histories = false;
      o.review = false;
      o.sensitivity = false;  // only the dynamic D/C of the alternative is read
      o.kinematic = &a.kinematic;  // the edit is the dynamic block's alone: the same kinematic results
      const FacadeAssessment alt = assess_facade(k, o);
      for (const MethodVerdict& x : alt.verdict.methods)
        if (x.code == "NTC2018" && x.method == "dynamic") {
          c.dc_alternative = x.max_dc;
          c.outcome_alternative = x.outcome();
        }
      if (std::isnan(c.dc_alternative)) c.not_computed = "no_records";
    } catch (const InputError&) {
      c.not_computed = "no_records";
    }
  } else {
    c.not_computed = "invalid";
  }
  b.out.push_back(c);
}

}  // namespace

std::vector<ModellingChoice> modelling_choices(const FacadeAssessment& a, bool records) {
  const MethodVerdict* mp = a.verdict.conclusion();
  if (!mp || mp->code != "NTC2018" || !a.kase.site) return {};
  Builder b{a, *mp, {}};
  add_sensitivity(b);
  add_kinematic_model(b, method_candidate(a, *mp));
  add_friction(b);
  if (a.dynamics.spec && a.dynamics.applies && a.dynamics.spec->selection && (records || mp->method == "dynamic"))
    add_selection_window(b);
  return b.out;
}

}  // namespace assess
