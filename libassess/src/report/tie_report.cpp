// tie_report.cpp: text and JSON of the tie rods (issues 23, 29), and the
// readings adopted; formatting only.
#include "assess/report/tie_report.hpp"
#include "assess/report/note_text.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/report/kinematic_report.hpp"
#include "assess/support/units.hpp"
#include "report/text_format.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace assess {
namespace {

constexpr double kN = units::kN;

std::string mm(double m) { return format("%.0f", m * 1e3); }

std::string rod_label(const Tie& t) {
  std::string s = t.rod.diameter > 0.0 ? "diam. " + mm(t.rod.diameter) + " mm" : format("A = %.0f mm2", t.rod.area * 1e6);
  s += " " + t.rod.grade;
  if (t.rod.ends == TieEnds::Threaded) return s + ", threaded ends M" + mm(t.rod.thread_diameter);
  return s + ", " + to_string(t.rod.ends) + " ends M" + mm(t.rod.thread_diameter);
}

std::string anchor_label(const Tie& t) {
  if (t.anchor.type == AnchorType::Plate)
    return format("plate %.0f x %.0f x %.0f mm %s", t.anchor.a * 1e3, t.anchor.b * 1e3, t.anchor.t * 1e3,
                  t.anchor.grade.c_str());
  return format("bar anchor (paletto) %.0f mm, diam. %.0f mm %s", t.anchor.a * 1e3, t.anchor.b * 1e3,
                t.anchor.grade.c_str());
}

std::string layout_label(const Tie& t) {
  const TieLayout& L = t.layout;
  std::string s = format("%d ties on the %.2f m wall", L.count, L.wall_length);
  if (L.count > 1) s += format(", spacing %.2f m", L.centre_spacing());
  s += format(", edge distance %.2f m", L.edge_distance);
  if (std::isfinite(L.crown)) s += format(", crown at z = %.2f m", L.crown);
  if (!L.openings.empty()) s += format(", %zu opening(s)", L.openings.size());
  return s;
}

std::string num_or_dash(double v, const char* f) { return std::isfinite(v) ? format(f, v) : std::string("-"); }

const CheckRow* find_row(const KinematicCaseResult& r, const CheckRow& key) {
  const CandidateResult& cr = r.candidates[r.governing];
  for (const CheckRow& row : cr.checks)
    if (row.code == key.code && row.limit_state == key.limit_state && row.kind == key.kind && row.location == key.location)
      return &row;
  return nullptr;
}

double scale(const TieCheckRow& r) { return r.unit == "mm" ? 1e3 : r.unit == "kN" ? 1.0 / kN : 1.0; }

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

nlohmann::json side_json(const KinematicCaseResult& r, double zeta, bool passes) {
  const CandidateResult& cr = r.candidates[r.governing];
  const KinematicResult& k = cr.result;
  nlohmann::json j;
  j["governing"] = cr.label;
  j["alpha0"] = num(k.alpha0);
  j["a0_star"] = num(k.a0_star);
  j["d0_star"] = k.curve_complete() ? num(k.d0_star) : nlohmann::json(nullptr);
  j["zeta_E"] = num(zeta);
  j["every_check_satisfied"] = passes;
  j["e_star"] = num(k.e_star);
  j["dk0"] = k.curve_complete() ? num(k.dk0) : nlohmann::json(nullptr);
  j["d_star_per_dk"] = num(k.d_star_per_dk);
  j["d_SLV"] = num(k.d_SLV);
  j["d_SLC"] = num(k.d_SLC);
  j["T_SLV"] = num(k.T_SLV);
  j["T_SLC"] = num(k.T_SLC);
  j["du_star"] = num(k.du_star);
  j["Ts"] = num(k.Ts);
  // Issue 37: the curve with each level breaking where it fails; the first
  // break that drops the capacity by more than 50 % caps it (C8.7.1.2.1.6).
  j["d_star_tie_limit"] = num(k.d_star_tie_limit);
  j["tie_limit_level"] = k.tie_limit_level;
  j["d_star_tie_cap"] = num(k.d_star_tie_cap);
  j["tie_breaks"] = nlohmann::json::array();
  for (const KinematicResult::TieBreak& b : k.tie_breaks)
    j["tie_breaks"].push_back({{"level", b.level},
                               {"d_star", num(b.d_star)},
                               {"alpha_before", num(b.alpha_before)},
                               {"alpha_after", num(b.alpha_after)},
                               {"caps", b.caps}});
  // The capacity curve with each tie level's force (kN) and elongation (m) at each point.
  nlohmann::json curve = nlohmann::json::array();
  for (const CapacityPoint& p : k.curve) {
    nlohmann::json pt{{"dk", num(p.dk)}, {"d_star", num(p.d_star)}, {"alpha", num(p.alpha)}, {"a_star", num(p.a_star)}};
    if (!p.tie_force.empty()) {
      nlohmann::json f = nlohmann::json::array(), e = nlohmann::json::array();
      for (double v : p.tie_force) f.push_back(num(v / kN));
      for (double v : p.tie_elongation) e.push_back(num(v));
      pt["tie_force_kN"] = f;
      pt["tie_elongation_m"] = e;
    }
    curve.push_back(pt);
  }
  j["capacity_curve"] = curve;
  nlohmann::json tl = nlohmann::json::array();
  for (const TieWork& w : k.ties)
    tl.push_back({{"name", w.tie.name},
                  {"ties_on_mechanism", num(w.tie.count)},
                  {"strength_kN", num(w.tie.capacity / kN)},
                  {"stiffness_kN_m", num(w.tie.stiffness / kN)},
                  {"pretension_kN", num(w.tie.pretension / kN)},
                  {"ductile", w.tie.ductile},
                  {"yield_elongation_m", num(w.tie.yield_elongation())},
                  {"failure_elongation_m", num(w.tie.failure_elongation())},
                  {"virtual_elongation_m_per_rad", num(w.d_along)},
                  {"work_in_alpha0_kNm", num(w.work / kN)}});
  j["tie_levels_on_mechanism"] = tl;
  j["checks"] = nlohmann::json::array();
  for (const CheckRow& row : cr.checks) j["checks"].push_back(to_json(row));
  return j;
}

nlohmann::json level_json(const TieLevelResult& L) {
  const Tie& tie = L.tie;
  nlohmann::json l;
  l["name"] = tie.name;
  l["existing"] = tie.existing;
  l["point_m"] = {tie.point.x(), tie.point.y()};
  l["direction"] = {tie.direction.x(), tie.direction.y()};
  l["rod"] = {{"diameter_mm", tie.rod.diameter * 1e3},
              {"area_mm2", tie.rod.area * 1e6},
              {"grade", tie.rod.grade},
              {"fyk_MPa", tie.rod.fyk / 1e6},
              {"ftk_MPa", tie.rod.ftk / 1e6},
              {"gamma_M0", tie.rod.gamma_M0},
              {"ends", to_string(tie.rod.ends)},
              {"thread_mm", tie.rod.thread_diameter * 1e3},
              {"thread_area_mm2", tie.rod.thread_area * 1e6},
              {"nut_width_mm", tie.rod.nut_width * 1e3}};
  l["anchor"] = tie.anchor.type == AnchorType::Plate
                    ? nlohmann::json{{"type", "plate"}, {"a_mm", tie.anchor.a * 1e3}, {"b_mm", tie.anchor.b * 1e3},
                                     {"t_mm", tie.anchor.t * 1e3}, {"grade", tie.anchor.grade}}
                    : nlohmann::json{{"type", "bar"}, {"length_mm", tie.anchor.a * 1e3},
                                     {"diameter_mm", tie.anchor.b * 1e3}, {"grade", tie.anchor.grade}};
  l["free_length_m"] = tie.free_length;
  l["layout"] = {{"wall_length_m", tie.layout.wall_length},
                 {"count", tie.layout.count},
                 {"spacing_m", tie.layout.centre_spacing()},
                 {"edge_distance_m", tie.layout.edge_distance},
                 {"tributary_length_m", tie.spacing}};
  l["pretension_kN"] = tie.pretension / kN;
  l["ties_on_mechanism"] = L.count;
  const TieResistance& r = L.resistance;
  l["strength_kN"] = {{"rod", r.rod / kN},           {"thread", r.thread / kN},
                      {"local_compression", r.bearing / kN}, {"punching", r.punching / kN},
                      {"sliding", num(r.sliding / kN)},       {"anchor_bending", r.anchor_bending / kN},
                      {"design", r.design / kN},             {"governing", r.governing}};
  l["sections_mm2"] = {{"rod_corroded", r.area_c * 1e6}, {"thread_corroded", r.thread_area_c * 1e6},
                       {"corrosion_mm", tie.rod.corrosion * 1e3}};
  l["wedge"] = {{"tie", r.wedge.tie + 1},
                {"x_m", r.wedge.x},
                {"strip_m", {r.wedge.x_lo, r.wedge.x_hi}},
                {"area_m2", r.wedge.area},
                {"full_area_m2", r.wedge.full_area},
                {"crown_z_m", num(tie.layout.crown)},
                {"distance_to_crown_m", num(tie.layout.crown - tie.point.y())}};
  l["sliding"] = {{"tie", r.slide.tie + 1},
                  {"block_top_z_m", num(r.slide.block_top)},
                  {"side_area_m2", r.slide.side_area},
                  {"base_area_m2", r.slide.base_area},
                  {"sigma_n_kPa", r.slide.sigma_n / 1e3},
                  {"base_strength_kPa", r.sliding_strength / 1e3}};
  l["temperature"] = {{"delta_T_K", tie.delta_T},
                      {"thermal_force_kN", r.thermal_force / kN},
                      {"fundamental_demand_kN", r.temperature_demand / kN}};
  l["per_level_kN"] = L.count > 0.0 ? num(r.design * tie.layout.count / kN) : nlohmann::json(nullptr);
  l["ductile"] = r.ductile;
  l["capacity_design"] = {{"yield_force_kN", r.yield_force / kN},
                          {"demand_kN", r.hierarchy_demand / kN},
                          {"gamma_Rd", tie_catalogue::gamma_Rd},
                          {"gamma_ov", tie_catalogue::gamma_ov},
                          {"weakest_brittle", r.weakest_brittle},
                          {"weakest_brittle_kN", r.weakest_brittle_capacity / kN}};
  l["stiffness_kN_m"] = r.stiffness / kN;
  l["yield_elongation_mm"] = r.yield_elongation * 1e3;
  l["eps_ud"] = r.eps_ud;
  l["ultimate_elongation_mm"] = r.ultimate_elongation * 1e3;
  l["required"] = nlohmann::json::array();
  for (const RequiredTieForce& f : L.required) {
    nlohmann::json q{{"code", f.code},
                     {"limit_state", f.limit_state},
                     {"kind", f.kind},
                     {"location", f.location},
                     {"reachable", f.reachable},
                     {"dc_without", num(f.dc_without)}};
    if (f.reachable) {
      q["per_tie_kN"] = num(f.per_tie / kN);
      q["per_metre_kN_m"] = num(f.per_metre / kN);
      q["level_kN"] = num(f.level_force / kN);
    } else {
      q["per_tie_kN"] = q["per_metre_kN_m"] = q["level_kN"] = nullptr;
      q["reason"] = f.reason;
    }
    l["required"].push_back(q);
  }
  const TieDemand& d = L.demand;
  l["demand"] = {{"static_kN", d.static_force / kN},
                 {"reachable", d.reachable},
                 {"at_displacement_demand_kN", d.curve_force ? num(*d.curve_force / kN) : nlohmann::json(nullptr)},
                 {"dynamic_kN", d.dynamic_force ? num(*d.dynamic_force / kN) : nlohmann::json(nullptr)},
                 {"elongation_m", d.elongation ? num(*d.elongation) : nlohmann::json(nullptr)},
                 {"elastic_demand_kN", d.elastic_demand() / kN},
                 {"dynamic_analyses", d.dynamic_runs},
                 {"dynamic_breaks", d.dynamic_breaks}};
  if (!d.reachable) l["demand"]["unreachable"] = d.unreachable;
  if (d.dynamic_breaks > 0) l["demand"]["dynamic_component"] = d.dynamic_component;
  l["checks"] = nlohmann::json::array();
  for (const TieCheckRow& c : L.checks) {
    nlohmann::json row{{"check", c.check},       {"clause", c.clause},         {"formula", c.formula},
                       {"unit", c.unit},         {"satisfied", c.satisfied},   {"reachable", c.reachable}};
    row["demand"] = c.reachable ? num(c.demand * scale(c)) : nlohmann::json(nullptr);
    row["capacity"] = num(c.capacity * scale(c));
    // The rupture check counts analyses: no break is D/C 0, a break a failure
    // whatever the count (null, as a collapse: one rule, issue 28).
    if (c.unit == "analyses")
      row["dc"] = c.satisfied ? nlohmann::json(0.0) : nlohmann::json(nullptr);
    else
      row["dc"] = c.reachable ? num(c.dc) : nlohmann::json(nullptr);
    if (row["dc"].is_null())
      row["dc_meaning"] = c.reachable ? "the tie broke in an analysis: a failure" : "a force no tie can give";
    l["checks"].push_back(row);
  }
  l["satisfied"] = L.satisfied;
  l["dynamic"] = {{"analyses", L.dynamic_runs}, {"yielded", L.dynamic_yielded}, {"broken", L.dynamic_broken}};
  return l;
}

nlohmann::json runs_json(const std::vector<TieDynamicRun>& runs) {
  nlohmann::json out = nlohmann::json::array();
  for (const TieDynamicRun& r : runs) {
    nlohmann::json lv = nlohmann::json::array();
    for (const TieLevelRun& l : r.levels)
      lv.push_back({{"name", l.name},
                    {"max_force_kN", num(l.max_force / kN)},
                    {"max_elongation_m", num(l.max_elongation)},
                    {"yielded", l.yielded},
                    {"plastic_elongation_m", num(l.plastic_elongation)},
                    {"broken", l.broken},
                    {"component", l.component},
                    {"t_broken_s", l.broken ? num(l.t_broken) : nlohmann::json(nullptr)}});
    out.push_back({{"run", r.run},
                   {"record", r.record},
                   {"reversed", r.reversed},
                   {"e", r.e},
                   {"theta_max", num(r.theta_max)},
                   {"theta_collapse", num(r.theta_collapse)},
                   {"overturned", r.overturned},
                   {"yielded", r.yielded},
                   {"broken", r.broken},
                   {"max_force_kN", num(r.max_force / kN)},
                   {"plastic_elongation_m", num(r.plastic_elongation)},
                   {"max_elongation_m", num(r.max_elongation)},
                   {"plastic_energy_kJ", num(r.plastic_energy / 1e3)},
                   {"d_star_m", num(r.d_star)},
                   {"collapse", r.collapse},
                   {"failed", r.failed},
                   {"levels", lv}});
  }
  return out;
}

// The outcome of one analysis for the ties, in words.
std::string outcome_text(const TieDynamicRun& r) {
  if (r.failed) return "integration failed";
  for (const TieLevelRun& l : r.levels)
    if (l.broken)
      return format("BROKEN: %s, %s at t = %.2f s", l.name.c_str(),
                    l.component == "elongation" ? "rod at its ultimate elongation" : l.component.c_str(), l.t_broken);
  if (r.yielded) return format("yielded (ductile), permanent elongation %.1f mm", r.plastic_elongation * 1e3);
  return "elastic";
}

std::string dynamics_text(const TieInterventionResult& t) {
  const TieDynamicResult& d = t.dynamics;
  if (!d.applies) return d.note.empty() ? "" : wrap_text("  dynamic analysis with the ties: not done: " + note_text(Lang::en, d.note), 4) + "\n";
  std::string s = wrap_text(t.intervention ? "  dynamic check, stato di fatto -> stato di progetto (Circ. 2019 "
                                             "C8.7.1.2.1.9; the analyses above repeated with every tie of the project)"
                                           : "  dynamic check of the stato di fatto with its existing ties (Circ. 2019 "
                                             "C8.7.1.2.1.9)",
                            4) +
                  "\n";
  s += format("      %7s %4s %-18s %9s %9s %10s %10s %9s %9s %8s %8s\n", "e", "N", "rule", "overt.bef", "overt.aft",
              "d* bef(m)", "d* aft(m)", "dSLV bef", "dSLV aft", "yielded", "broken");
  // The demand of a state with a collapse is unbounded: "∞" (one column), as its D/C (issue 28).
  auto dem = [](double v) { return finite_or(v, "%10.4f", "         ∞"); };
  for (const TieDynamicSummary& x : d.summaries) {
    const char* before = x.satisfied_before ? "satisfied" : "NOT satisfied";
    const char* after = x.satisfied_after ? "satisfied" : "NOT satisfied";
    s += format("      %7.3f %4d %-18s %9d %9d %s %s %9.4f %9.4f %8d %8d\n", x.e, x.records, x.rule.c_str(),
                x.overturned_before, x.overturned_after, dem(x.d_demand_before).c_str(), dem(x.d_demand_after).c_str(),
                x.d_SLV_before, x.d_SLV_after, x.yielded_after, x.broken_after);
    // One state without an intervention: its verdict once.
    s += t.intervention ? format("        verdict: %s -> %s\n", before, after) : format("        verdict: %s\n", after);
  }
  s += t.intervention ? "    each analysis of the stato di progetto (per tie):\n" : "    each analysis of the stato di fatto (per tie):\n";
  s += format("      %4s %7s %-8s %10s %11s  %s\n", "rec", "e", "polarity", "theta_max", "F max (kN)", "tie outcome");
  for (const TieDynamicRun& r : d.runs)
    s += format("      %4zu %7.3f %-8s %10.5f %11.2f  %s\n", r.record + 1, r.e, r.reversed ? "reversed" : "normal",
                r.theta_max, r.max_force / kN, outcome_text(r).c_str());
  return s;
}

std::string level_text(const TieLevelResult& L) {
  const Tie& tie = L.tie;
  std::string s = wrap_text(format("  level \"%s\" (%s): rod %s (A = %.0f mm2, A_res = %.1f mm2), %s, anchor at (%.2f, "
                                   "%.2f) m, %s, free length %.2f m, pretension %.1f kN",
                                   tie.name.c_str(), tie.existing ? "existing" : "new", rod_label(tie).c_str(),
                                   tie.rod.area * 1e6, tie.rod.thread_area * 1e6, anchor_label(tie).c_str(),
                                   tie.point.x(), tie.point.y(), layout_label(tie).c_str(), tie.free_length,
                                   tie.pretension / kN),
                            4) +
                  "\n";
  const TieResistance& r = L.resistance;
  s += wrap_text(format("    design strengths per tie (kN): rod %.1f, thread %.1f (sections after a corrosion allowance "
                        "of %.1f mm), local compression %.1f, punching %.1f, sliding %s, anchor bending %.1f -> T_Rd = "
                        "%.1f (%s), %.1f kN per level of %d ties; k = EA/L = %.0f kN/m; the chain analysed (%.2f m of "
                        "wall) carries %.3f of them",
                        r.rod / kN, r.thread / kN, tie.rod.corrosion * 1e3, r.bearing / kN, r.punching / kN,
                        num_or_dash(r.sliding / kN, "%.1f").c_str(), r.anchor_bending / kN, r.design / kN,
                        r.governing.c_str(), r.design * tie.layout.count / kN, tie.layout.count, r.stiffness / kN,
                        L.count * tie.layout.wall_length / tie.layout.count, L.count),
                 6) +
       "\n";
  s += wrap_text(format("    punched wedge (45 deg through %.2f m) of tie %d at %.2f m along the wall: lateral area in "
                        "masonry %.3f m2 of %.3f m2 uncut%s; sliding block above its lower edge up to z = %s m, sides "
                        "%.3f m2 + base %.3f m2 at %.1f kPa (sigma_n %.1f kPa)",
                        tie.masonry.thickness, r.wedge.tie + 1, r.wedge.x, r.wedge.area, r.wedge.full_area,
                        std::isfinite(tie.layout.crown)
                            ? format(" (anchor %.2f m below the crown at %.2f m)", tie.layout.crown - tie.point.y(),
                                     tie.layout.crown).c_str()
                            : "",
                        num_or_dash(r.slide.block_top, "%.2f").c_str(), r.slide.side_area, r.slide.base_area,
                        r.sliding_strength / 1e3, r.slide.sigma_n / 1e3),
                 6) +
       "\n";
  s += wrap_text(r.ductile ? format("    DUCTILE: every brittle capacity >= gamma_Rd gamma_ov A fyk = %.2f x %.2f x %.1f = "
                                    "%.1f kN (the weakest, %s, %.1f kN): the rod may yield, up to eps_ud L = %.4f x "
                                    "%.2f m = %.0f mm (eps_ud = 0.9 eps_uk, the grade's uniform elongation)",
                                    tie_catalogue::gamma_Rd, tie_catalogue::gamma_ov, r.yield_force / kN,
                                    r.hierarchy_demand / kN, r.weakest_brittle.c_str(),
                                    r.weakest_brittle_capacity / kN, r.eps_ud, tie.free_length,
                                    r.ultimate_elongation * 1e3)
                           : tie.rod.ends == TieEnds::Threaded
                               ? format("    NOT DUCTILE (threaded on the rod: the thread, %.1f kN, is weaker than the "
                                        "rod): the tie must stay elastic; its checks take the largest force it develops "
                                        "(%.2f kN)",
                                        r.thread / kN, L.demand.elastic_demand() / kN)
                               : format("    NOT DUCTILE (%s %.1f kN < gamma_Rd gamma_ov A fyk = %.1f kN): the tie must "
                                        "stay elastic; its checks take the largest force it develops (%.2f kN)",
                                        r.weakest_brittle.c_str(), r.weakest_brittle_capacity / kN,
                                        r.hierarchy_demand / kN, L.demand.elastic_demand() / kN),
                 6) +
       "\n";
  s += "    force needed by each check of the mechanism (this level, the others as given):\n";
  s += format("      %-8s %-4s %-13s %-8s %12s %14s %12s\n", "code", "LS", "kind", "where", "per tie kN",
              "per metre kN/m", "D/C without");
  for (const RequiredTieForce& f : L.required)
    s += format("      %-8s %-4s %-13s %-8s %12s %14s %12s\n", f.code.c_str(), f.limit_state.c_str(), f.kind.c_str(),
                f.location.c_str(), f.reachable ? format("%.2f", f.per_tie / kN).c_str() : "not reachable",
                f.reachable ? format("%.2f", f.per_metre / kN).c_str() : "-", num_or_dash(f.dc_without, "%.3f").c_str());
  for (const RequiredTieForce& f : L.required)
    if (!f.reachable)
      s += wrap_text("      not reachable (" + f.code + " " + f.limit_state + " " + f.kind + " " + f.location +
                         "): " + f.reason,
                     8) +
           "\n";
  s += "    checks of the tie:\n";
  s += format("      %-28s %-22s %9s %9s %8s %6s  %s\n", "check", "clause / source", "demand", "capacity", "unit",
              "D/C", "verdict");
  for (const TieCheckRow& c : L.checks) {
    const bool count = c.unit == "analyses";
    s += format("      %-28s %-22s %9s %9s %8s %6s  %s\n", c.check.c_str(), c.clause.c_str(),
                !c.reachable ? "n/r" : count ? format("%.0f", c.demand).c_str() : format("%.2f", c.demand * scale(c)).c_str(),
                count ? "0" : format("%.2f", c.capacity * scale(c)).c_str(), c.unit.c_str(),
                c.reachable && !count ? format("%.3f", c.dc).c_str() : "-", c.satisfied ? "satisfied" : "NOT satisfied");
  }
  return s;
}

}  // namespace

std::vector<TieGroup> tie_groups(const TieInterventionResult& t, bool after) {
  std::vector<TieGroup> out;
  for (bool existing : {true, false}) {
    TieGroup g{existing, nullptr, 0};
    for (const TieLevelResult& l : after ? t.levels : t.levels_before)
      if (l.tie.existing == existing && g.levels++ == 0) g.first = &l.tie;
    if (g.first) out.push_back(g);
  }
  return out;
}

std::string tie_text(const TieInterventionResult& t) {
  std::string s = "\nTie rods (catene): stato di fatto and stato di progetto\n";
  if (t.designed) {
    s += wrap_text(t.found ? format("  design: the first rod and anchor of the order, ductile ties first, that make every "
                                    "check pass, every existing tie's included (%d combination%s of the order reached); "
                                    "the new ties are %s",
                                    t.tried, t.tried == 1 ? "" : "s",
                                    t.regime == "ductile" ? "DUCTILE (capacity design satisfied)"
                                                          : "NOT ductile and stay ELASTIC in every analysis")
                           : "  design: NOT FOUND: " + t.message + "; the combination that came closest is shown",
                   4) +
         "\n";
    if (t.passes_before)
      s += "  note: the mechanism already satisfies every check without the ties designed here; the smallest tie of the "
           "lists is shown\n";
    if (!t.wall_members.empty()) {
      std::string m;
      for (const std::string& n : t.wall_members) m += (m.empty() ? "" : ", ") + n;
      s += wrap_text("  the wall's ties act on every mechanism they cross: designed for " + m + " together", 4) + "\n";
    }
    // The trials (all in the JSON): the first ones and the last.
    const std::size_t shown = 30;
    for (std::size_t i = 0; i < t.trials.size(); ++i) {
      if (i == shown && t.trials.size() > shown + 1) {
        s += format("    ... %zu more (JSON: ties.trials)\n", t.trials.size() - shown - 1);
        i = t.trials.size() - 1;
      }
      const TieTrial& x = t.trials[i];
      std::string what = x.diameter > 0.0
                             ? format("diam. %.0f %s M%.0f, %s %.0f x %.0f %s: T_Rd %.1f kN (%s%s)", x.diameter * 1e3,
                                      x.grade.c_str(), x.thread * 1e3,
                                      x.anchor == AnchorType::Plate ? "plate" : "bar", x.plate * 1e3, x.plate_t * 1e3,
                                      x.plate_grade.c_str(), x.T_Rd / kN, x.governing.c_str(),
                                      x.ductile ? ", ductile" : "")
                             : std::string("no new level");
      if (!x.changes.empty()) what += "; " + x.changes;
      s += wrap_text(format("    tried %s: %s%s%s", what.c_str(), x.outcome.c_str(),
                            x.component.empty() ? "" : (" (" + x.component + ")").c_str(),
                            x.mechanism.empty() ? "" : (" in " + x.mechanism).c_str()),
                     8) +
           "\n";
    }
    for (const TieChange& c : t.changes)
      s += wrap_text("  existing level \"" + c.level + "\" fails: changed in the stato di progetto (the least change): " +
                         describe_change(c),
                     4) +
           "\n";
  } else if (!t.intervention) {
    s += "  no intervention: the existing ties are part of the stato di fatto\n";
  }
  if (!t.designed && !t.failing_existing.empty()) {
    std::string n;
    for (const std::string& x : t.failing_existing) n += (n.empty() ? "\"" : ", \"") + x + "\"";
    s += wrap_text("  existing tie(s) " + n + " NOT satisfied: add \"design\": {\"ties\": {\"levels\": []}} to have "
                   "the least change proposed (a new anchor, a new rod, or its removal; docs/theory/ties.md §5)",
                   4) +
         "\n";
  }
  if (!t.levels_before.empty()) {
    s += "  stato di fatto: the existing ties\n";
    for (const TieLevelResult& L : t.levels_before) s += level_text(L);
  }
  if (t.intervention) {
    s += "  stato di progetto: every tie\n";
    for (const TieLevelResult& L : t.levels) s += level_text(L);
  }
  const CandidateResult& b = t.before.candidates[t.before.governing];
  const CandidateResult& a = t.after.candidates[t.after.governing];
  s += "  the mechanism in the stato di fatto and in the stato di progetto (governing candidate):\n";
  s += format("      %-44s %14s %14s\n", "", "di fatto", "di progetto");
  s += format("      %-44s %14.4f %14.4f\n", "alpha0 (-)", b.result.alpha0, a.result.alpha0);
  s += format("      %-44s %14.4f %14.4f\n", "a0* (m/s2)", b.result.a0_star, a.result.a0_star);
  auto dcol = [](const KinematicResult& k, double v) {
    return k.curve_complete() ? num_or_dash(v, "%.4f") : std::string("-");
  };
  s += format("      %-44s %14s %14s\n", "d0* (m)", dcol(b.result, b.result.d0_star).c_str(),
              dcol(a.result, a.result.d0_star).c_str());
  s += format("      %-44s %14s %14s\n", "d* where a tie reaches its strength (m)",
              dcol(b.result, b.result.d_star_tie_limit).c_str(), dcol(a.result, a.result.d_star_tie_limit).c_str());
  s += format("      %-44s %14s %14s\n", "d* of a break dropping alpha > 50 % (m)",
              dcol(b.result, b.result.d_star_tie_cap).c_str(), dcol(a.result, a.result.d_star_tie_cap).c_str());
  s += format("      %-44s %14s %14s\n", "d_SLV (m)", dcol(b.result, b.result.d_SLV).c_str(),
              dcol(a.result, a.result.d_SLV).c_str());
  s += format("      %-44s %14s %14s\n", "d_SLC (m)", dcol(b.result, b.result.d_SLC).c_str(),
              dcol(a.result, a.result.d_SLC).c_str());
  for (const auto* k : {&b.result, &a.result})
    for (const KinematicResult::TieBreak& x : k->tie_breaks)
      s += wrap_text(format("      %s: \"%s\" breaks at d* = %.4f m, alpha %.4f -> %.4f%s", k == &b.result ? "di fatto" : "di progetto",
                            x.level.c_str(), x.d_star, x.alpha_before, x.alpha_after,
                            x.caps ? " (a drop above 50 %: the capacity stops there, Circ. 2019 C8.7.1.2.1.6)" : ""),
                     8) +
           "\n";
  s += format("      %-44s %14s %14s\n", "zeta_E = PGA capacity / demand", num_or_dash(t.zetaE_before, "%.3f").c_str(),
              num_or_dash(t.zetaE_after, "%.3f").c_str());
  s += format("      %-44s %14s %14s\n", "every check", t.passes_before ? "satisfied" : "NOT satisfied",
              t.passes_after ? "satisfied" : "NOT satisfied");
  if (t.intervention && std::isfinite(t.zetaE_before) && std::isfinite(t.zetaE_after) && t.zetaE_before > 0.0)
    s += format("      improvement of zeta_E: %+.3f (x %.2f)\n", t.zetaE_after - t.zetaE_before,
                t.zetaE_after / t.zetaE_before);
  s += format("      %-8s %-4s %-13s %-8s %14s %14s\n", "code", "LS", "kind", "where", "D/C fatto", "D/C progetto");
  for (const CheckRow& row : b.checks) {
    const CheckRow* r2 = find_row(t.after, row);
    auto dc = [](const CheckRow* x) { return num_or_dash(x->dc, "%.3f"); };
    s += format("      %-8s %-4s %-13s %-8s %14s %14s\n", row.code.c_str(), row.limit_state.c_str(), row.kind.c_str(),
                row.location.c_str(), dc(&row).c_str(), r2 ? dc(r2).c_str() : "-");
  }
  s += dynamics_text(t);
  s += "  readings adopted (for the appendix):\n";
  for (const TieReading& r : tie_readings(t, Lang::en))
    s += wrap_text("    - " + r.quantity + ": " + r.reading + " (" + r.basis + ")", 6, 100) + "\n";
  return s;
}

nlohmann::json tie_json(const TieInterventionResult& t) {
  nlohmann::json j;
  j["designed"] = t.designed;
  j["intervention"] = t.intervention;
  if (t.designed) {
    j["found"] = t.found;
    j["combinations_analysed"] = t.tried;
    j["regime"] = t.regime;
    if (!t.found) j["message"] = t.message;
    j["trials"] = nlohmann::json::array();
    for (const TieTrial& x : t.trials)
      j["trials"].push_back({{"diameter_mm", x.diameter * 1e3}, {"grade", x.grade}, {"thread_mm", x.thread * 1e3},
                             {"anchor", x.anchor == AnchorType::Plate ? "plate" : "bar"},
                             {"plate_mm", x.plate * 1e3}, {"plate_t_mm", x.plate_t * 1e3},
                             {"anchor_grade", x.plate_grade}, {"T_Rd_kN", num(x.T_Rd / kN)},
                             {"governing", x.governing}, {"ductile", x.ductile}, {"changes", x.changes},
                             {"outcome", x.outcome}, {"component", x.component}, {"mechanism", x.mechanism}});
    j["changes"] = nlohmann::json::array();
    for (const TieChange& c : t.changes)
      j["changes"].push_back({{"level", c.level}, {"kind", c.kind}, {"description", describe_change(c)}});
  }
  j["failing_existing"] = t.failing_existing;
  j["wall_members"] = t.wall_members;
  j["levels_before"] = nlohmann::json::array();
  for (const TieLevelResult& L : t.levels_before) j["levels_before"].push_back(level_json(L));
  j["levels"] = nlohmann::json::array();
  for (const TieLevelResult& L : t.levels) j["levels"].push_back(level_json(L));
  j["before"] = side_json(t.before, t.zetaE_before, t.passes_before);
  j["after"] = side_json(t.after, t.zetaE_after, t.passes_after);
  j["zeta_E_improvement"] = num(t.zetaE_after - t.zetaE_before);
  nlohmann::json dj;
  dj["applies"] = t.dynamics.applies;
  dj["note"] = note_text(Lang::en, t.dynamics.note);
  dj["summaries"] = nlohmann::json::array();
  for (const TieDynamicSummary& x : t.dynamics.summaries)
    dj["summaries"].push_back({{"e", x.e},
                               {"records", x.records},
                               {"rule", x.rule},
                               {"overturned_before", x.overturned_before},
                               {"overturned_after", x.overturned_after},
                               {"d_demand_before_m", num(x.d_demand_before)},
                               {"d_demand_after_m", num(x.d_demand_after)},
                               {"d_SLV_before_m", num(x.d_SLV_before)},
                               {"d_SLV_after_m", num(x.d_SLV_after)},
                               {"collapse_before", x.collapse_before},
                               {"collapse_after", x.collapse_after},
                               {"satisfied_before", x.satisfied_before},
                               {"satisfied_after", x.satisfied_after},
                               {"analyses_yielded_before", x.yielded_before},
                               {"analyses_yielded_after", x.yielded_after},
                               {"analyses_broken_before", x.broken_before},
                               {"analyses_broken_after", x.broken_after},
                               {"max_plastic_elongation_m", num(x.max_plastic_elongation)}});
  dj["runs_before"] = runs_json(t.dynamics.runs_before);
  dj["runs"] = runs_json(t.dynamics.runs);
  j["dynamic"] = dj;
  j["readings"] = nlohmann::json::array();
  for (const TieReading& r : tie_readings(t, Lang::en))
    j["readings"].push_back({{"quantity", r.quantity}, {"reading", r.reading}, {"basis", r.basis}});
  return j;
}

}  // namespace assess
