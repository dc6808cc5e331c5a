// building_report.cpp: the building's JSON (issue 22): the assessment's own
// data. Formatting only: every number comes from BuildingAssessment.
#include "assess/report/building_report.hpp"

#include "assess/report/kinematic_report.hpp"
#include "assess/report/tie_report.hpp"
#include "assess/report/note_text.hpp"

#include "report/report_heading.hpp"
#include "report/number_text.hpp"
#include "report/text_format.hpp"

#include <cmath>
#include <limits>

namespace assess {

namespace {

nlohmann::json num(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

}  // namespace

nlohmann::json safety_indices_json(const std::vector<SafetyIndex>& indices) {
  nlohmann::json arr = nlohmann::json::array();
  for (const SafetyIndex& s : indices) {
    nlohmann::json j;
    j["code"] = s.code;
    j["approach"] = s.approach;
    j["dc"] = num(s.dc);
    add_outcome(j, s.outcome());  // no failing check but some without a verdict: no verdict (null)
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
      // The index of that check (kinematic/check_index.hpp): zeta_E, PGA_C, PGA_D, TR_C, TR_D ...
      j.update(to_json(s.index));
      j.erase("note");
    }
    if (!s.note.empty()) j["note"] = note_text(Lang::en, s.note);
    arr.push_back(j);
  }
  return arr;
}

namespace {

// The building: its file, site and the record sets its mechanisms share.
nlohmann::json building_part_json(const BuildingAssessment& b) {
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
    if (!s.note.empty()) sj["note"] = note_text(Lang::en, s.note);
    sets.push_back(sj);
  }
  bj["record_sets"] = sets;
  return bj;
}

// One mechanism: its identity, governing candidate, record set, indices, conclusion, ties and whole assessment.
nlohmann::json mechanism_json(const BuildingMechanism& m, const BuildingMechanismResult& r) {
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
  if (r.a.dynamics.spec && r.a.dynamics.applies) {
    rs["records"] = r.a.dynamics.records.size();
    rs["period_range_s"] = {r.a.selection.range.T_min, r.a.selection.range.T_max};
    // The records it used (issue 41: a mechanism alone is its building line).
    nlohmann::json used = nlohmann::json::array();
    for (const RecordUsed& u : r.a.dynamics.records) used.push_back({{"name", u.name}, {"file", u.file}, {"scale", u.scale}});
    rs["used"] = used;
  }
  mj["record_set"] = rs;
  mj["safety_indices"] = safety_indices_json(r.a.indices);
  if (const MethodVerdict* c = r.a.verdict.conclusion()) {
    nlohmann::json v;
    v["adopted"] = r.a.verdict.adopted;
    v["code"] = c->code;
    add_outcome(v, c->outcome());
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
  return mj;
}

// The governing mechanism of each code and approach.
nlohmann::json governing_json(const BuildingAssessment& b) {
  const BuildingCase& bc = b.building;
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
    x["satisfied_count"] = g.satisfied;
    x["failing"] = g.failing;
    x["no_verdict"] = g.no_verdict;
    gv.push_back(x);
  }
  return gv;
}

// A mechanism's id by its index, null for none (-1).
nlohmann::json mechanism_id(const BuildingCase& bc, int i) {
  return i >= 0 ? nlohmann::json(bc.mechanisms[std::size_t(i)].id) : nlohmann::json(nullptr);
}

// The building's verdict (issue 28): every mechanism by its adopted method.
nlohmann::json verdict_json(const BuildingAssessment& b) {
  const BuildingCase& bc = b.building;
  const BuildingVerdict& bv = b.verdict;
  nlohmann::json vj;
  add_outcome(vj, bv.outcome());  // null without a verdict (issue 41): "undecided" says which
  vj["mechanisms"] = bv.mechanisms;
  nlohmann::json failing = nlohmann::json::array(), undecided = nlohmann::json::array();
  for (int i : bv.failing) failing.push_back(bc.mechanisms[std::size_t(i)].id);
  for (int i : bv.undecided) undecided.push_back(bc.mechanisms[std::size_t(i)].id);
  vj["failing"] = failing;
  vj["undecided"] = undecided;
  vj["zeta_E"] = num(bv.zeta);
  vj["zeta_E_mechanism"] = mechanism_id(bc, bv.zeta_mechanism);
  vj["max_dc"] = num(bv.max_dc);
  vj["max_dc_mechanism"] = mechanism_id(bc, bv.dc_mechanism);
  return vj;
}

// The building's index before and after the ties (docs/theory/building.md §8).
nlohmann::json tie_index_json(const BuildingAssessment& b) {
  const BuildingCase& bc = b.building;
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
    tj[state] = {{"zeta_E", num(after ? ti.zeta_after : ti.zeta_before)},
                 {"mechanism", mechanism_id(bc, after ? ti.mechanism_after : ti.mechanism_before)},
                 {"passing", after ? ti.passing_after : ti.passing_before}};
  }
  return tj;
}

}  // namespace

nlohmann::json building_json(const BuildingAssessment& b) {
  nlohmann::json j;
  j["building"] = building_part_json(b);
  nlohmann::json ms = nlohmann::json::array();
  for (std::size_t i = 0; i < b.building.mechanisms.size(); ++i)
    ms.push_back(mechanism_json(b.building.mechanisms[i], b.results[i]));
  j["mechanisms"] = ms;
  j["governing"] = governing_json(b);
  j["verdict"] = verdict_json(b);
  j["tie_index"] = tie_index_json(b);
  j["warnings"] = b.warnings;
  return j;
}

}  // namespace assess
