// tie_report.cpp: text and JSON of the tie rods (issue 23); formatting only.
#include "assess/report/tie_report.hpp"

#include "assess/report/kinematic_report.hpp"
#include "assess/support/units.hpp"
#include "report/text_format.hpp"

#include <cmath>
#include <algorithm>
#include <limits>

namespace assess {
namespace {

constexpr double kN = units::kN;

std::string rod_label(const Tie& t) {
  if (t.rod.diameter > 0.0)
    return format("rod %s%.0f mm %s", "diam. ", t.rod.diameter * 1e3, t.rod.grade.c_str());
  return format("rod A = %.0f mm2 %s", t.rod.area * 1e6, t.rod.grade.c_str());
}

std::string anchor_label(const Tie& t) {
  if (t.anchor.type == AnchorType::Plate)
    return format("plate %.0f x %.0f x %.0f mm %s", t.anchor.a * 1e3, t.anchor.b * 1e3, t.anchor.t * 1e3,
                  t.anchor.grade.c_str());
  return format("bar anchor %.0f mm, diam. %.0f mm %s", t.anchor.a * 1e3, t.anchor.b * 1e3, t.anchor.grade.c_str());
}

std::string num_or_dash(double v, const char* f) { return std::isfinite(v) ? format(f, v) : std::string("-"); }

const CheckRow* find_row(const KinematicCaseResult& r, const CheckRow& key) {
  const CandidateResult& cr = r.candidates[r.governing];
  for (const CheckRow& row : cr.checks)
    if (row.code == key.code && row.limit_state == key.limit_state && row.kind == key.kind && row.location == key.location)
      return &row;
  return nullptr;
}

double scale(const TieCheckRow& r) { return r.unit == "mm" ? 1e3 : 1.0 / kN; }

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json side_json(const KinematicCaseResult& r, double zeta, bool passes) {
  const CandidateResult& cr = r.candidates[r.governing];
  nlohmann::json j;
  j["governing"] = cr.label;
  j["alpha0"] = cr.result.alpha0;
  j["a0_star"] = cr.result.a0_star;
  j["d0_star"] = cr.result.curve_complete() ? num(cr.result.d0_star) : nlohmann::json(nullptr);
  j["zeta_E"] = num(zeta);
  j["every_check_satisfied"] = passes;
  j["e_star"] = cr.result.e_star;
  j["dk0"] = cr.result.curve_complete() ? num(cr.result.dk0) : nlohmann::json(nullptr);
  j["d_star_per_dk"] = cr.result.d_star_per_dk;
  j["d_SLV"] = cr.result.d_SLV;
  j["d_SLC"] = cr.result.d_SLC;
  j["T_SLV"] = cr.result.T_SLV;
  j["T_SLC"] = cr.result.T_SLC;
  j["du_star"] = cr.result.du_star;
  j["Ts"] = cr.result.Ts;
  // The capacity curve with each tie level's force (kN) and elongation (m) at each point.
  nlohmann::json curve = nlohmann::json::array();
  for (const CapacityPoint& p : cr.result.curve) {
    nlohmann::json pt{{"dk", p.dk}, {"d_star", p.d_star}, {"alpha", p.alpha}, {"a_star", p.a_star}};
    if (!p.tie_force.empty()) {
      nlohmann::json f = nlohmann::json::array(), e = nlohmann::json::array();
      for (double v : p.tie_force) f.push_back(v / kN);
      for (double v : p.tie_elongation) e.push_back(v);
      pt["tie_force_kN"] = f;
      pt["tie_elongation_m"] = e;
    }
    curve.push_back(pt);
  }
  j["capacity_curve"] = curve;
  nlohmann::json tl = nlohmann::json::array();
  for (const TieWork& w : cr.result.ties)
    tl.push_back({{"name", w.tie.name},
                  {"ties_on_mechanism", w.tie.count},
                  {"strength_kN", w.tie.capacity / kN},
                  {"stiffness_kN_m", w.tie.stiffness / kN},
                  {"pretension_kN", w.tie.pretension / kN},
                  {"yield_elongation_m", w.tie.yield_elongation()},
                  {"virtual_elongation_m_per_rad", w.d_along},
                  {"work_in_alpha0_kNm", w.work / kN}});
  j["tie_levels_on_mechanism"] = tl;
  j["checks"] = nlohmann::json::array();
  for (const CheckRow& row : cr.checks) j["checks"].push_back(to_json(row));
  return j;
}

std::string dynamics_text(const TieDynamicResult& d, bool designed) {
  if (!d.applies) return d.note.empty() ? "" : wrap_text("  dynamic analysis with the tie: not done: " + d.note, 4) + "\n";
  std::string s = wrap_text(designed ? "  dynamic check before and after the tie (Circ. 2019 C8.7.1.2.1.9; the analyses "
                                       "above repeated with the tie as a one-sided elastic-perfectly-plastic restraint):"
                                     : "  dynamic check before and after the tie (Circ. 2019 C8.7.1.2.1.9; the analyses "
                                       "above are those of the wall with its ties, as one-sided elastic-perfectly-plastic "
                                       "restraints; before: the same analyses without them):",
                             4) +
                   "\n";
  s += format("      %7s %4s %-18s %9s %9s %10s %10s %9s %9s %9s\n", "e", "N", "rule", "overt.bef", "overt.aft",
              "d* bef(m)", "d* aft(m)", "dSLV bef", "dSLV aft", "yld/brk");
  for (const TieDynamicSummary& x : d.summaries)
    s += format("      %7.3f %4d %-18s %9d %9d %10.4f %10.4f %9.4f %9.4f %9s\n        verdict: %s -> %s\n", x.e,
                x.records, x.rule.c_str(), x.overturned_before, x.overturned_after, x.d_demand_before, x.d_demand_after,
                x.d_SLV_before, x.d_SLV_after, format("%d/%d", x.yielded, x.ruptured).c_str(),
                x.satisfied_before ? "satisfied" : "NOT satisfied", x.satisfied_after ? "satisfied" : "NOT satisfied");
  double ep = 0.0, E = 0.0, F = 0.0;
  for (const TieDynamicRun& r : d.runs) {
    ep = std::max(ep, r.plastic_elongation);
    E = std::max(E, r.plastic_energy);
    F = std::max(F, r.max_force);
  }
  s += wrap_text(format("      largest tie force %.2f kN per tie, permanent elongation %.1f mm, energy dissipated by the "
                        "rods %.3f kJ per tie (one tie of each level, summed)",
                        F / kN, ep * 1e3, E / 1e3),
                 8) +
       "\n";
  return s;
}

}  // namespace

std::string tie_text(const TieInterventionResult& t) {
  std::string s = "\nTie rods (catene) - issue 23\n";
  if (t.designed)
    s += t.found ? format("  design: the smallest rod and plate of the lists that make every check pass (%d combinations "
                          "analysed)\n",
                          t.tried)
                 : "  design: NOT FOUND: " + t.message + "; the largest combination is shown\n";
  if (t.designed && t.passes_before)
    s += "  note: the mechanism already satisfies every check without the ties designed here; the smallest tie of the "
         "lists is shown\n";
  for (const TieLevelResult& L : t.levels) {
    const Tie& tie = L.tie;
    s += wrap_text(format("  level \"%s\": %s%s, %s, anchor at (%.2f, %.2f) m, spacing %.2f m, free length %.2f m, "
                "pretension %.1f kN",
                tie.name.c_str(), rod_label(tie).c_str(),
                tie.rod.diameter > 0.0 ? format(" (A = %.0f mm2)", tie.rod.area * 1e6).c_str() : "", anchor_label(tie).c_str(), tie.point.x(),
                tie.point.y(), tie.spacing, tie.free_length, tie.pretension / kN), 4) + "\n";
    const TieResistance& r = L.resistance;
    s += wrap_text(format("    design strengths (kN): rod %.1f, local compression %.1f, punching %.1f, anchor bending %.1f -> "
                "T_Rd = %.1f (%s); k = EA/L = %.0f kN/m; %.3f ties on the mechanism",
                r.rod / kN, r.bearing / kN, r.punching / kN, r.anchor_bending / kN, r.design / kN, r.governing.c_str(),
                r.stiffness / kN, L.count), 6) + "\n";
    s += "    force needed by each check of the mechanism (this level, the others as given):\n";
    s += format("      %-8s %-4s %-13s %-8s %12s %14s %12s\n", "code", "LS", "kind", "where", "per tie kN",
                "per metre kN/m", "D/C without");
    for (const RequiredTieForce& f : L.required)
      s += format("      %-8s %-4s %-13s %-8s %12s %14s %12.3f\n", f.code.c_str(), f.limit_state.c_str(),
                  f.kind.c_str(), f.location.c_str(), num_or_dash(f.per_tie / kN, "%.2f").c_str(),
                  num_or_dash(f.per_metre / kN, "%.2f").c_str(), f.dc_without);
    s += format("    checks of the tie (N_Ed = %.2f kN per tie, the largest force needed):\n", L.N_Ed / kN);
    s += format("      %-18s %-38s %9s %9s %4s %6s  %s\n", "check", "clause / source", "demand", "capacity", "unit",
                "D/C", "verdict");
    for (const TieCheckRow& c : L.checks)
      s += format("      %-18s %-38s %9.2f %9.2f %4s %6.3f  %s\n", c.check.c_str(), c.clause.c_str(),
                  c.demand * scale(c), c.capacity * scale(c), c.unit.c_str(), c.dc, verdict(c.satisfied));
  }
  const CandidateResult& b = t.before.candidates[t.before.governing];
  const CandidateResult& a = t.after.candidates[t.after.governing];
  s += "  the mechanism before and after the ties (governing candidate):\n";
  s += format("      %-34s %14s %14s\n", "", "before", "after");
  s += format("      %-34s %14.4f %14.4f\n", "alpha0 (-)", b.result.alpha0, a.result.alpha0);
  s += format("      %-34s %14.4f %14.4f\n", "a0* (m/s2)", b.result.a0_star, a.result.a0_star);
  s += format("      %-34s %14s %14s\n", "d0* (m)",
              b.result.curve_complete() ? format("%.4f", b.result.d0_star).c_str() : "-",
              a.result.curve_complete() ? format("%.4f", a.result.d0_star).c_str() : "-");
  s += format("      %-34s %14s %14s\n", "zeta_E = PGA capacity / demand", num_or_dash(t.zetaE_before, "%.3f").c_str(),
              num_or_dash(t.zetaE_after, "%.3f").c_str());
  s += format("      %-34s %14s %14s\n", "every check", t.passes_before ? "satisfied" : "NOT satisfied",
              t.passes_after ? "satisfied" : "NOT satisfied");
  if (std::isfinite(t.zetaE_before) && std::isfinite(t.zetaE_after))
    s += format("      improvement of zeta_E: %+.3f (x %.2f)\n", t.zetaE_after - t.zetaE_before,
                t.zetaE_after / t.zetaE_before);
  s += format("      %-8s %-4s %-13s %-8s %12s %12s\n", "code", "LS", "kind", "where", "D/C before", "D/C after");
  for (const CheckRow& row : b.checks) {
    const CheckRow* r2 = find_row(t.after, row);
    s += format("      %-8s %-4s %-13s %-8s %12.3f %12s\n", row.code.c_str(), row.limit_state.c_str(), row.kind.c_str(),
                row.location.c_str(), row.dc, r2 ? format("%.3f", r2->dc).c_str() : "-");
  }
  s += dynamics_text(t.dynamics, t.designed);
  return s;
}

nlohmann::json tie_json(const TieInterventionResult& t) {
  nlohmann::json j;
  j["designed"] = t.designed;
  if (t.designed) {
    j["found"] = t.found;
    j["combinations_analysed"] = t.tried;
    if (!t.found) j["message"] = t.message;
  }
  j["levels"] = nlohmann::json::array();
  for (const TieLevelResult& L : t.levels) {
    const Tie& tie = L.tie;
    nlohmann::json l;
    l["name"] = tie.name;
    l["point_m"] = {tie.point.x(), tie.point.y()};
    l["direction"] = {tie.direction.x(), tie.direction.y()};
    l["rod"] = {{"diameter_mm", tie.rod.diameter * 1e3}, {"area_mm2", tie.rod.area * 1e6}, {"grade", tie.rod.grade},
                {"fyk_MPa", tie.rod.fyk / 1e6}, {"gamma_M0", tie.rod.gamma_M0}};
    l["anchor"] = tie.anchor.type == AnchorType::Plate
                      ? nlohmann::json{{"type", "plate"}, {"a_mm", tie.anchor.a * 1e3}, {"b_mm", tie.anchor.b * 1e3},
                                       {"t_mm", tie.anchor.t * 1e3}, {"grade", tie.anchor.grade}}
                      : nlohmann::json{{"type", "bar"}, {"length_mm", tie.anchor.a * 1e3},
                                       {"diameter_mm", tie.anchor.b * 1e3}, {"grade", tie.anchor.grade}};
    l["free_length_m"] = tie.free_length;
    l["spacing_m"] = tie.spacing;
    l["pretension_kN"] = tie.pretension / kN;
    l["ties_on_mechanism"] = L.count;
    const TieResistance& r = L.resistance;
    l["strength_kN"] = {{"rod", r.rod / kN},           {"local_compression", r.bearing / kN},
                        {"punching", r.punching / kN}, {"anchor_bending", num(r.anchor_bending / kN)},
                        {"design", r.design / kN},     {"governing", r.governing}};
    l["stiffness_kN_m"] = r.stiffness / kN;
    l["required"] = nlohmann::json::array();
    for (const RequiredTieForce& f : L.required)
      l["required"].push_back({{"code", f.code},
                               {"limit_state", f.limit_state},
                               {"kind", f.kind},
                               {"location", f.location},
                               {"per_tie_kN", num(f.per_tie / kN)},
                               {"per_metre_kN_m", num(f.per_metre / kN)},
                               {"level_kN", num(f.level_force / kN)},
                               {"reachable", f.reachable},
                               {"dc_without", num(f.dc_without)}});
    l["N_Ed_kN"] = L.N_Ed / kN;
    l["elongation_demand_m"] = L.elongation_demand ? num(*L.elongation_demand) : nlohmann::json(nullptr);
    l["checks"] = nlohmann::json::array();
    for (const TieCheckRow& c : L.checks)
      l["checks"].push_back({{"check", c.check},
                             {"clause", c.clause},
                             {"formula", c.formula},
                             {"demand", c.demand * scale(c)},
                             {"capacity", num(c.capacity * scale(c))},
                             {"unit", c.unit},
                             {"dc", num(c.dc)},
                             {"satisfied", c.satisfied}});
    l["satisfied"] = L.satisfied;
    j["levels"].push_back(l);
  }
  j["before"] = side_json(t.before, t.zetaE_before, t.passes_before);
  j["after"] = side_json(t.after, t.zetaE_after, t.passes_after);
  j["zeta_E_improvement"] = num(t.zetaE_after - t.zetaE_before);
  nlohmann::json dj;
  dj["applies"] = t.dynamics.applies;
  dj["note"] = t.dynamics.note;
  dj["summaries"] = nlohmann::json::array();
  for (const TieDynamicSummary& x : t.dynamics.summaries)
    dj["summaries"].push_back({{"e", x.e},
                               {"records", x.records},
                               {"rule", x.rule},
                               {"overturned_before", x.overturned_before},
                               {"overturned_after", x.overturned_after},
                               {"d_demand_before_m", x.d_demand_before},
                               {"d_demand_after_m", x.d_demand_after},
                               {"d_SLV_before_m", x.d_SLV_before},
                               {"d_SLV_after_m", x.d_SLV_after},
                               {"collapse_before", x.collapse_before},
                               {"collapse_after", x.collapse_after},
                               {"satisfied_before", x.satisfied_before},
                               {"satisfied_after", x.satisfied_after},
                               {"analyses_rod_yielded", x.yielded},
                               {"analyses_rod_broken", x.ruptured},
                               {"max_plastic_elongation_m", x.max_plastic_elongation}});
  dj["runs"] = nlohmann::json::array();
  for (const TieDynamicRun& r : t.dynamics.runs)
    dj["runs"].push_back({{"run", r.run},
                          {"theta_max", r.theta_max},
                          {"theta_collapse", r.theta_collapse},
                          {"overturned", r.overturned},
                          {"yielded", r.yielded},
                          {"max_force_kN", r.max_force / kN},
                          {"plastic_elongation_m", r.plastic_elongation},
                          {"max_elongation_m", r.max_elongation},
                          {"ruptured", r.ruptured},
                          {"plastic_energy_kJ", r.plastic_energy / 1e3},
                          {"d_star_m", r.d_star},
                          {"collapse", r.collapse},
                          {"failed", r.failed}});
  j["dynamic"] = dj;
  return j;
}

}  // namespace assess
