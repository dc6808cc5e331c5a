// building_report.cpp: the building report as terminal text and JSON
// (issue 22). Formatting only: every number comes from BuildingAssessment.
#include "assess/report/building_report.hpp"

#include "assess/report/kinematic_report.hpp"
#include "assess/report/tie_report.hpp"

#include "report/report_heading.hpp"
#include "report/number_text.hpp"
#include "report/text_format.hpp"

#include <cmath>
#include <limits>

namespace assess {

namespace {

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// A number of the terminal tables: "∞" for an unbounded one (a collapse's D/C, an ag never reached), "-" undefined.
std::string fx(double v, int prec) {
  if (std::isnan(v)) return "-";
  if (!std::isfinite(v)) return v > 0 ? "∞" : "-∞";
  return format("%.*f", prec, v);
}

// TR_C/TR_D: a return period extrapolated beyond the grid's 30-2475 years is a bound, never a number (issue 28).
std::string tr_ratio(const SafetyIndex& s) {
  if (!s.TR_extrapolated) return fx(s.TR_ratio, 2);
  return s.TR_capacity > 2475.0 ? ">" + fx(2475.0 / s.TR_demand, 1) : "<" + fx(30.0 / s.TR_demand, 2);
}

std::string rstrip(std::string s) {
  while (!s.empty() && s.back() == ' ') s.pop_back();
  return s;
}

// Display width of a UTF-8 string (code points).
std::size_t width_of(const std::string& s) {
  std::size_t w = 0;
  for (unsigned char ch : s) w += (ch & 0xC0) != 0x80;
  return w;
}

std::string pad(const std::string& s, std::size_t n) {
  const std::size_t w = width_of(s);
  return w >= n ? s : s + std::string(n - w, ' ');
}

// Word-wraps one line within `width` columns, its leading blanks dropped,
// continuation lines indented by 4.
std::string wrap(const std::string& line, std::size_t width) {
  const std::size_t first = line.find_first_not_of(' ');
  return (first == std::string::npos ? std::string() : wrap_text(line.substr(first), 4, width)) + "\n";
}

using detail::code_name;

std::string approach_name(const std::string& a) {
  return a == "strength" ? "linear (strength)" : a == "displacement" ? "non-linear (displacement)" : "dynamic";
}

std::string record_set_text(const BuildingAssessment& b, const BuildingMechanism& m) {
  switch (m.record_set) {
    case RecordSetKind::none: return "-";
    case RecordSetKind::listed: return "listed";
    case RecordSetKind::shared: return m.record_group;
    case RecordSetKind::own: return "own";
  }
  (void)b;
  return "-";
}

// The tie rods of a mechanism in one state in a few words (issue 29): its
// first level's count, rod and anchor (a design gives every level the same),
// "+n lev." for the others; existing and new apart.
std::string tie_label(const TieInterventionResult& t, bool after) {
  if ((after ? t.levels : t.levels_before).empty()) return "-";
  std::string out;
  for (const TieGroup& g : tie_groups(t, after)) {
    const Tie* x = g.first;
    std::string s = std::string(g.existing ? "exist. " : "new ") + format("%dx ", x->layout.count) +
                    (x->rod.diameter > 0.0 ? format("diam. %.0f %s", x->rod.diameter * 1e3, x->rod.grade)
                                           : format("A %.0f mm2 %s", x->rod.area * 1e6, x->rod.grade));
    s += x->anchor.type == AnchorType::Plate
             ? format(", pl. %.0fx%.0fx%.0f", x->anchor.a * 1e3, x->anchor.b * 1e3, x->anchor.t * 1e3)
             : format(", bar %.0f", x->anchor.a * 1e3);
    if (g.levels > 1) s += format(" +%d lev.", g.levels - 1);
    out += (out.empty() ? "" : "; ") + s;
  }
  // Issue 37: the existing levels the design changed.
  if (after)
    for (const TieChange& c : t.changes)
      out += (out.empty() ? "" : "; ") + std::string("exist. ") +
             (c.kind == "removed" ? "removed" : c.kind == "anchor" ? "new anchor" : "new rod");
  if (after && t.designed && !t.found) out = "NOT FOUND (" + out + ")";
  return out;
}

// The dynamic check of the tied analyses, before or after: every restitution
// value satisfied ("ok"), not ("NO"), or no tied dynamics ("-").
std::string tie_dynamic_verdict(const TieInterventionResult& t, bool after) {
  if (!t.dynamics.applies || t.dynamics.summaries.empty()) return "-";
  for (const TieDynamicSummary& x : t.dynamics.summaries)
    if (!(after ? x.satisfied_after : x.satisfied_before)) return "NO";
  return "ok";
}

}  // namespace

nlohmann::json safety_indices_json(const std::vector<SafetyIndex>& indices) {
  nlohmann::json arr = nlohmann::json::array();
  for (const SafetyIndex& s : indices) {
    nlohmann::json j;
    j["code"] = s.code;
    j["approach"] = s.approach;
    j["dc"] = num(s.dc);
    // No failing check but some without a verdict: no verdict (issue 28).
    j["satisfied"] = s.failing == 0 && s.no_verdict > 0 ? nlohmann::json(nullptr) : nlohmann::json(s.satisfied);
    j["checks"] = s.checks;
    if (!s.dc_candidate.empty()) {  // the candidate whose check gives the D/C, and its alpha0 and a0* (issue 28)
      j["dc_candidate"] = s.dc_candidate;
      j["dc_alpha0"] = num(s.dc_alpha0);
      j["dc_a0_star"] = num(s.dc_a0_star);
    }
    j["failing"] = s.failing;
    j["no_verdict"] = s.no_verdict;
    j["defined"] = s.defined;
    if (s.defined) {
      j["limit_state"] = s.limit_state;
      j["location"] = s.location;
      j["candidate"] = s.candidate;
      j["ag_capacity_g"] = num(s.ag_capacity_g);
      j["ag_capacity_reached"] = std::isfinite(s.ag_capacity_g);
      j["ag_demand_g"] = num(s.ag_demand_g);
      j["zeta_E"] = num(s.zeta);
      j["TR_capacity_years"] = num(s.TR_capacity);
      j["TR_demand_years"] = num(s.TR_demand);
      j["TR_ratio"] = num(s.TR_ratio);
      j["TR_extrapolated"] = s.TR_extrapolated;
    }
    if (!s.note.empty()) j["note"] = s.note;
    arr.push_back(j);
  }
  return arr;
}

nlohmann::json building_json(const BuildingAssessment& b) {
  nlohmann::json j;
  const BuildingCase& bc = b.building;
  nlohmann::json bj;
  bj["project"] = bc.project;
  bj["file"] = bc.file;
  bj["site"] = b.site_description;
  bj["VR_years"] = b.VR;
  bj["TR_SLV_years"] = b.TR_SLV;
  bj["ag_SLV_g"] = b.ag_SLV_g;
  bj["record_selection"] = bc.record_selection;
  nlohmann::json sets = nlohmann::json::array();
  for (const SharedSelection& s : bc.selections) {
    nlohmann::json sj;
    sj["id"] = s.id;
    sj["period_range_s"] = {s.T_min, s.T_max};
    nlohmann::json members = nlohmann::json::array();
    for (std::size_t i : s.members) members.push_back(bc.mechanisms[i].id);
    sj["members"] = members;
    sj["fell_back"] = s.fell_back;
    if (!s.note.empty()) sj["note"] = s.note;
    sets.push_back(sj);
  }
  bj["record_sets"] = sets;
  j["building"] = bj;
  nlohmann::json ms = nlohmann::json::array();
  for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
    const BuildingMechanism& m = bc.mechanisms[i];
    const BuildingMechanismResult& r = b.results[i];
    const CandidateResult& gc = r.a.kinematic.candidates[r.a.kinematic.governing];
    nlohmann::json mj;
    mj["id"] = m.id;
    mj["wall"] = m.wall;
    mj["name"] = m.name;
    mj["json_path"] = m.json_path;
    mj["type"] = m.kase.mechanism.type;
    mj["alpha0"] = num(gc.result.alpha0);
    mj["a0_star_m_s2"] = num(gc.result.a0_star);
    mj["candidate"] = gc.label;
    nlohmann::json rs;
    rs["kind"] = to_string(m.record_set);
    if (!m.record_group.empty()) rs["set"] = m.record_group;
    if (r.a.dynamic && r.a.dynamic_applies) {
      rs["records"] = r.a.records.size();
      rs["period_range_s"] = {r.a.selection_range.T_min, r.a.selection_range.T_max};
    }
    mj["record_set"] = rs;
    mj["safety_indices"] = safety_indices_json(r.indices);
    if (const MethodVerdict* c = r.a.verdict.conclusion()) {
      nlohmann::json v;
      v["adopted"] = r.a.verdict.adopted;
      v["code"] = c->code;
      v["satisfied"] = c->satisfied && std::isfinite(c->max_dc);
      v["dc"] = num(c->max_dc);
      mj["conclusion"] = v;
    }
    // Issue 23: the mechanism's ties (as `assess run` of its case prints them)
    // and its zetaE / every-check verdict before and after them.
    nlohmann::json iv;
    iv["ties"] = !r.ties ? "none" : r.ties->designed ? "design" : r.ties->intervention ? "given" : "existing";
    iv["zeta_E_before"] = num(r.zeta_before);
    iv["zeta_E_after"] = num(r.zeta_after);
    iv["passes_before"] = r.passes_before;
    iv["passes_after"] = r.passes_after;
    mj["intervention"] = iv;
    if (r.ties) mj["ties"] = tie_json(*r.ties);
    mj["case"] = m.expanded;
    mj["assessment"] = facade_json(r.a);
    ms.push_back(mj);
  }
  j["mechanisms"] = ms;
  nlohmann::json gv = nlohmann::json::array();
  for (const BuildingGoverning& g : b.governing) {
    nlohmann::json x;
    x["code"] = g.code;
    x["approach"] = g.approach;
    if (g.mechanism >= 0) {
      x["mechanism"] = bc.mechanisms[std::size_t(g.mechanism)].id;
      x["name"] = bc.mechanisms[std::size_t(g.mechanism)].name;
    }
    x["zeta_E"] = num(g.zeta);
    x["dc"] = num(g.dc);
    x["assessed"] = g.assessed;
    x["satisfied"] = g.satisfied;
    x["failing"] = g.failing;
    x["no_verdict"] = g.no_verdict;
    gv.push_back(x);
  }
  j["governing"] = gv;
  // The building's verdict (issue 28): every mechanism by its adopted method.
  const BuildingVerdict& bv = b.verdict;
  nlohmann::json vj;
  vj["satisfied"] = bv.satisfied;
  vj["mechanisms"] = bv.mechanisms;
  nlohmann::json failing = nlohmann::json::array(), undecided = nlohmann::json::array();
  for (int i : bv.failing) failing.push_back(bc.mechanisms[std::size_t(i)].id);
  for (int i : bv.undecided) undecided.push_back(bc.mechanisms[std::size_t(i)].id);
  vj["failing"] = failing;
  vj["undecided"] = undecided;
  vj["zeta_E"] = num(bv.zeta);
  vj["zeta_E_mechanism"] = bv.zeta_mechanism >= 0 ? nlohmann::json(bc.mechanisms[std::size_t(bv.zeta_mechanism)].id) : nlohmann::json(nullptr);
  vj["max_dc"] = num(bv.max_dc);
  vj["max_dc_mechanism"] = bv.dc_mechanism >= 0 ? nlohmann::json(bc.mechanisms[std::size_t(bv.dc_mechanism)].id) : nlohmann::json(nullptr);
  j["verdict"] = vj;
  // The building's index before and after the ties (docs/theory/building.md §8).
  const BuildingTieIndex& ti = b.tie_index;
  nlohmann::json tj;
  tj["definition"] = "the smallest mechanism zeta_E (NTC 2018, each mechanism's adopted method: strength rows for "
                     "linear, displacement rows otherwise), in the stato di fatto (before: each mechanism with its "
                     "existing ties) and in the stato di progetto (after: with the new ties)";
  tj["any_ties"] = ti.any_ties;
  tj["zeta_E_before"] = num(ti.zeta_before);
  tj["zeta_E_after"] = num(ti.zeta_after);
  if (ti.mechanism_before >= 0) tj["mechanism_before"] = bc.mechanisms[std::size_t(ti.mechanism_before)].id;
  if (ti.mechanism_after >= 0) tj["mechanism_after"] = bc.mechanisms[std::size_t(ti.mechanism_after)].id;
  tj["passing_before"] = ti.passing_before;
  tj["passing_after"] = ti.passing_after;
  tj["mechanisms"] = bc.mechanisms.size();
  // The same, by state (issue 29): one index per state.
  for (const char* state : {"existing_state", "design_state"}) {
    const bool after = std::string(state) == "design_state";
    const int m = after ? ti.mechanism_after : ti.mechanism_before;
    tj[state] = {{"zeta_E", num(after ? ti.zeta_after : ti.zeta_before)},
                 {"mechanism", m >= 0 ? nlohmann::json(bc.mechanisms[std::size_t(m)].id) : nlohmann::json(nullptr)},
                 {"passing", after ? ti.passing_after : ti.passing_before}};
  }
  j["tie_index"] = tj;
  j["warnings"] = b.warnings;
  return j;
}

std::string building_text(const BuildingAssessment& b, TextWidth width) {
  const BuildingCase& bc = b.building;
  const bool wide = width == TextWidth::wide;
  std::string o;
  o += "BUILDING ASSESSMENT (local mechanisms, " + std::to_string(bc.mechanisms.size()) + " mechanisms)\n";
  if (!bc.project.empty()) o += "project: " + bc.project + "\n";
  o += "case file: " + bc.file + "\n";
  o += "site: " + b.site_description + "\n";
  o += "VR = " + fx(b.VR, 0) + " years; SLV: TR = " + fx(b.TR_SLV, 0) + " years, ag = " + fx(b.ag_SLV_g, 4) + " g\n";
  if (!bc.selections.empty() || bc.record_selection != "shared") {
    std::string rs = "record sets (" + bc.record_selection + "):";
    for (std::size_t k = 0; k < bc.selections.size(); ++k) {
      const SharedSelection& s = bc.selections[k];
      rs += std::string(k ? "; " : " ") + s.id + " = one selection over " + fx(s.T_min, 3) + "-" + fx(s.T_max, 3) +
            " s for";
      for (std::size_t i : s.members) rs += " " + bc.mechanisms[i].id;
      if (s.fell_back) rs += " (fell back: " + s.note + ")";
    }
    if (bc.selections.empty()) rs += " none shared; each mechanism selects over its own period range";
    o += wide ? rs + "\n" : wrap(rs, 120);
  }
  const std::string legend =
      "zetaE = PGA_C / PGA_D (ag on rock; the approach's governing check at SLV or SLC), TR_C / TR_D on the site's "
      "hazard curve; * governing mechanism of the approach (docs/theory/building.md)";
  o += "\n" + (wide ? legend + "\n" : wrap(legend, 120));
  // The mechanisms by id (the tables below name them by id only).
  o += "\nmechanisms\n";
  for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
    const BuildingMechanism& m = bc.mechanisms[i];
    const BuildingMechanismResult& r = b.results[i];
    std::string line = format("  %-4s ", m.id) + m.wall + ": " + m.name + " (" + m.kase.mechanism.type +
                       (m.json_path.empty() ? "" : ", " + m.json_path);
    if (r.a.dynamic && r.a.dynamic_applies)
      line += "; records " + record_set_text(b, m) + ": " + std::to_string(r.a.records.size()) + " over " +
              fx(r.a.selection_range.T_min, 3) + "-" + fx(r.a.selection_range.T_max, 3) + " s";
    else if (r.a.dynamic)
      line += "; dynamic analysis not applicable";
    line += ")";
    if (const MethodVerdict* c = r.a.verdict.conclusion())
      line += ": " + std::string(c->satisfied && std::isfinite(c->max_dc) ? "satisfied" : "NOT SATISFIED") + " (" +
              r.a.verdict.adopted + ", D/C " + fx(c->max_dc, 3) + ")";
    o += wide ? line + "\n" : wrap(line, 120);
  }
  // The building's verdict in one sentence (issue 28): every mechanism by its adopted method.
  {
    const BuildingVerdict& v = b.verdict;
    std::string failing;
    for (int i : v.failing) failing += (failing.empty() ? "" : ", ") + bc.mechanisms[std::size_t(i)].id;
    std::string line = "\nbuilding: " + std::string(v.satisfied ? "SATISFIED" : "NOT SATISFIED") + ": " +
                       std::to_string(v.mechanisms - int(v.failing.size()) - int(v.undecided.size())) + " of " +
                       std::to_string(v.mechanisms) + " mechanisms satisfy their adopted method" +
                       (failing.empty() ? "" : "; not satisfied: " + failing);
    if (v.zeta_mechanism >= 0)
      line += "; zetaE,building = " + fx(v.zeta, 3) + " (" + bc.mechanisms[std::size_t(v.zeta_mechanism)].id +
              ", the smallest zetaE of the adopted approaches)";
    o += wide ? line + "\n" : wrap(line, 120);
  }
  const std::size_t name_w = 0;
  for (const std::string& code : b.codes) {
    const bool y18 = code == "NTC2018";
    o += "\n" + code_name(code) + (y18 ? "" : " (for comparison)") + "\n";
    std::string head = format("%-4s ", "id") + pad("", name_w) +
                       format(" %7s %7s | %6s %6s %6s | %6s %6s %6s", "alpha0", "a0*", "D/C", "zetaE", "TRC/TRD", "D/C",
                              "zetaE", "TRC/TRD");
    if (y18) head += format(" | %6s  %-6s", "D/C", "rec");
    o += rstrip(head) + "\n";
    std::string units = format("%-4s ", "") + pad("", name_w) +
                        format(" %7s %7s | %-20s | %-20s", "-", "m/s2", "linear (strength)", "non-linear (displ.)");
    // (alpha0, a0*: of the linear D/C's candidate)
    if (y18) units += format(" | %-11s", "dynamic");
    o += rstrip(units) + "\n";
    std::vector<std::string> others;
    for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
      const BuildingMechanism& m = bc.mechanisms[i];
      const BuildingMechanismResult& r = b.results[i];
      const CandidateResult& gc = r.a.kinematic.candidates[r.a.kinematic.governing];
      auto cell = [&](const char* approach) {
        const SafetyIndex* s = r.index(code, approach);
        const BuildingGoverning* g = b.governing_of(code, approach);
        const std::string star = g && g->mechanism == int(i) ? "*" : " ";
        if (!s || !s->has_checks) return format(" %6s %6s %7s", "-", "-", "-");
        return " " + detail::pad(fx(s->dc, 3), 6) + " " + detail::pad(s->defined ? fx(s->zeta, 3) : "-", 6) + star +
               detail::pad(s->defined ? tr_ratio(*s) : "-", 7);
      };
      // alpha0 and a0* of the candidate whose check gives the linear D/C beside them (issue 28); the
      // non-linear D/C's candidate named under the table when it is another one.
      const SafetyIndex* lin = r.index(code, "strength");
      const SafetyIndex* nl = r.index(code, "displacement");
      const bool own = lin && !lin->dc_candidate.empty();
      std::string line = format("%-4s ", m.id) + pad("", name_w) +
                         format(" %7.4f %7.4f |", own ? lin->dc_alpha0 : gc.result.alpha0,
                                own ? lin->dc_a0_star : gc.result.a0_star) +
                         cell("strength") + " |" + cell("displacement");
      if (own && nl && !nl->dc_candidate.empty() && nl->dc_candidate != lin->dc_candidate)
        others.push_back(m.id + ": the non-linear D/C is of " + nl->dc_candidate + " (alpha0 " + fx(nl->dc_alpha0, 4) +
                         ", a0* " + fx(nl->dc_a0_star, 4) + " m/s2); the linear one of " + lin->dc_candidate);
      if (y18) {
        const SafetyIndex* s = r.index(code, "dynamic");
        const BuildingGoverning* g = b.governing_of(code, "dynamic");
        const std::string star = g && g->mechanism == int(i) ? "*" : " ";
        line += " |" + (s ? " " + detail::pad(fx(s->dc, 3), 6) + star : format(" %6s ", "-")) +
                format(" %-6s", record_set_text(b, m));
      }
      o += rstrip(line) + "\n";
    }
    for (const std::string& x : others) o += wide ? "  " + x + "\n" : wrap("  " + x, 120);
  }
  o += "\ngoverning mechanisms\n";
  for (const BuildingGoverning& g : b.governing) {
    const BuildingMechanism& m = bc.mechanisms[std::size_t(g.mechanism)];
    const SafetyIndex* s = b.results[std::size_t(g.mechanism)].index(g.code, g.approach);
    std::string line = "  " + code_name(g.code) + ", " + approach_name(g.approach) + ": " + m.id + " " + m.wall + ": " +
                       m.name;
    if (s && s->defined)
      line += ", zetaE = " + fx(s->zeta, 3) + " (PGA_C " + fx(s->ag_capacity_g, 4) + " g / PGA_D " +
              fx(s->ag_demand_g, 4) + " g, " + s->limit_state + "), TR_C = " +
              (s->TR_extrapolated ? (s->TR_capacity > 2475.0 ? "> 2475" : "< 30") : fx(s->TR_capacity, 0)) +
              " / TR_D = " + fx(s->TR_demand, 0) + " years" + (s->TR_extrapolated ? " (beyond the grid: a bound)" : "");
    else
      line += ", D/C = " + fx(g.dc, 3) + " (no zetaE: no PGA capacity)";
    line += "; " + std::to_string(g.satisfied) + " of " + std::to_string(g.assessed) + " satisfied, " +
            std::to_string(g.failing) + " not satisfied" +
            (g.no_verdict ? ", " + std::to_string(g.no_verdict) + " without verdict" : "");
    o += wide ? line + "\n" : wrap(line, 120);
  }
  // Issues 23, 29: the building in its stato di fatto (each mechanism with its
  // existing ties) and in its stato di progetto (with the new ties): one table
  // and one index per state; then each mechanism's ties in full.
  const BuildingTieIndex& ti = b.tie_index;
  if (ti.any_ties) {
    const std::string head =
        "tie rods: the building in its stato di fatto (existing ties part of the walls) and in its stato di progetto "
        "(with the new ties, given or designed): each mechanism's zetaE (NTC 2018, its adopted method's approach), "
        "every kinematic check and every check of its ties, and the dynamic check of its tied analyses "
        "(docs/theory/building.md §8)";
    o += "\n" + (wide ? head + "\n" : wrap(head, 120));
    auto yes = [](bool p) { return std::string(p ? "ok" : "NO"); };
    auto at = [&](int k) { return k >= 0 ? " (" + bc.mechanisms[std::size_t(k)].id + ")" : std::string(); };
    for (bool after : {false, true}) {
      o += std::string(after ? "stato di progetto" : "stato di fatto") + "\n";
      o += rstrip(format("%-4s %-52s | %7s | %6s | %6s", "id", after ? "ties (existing and new)" : "existing ties",
                         "zetaE", "checks", "dyn.")) +
           "\n";
      for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
        const BuildingMechanismResult& r = b.results[i];
        std::string label = r.ties ? tie_label(*r.ties, after) : "-";
        if (!wide && width_of(label) > 52) label = label.substr(0, 51) + "~";
        o += rstrip(format("%-4s ", bc.mechanisms[i].id) + pad(label, 52) +
                    format(" | %7s | %6s | %6s", fx(after ? r.zeta_after : r.zeta_before, 3),
                           yes(after ? r.passes_after : r.passes_before),
                           r.ties ? tie_dynamic_verdict(*r.ties, after) : "-")) +
             "\n";
      }
      const std::string idx = std::string("building index, ") + (after ? "stato di progetto" : "stato di fatto") +
                              " (the smallest mechanism zetaE): " + fx(after ? ti.zeta_after : ti.zeta_before, 3) +
                              at(after ? ti.mechanism_after : ti.mechanism_before) +
                              "; every check satisfied: " +
                              std::to_string(after ? ti.passing_after : ti.passing_before) + " of " +
                              std::to_string(bc.mechanisms.size()) + " mechanisms";
      o += wide ? idx + "\n" : wrap(idx, 120);
    }
    for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
      const BuildingMechanismResult& r = b.results[i];
      if (!r.ties) continue;
      const BuildingMechanism& m = bc.mechanisms[i];
      const std::string title = m.id + " " + m.wall + ": " + m.name + " (" + m.json_path + ")";
      o += "\n" + (wide ? title + "\n" : wrap(title, 120)) + tie_text(*r.ties).substr(1);
    }
  }
  if (!b.warnings.empty()) o += "\n" + std::to_string(b.warnings.size()) + " warnings (printed above; --json lists them)\n";
  o += "\neach mechanism in full: assess run " + bc.file + " --mechanism ID (or --json, --html)\n";
  return o;
}

}  // namespace assess
