// facade_report.cpp: text, JSON and HTML reports of a façade assessment.
#include "assess/report/facade_report.hpp"

#include "report/number_text.hpp"
#include "report/text_format.hpp"

#include "assess/hazard/comuni.hpp"
#include "assess/report/kinematic_report.hpp"
#include "assess/report/note_text.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>

namespace assess {

namespace {

constexpr double g = units::g;
using detail::number_text;

const CandidateResult& governing(const FacadeAssessment& a) {
  return a.kinematic.candidates[a.kinematic.governing];
}

// JSON has no infinity: an unbounded or undefined figure is null (its meaning beside it).
nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

// The site, its limit states and their spectra's parameters.
nlohmann::json site_json(const FacadeAssessment& a) {
  const SiteSpec& sp = *a.kase.site;
  nlohmann::json s{{"description", a.site.description}, {"soil", to_string(sp.conditions.soil)},
                   {"topography", to_string(sp.conditions.topography)}, {"VN", sp.vn_years}, {"CU", sp.cu},
                   {"VR", a.site.VR}};
  nlohmann::json ls_arr = nlohmann::json::array();
  for (const auto& [ls, act] : a.site.actions) {
    const ElasticSpectrum& e = a.site.spectra.at(ls);
    ls_arr.push_back({{"limit_state", to_string(ls)}, {"PVR", act.PVR}, {"TR", act.TR}, {"ag_g", e.ag_g()},
                      {"F0", e.F0()}, {"Tc_star", e.Tc_star()}, {"SS", e.SS()}, {"CC", e.CC()}, {"ST", e.ST()},
                      {"S", e.S()}, {"TB", e.TB()}, {"TC", e.TC()}, {"TD", e.TD()}});
  }
  s["limit_states"] = ls_arr;
  return s;
}

// The dynamic model: a rocking body or a chain, ties, base motion and floor filter.
nlohmann::json dynamic_model_json(const FacadeAssessment& a) {
  const MechanismDynamics& md = *a.dynamics.mechanism;
  nlohmann::json model;
  if (a.dynamics.model) {
    const RockingBody& b = a.dynamics.body->body;
    const RockingModel& m = *a.dynamics.model;
    model = {{"type", a.dynamics.spec->smooth ? "smooth" : "rigid"},
             {"k_kN_m3", a.dynamics.spec->smooth ? nlohmann::json(a.dynamics.spec->k / units::kN) : nlohmann::json(nullptr)},
             {"sidedness", m.sidedness() == Sidedness::one_sided ? "one-sided" : "two-sided"},
             {"polarity", to_string(a.dynamics.spec->polarity)},
             {"W_kN_m", b.W / units::kN}, {"b", b.b}, {"R", b.R}, {"alpha", b.alpha}, {"I0", b.I0},
             {"M_ext_kNm_m", b.M_ext / units::kN},
             {"theta_cr", a.dynamics.spec->smooth ? nlohmann::json(m.theta_cr()) : nlohmann::json(nullptr)},
             {"theta_u", m.theta_u(+1)}, {"peak_moment_kNm_m", m.peak_moment(+1) / units::kN},
             {"capacity_kJ_m", m.capacity() / units::kN}};
  } else {
    const ChainDynamics& c = *md.chain;
    model = {{"type", a.dynamics.spec->smooth ? "smooth" : "rigid"},
             {"k_kN_m3", a.dynamics.spec->smooth ? nlohmann::json(a.dynamics.spec->k / units::kN) : nlohmann::json(nullptr)},
             {"sidedness", md.sidedness == Sidedness::two_sided ? "two-sided" : "one-sided"},
             {"polarity", to_string(a.dynamics.spec->polarity)},
             {"chain_blocks", c.chain().blocks().size()},
             {"M0_kg_m2", c.mass(0.0)}, {"B0_kg_m", c.coupling(0.0)},
             {"theta_cr", a.dynamics.spec->smooth ? nlohmann::json(c.q_cr()) : nlohmann::json(nullptr)},
             {"theta_u", c.q_u()}, {"capacity_kJ_m", c.capacity() / md.length / units::kN}};
  }
  if (md.tied_envelope)  // the ties at their strength (docs/theory/ties.md §6)
    model["tied"] = {{"levels", md.ties.size()},
                     {"theta_collapse", md.q_u()},
                     {"capacity_kJ_m", md.capacity() / units::kN}};
  model["kind"] = md.single_body() ? "rocking body" : "chain";
  model["Z"] = md.Z;
  model["input"] = md.floor_input ? "floor motions given" : md.filter ? "floor motions (first-mode filter)" : "ground motions";
  if (md.filter)
    model["floor_filter"] = {{"T1_s", md.filter->T1}, {"damping_pct", md.filter_damping_pct},
                             {"gamma_psi", md.filter->gamma_psi}};
  return model;
}

// Notes in English, as the JSON gives them (issue 41: the notes are data, note.hpp).
template <class N>
std::vector<std::string> english(const std::vector<N>& notes) {
  std::vector<std::string> out;
  for (const N& n : notes) out.push_back(note_text(Lang::en, n));
  return out;
}

// The records used, with their metadata.
nlohmann::json records_json(const FacadeAssessment& a) {
  nlohmann::json recs = nlohmann::json::array();
  for (const RecordUsed& r : a.dynamics.records)
    recs.push_back({{"name", r.name}, {"file", r.file}, {"event", r.event}, {"station", r.station},
                    {"component", r.component}, {"positive_direction", r.positive_direction},
                    {"scale", r.scale}, {"pga_g", r.pga / g},
                    {"Mw", std::isfinite(r.Mw) ? nlohmann::json(r.Mw) : nlohmann::json(nullptr)},
                    {"distance_km", std::isfinite(r.distance_km) ? nlohmann::json(r.distance_km) : nlohmann::json(nullptr)},
                    {"distance_kind", r.distance_kind}, {"site_class", r.site_class},
                    {"deviation", std::isfinite(r.deviation) ? nlohmann::json(r.deviation) : nlohmann::json(nullptr)},
                    {"rank", r.rank}, {"duration_s", r.duration_s}, {"integrated_s", r.integrated_s},
                    {"in_catalogue", r.in_catalogue}, {"date", r.date}, {"country", r.country},
                    {"station_code", r.station_code},
                    {"vs30_m_s", std::isfinite(r.vs30_m_s) ? nlohmann::json(r.vs30_m_s) : nlohmann::json(nullptr)},
                    {"site_class_basis", r.site_class_basis}, {"vs30_class", r.vs30_class},
                    {"usable_period_s", std::isfinite(r.usable_period_s) ? nlohmann::json(r.usable_period_s)
                                                                         : nlohmann::json(nullptr)},
                    {"pulse", r.pulse}, {"near_fault", r.near_fault}, {"misfit_flag", r.misfit_flag},
                    {"flags", english(r.flags)}});
  return recs;
}

// The record selection: its status, rules, limits and spectra (a.selection.result given).
nlohmann::json selection_json(const FacadeAssessment& a) {
  return {{"status", to_string(a.selection.result->status)},
                    {"T_min", a.selection.range.T_min},
                    {"T_max", a.selection.range.T_max},
                    {"min_ratio", a.selection.result->min_ratio},
                    {"max_ratio", a.selection.result->max_ratio},
                    {"band_satisfied", a.selection.result->band_satisfied},
                    {"message", a.selection.result->message},
                    {"limit_state", a.selection.limit_state},
                    {"mechanism_periods_s", {a.selection.T_first, a.selection.T_last}},
                    {"band", {1.0 - 0.10, 1.0 + 0.30}},
                    {"candidates", a.selection.candidates},
                    {"eligible", a.selection.result->eligible},
                    {"combinations", a.selection.result->combinations},
                    {"site_classes", a.selection.site_classes},
                    {"site_class_steps", english(a.selection.steps)},
                    {"warnings", a.selection.warnings},
                    {"range_note", note_text(Lang::en, a.selection.range_note)},
                    {"shared_note", note_text(Lang::en, a.selection.shared_note)},
                    {"spectra", a.selection.spectra},
                    {"max_scale", a.selection.max_scale},
                    {"max_mean_scale", a.selection.max_mean_scale},
                    {"max_misfit", a.selection.max_misfit},
                    {"include_near_fault", a.selection.include_near_fault},
                    {"near_fault_km", a.selection.near_fault_km},
                    {"near_fault_excluded", a.selection.near_fault_excluded},
                    {"mean_scale", a.selection.result->mean_scale},
                    {"max_scaled_pga_g", a.selection.result->max_scaled_pga / g},
                    {"max_pga_ratio", a.selection.max_pga_ratio},
                    {"target_pga_g", a.selection.result->target_pga / g},
                    {"periods_s", a.selection.result->periods},
                    {"target_m_s2", a.selection.result->target},
                    {"mean_psa_m_s2", a.selection.result->mean_psa},
                    {"record_psa_m_s2", [&] {
                       nlohmann::json rp = nlohmann::json::array();
                       for (const auto& sr : a.selection.result->records) rp.push_back(sr.psa);
                       return rp;
                     }()}};
}

// Each analysis: record, polarity, restitution, peak rotation, d*, end, and the ties' outcome.
nlohmann::json analyses_json(const FacadeAssessment& a) {
  nlohmann::json runs = nlohmann::json::array();
  for (const DynamicRun& r : a.dynamics.runs) {
    runs.push_back({{"record", a.dynamics.records[r.record].name},
                    {"scale", a.dynamics.records[r.record].scale},
                    {"reversed", r.reversed},
                    {"restitution", r.e},
                    {"theta_max", r.result.theta_max},
                    {"t_theta_max", r.result.t_theta_max},
                    {"theta_u", r.result.theta_u},
                    {"theta_ratio", r.theta_ratio},
                    {"overturned", r.result.overturned},
                    {"t_overturn", r.result.t_overturn ? nlohmann::json(*r.result.t_overturn) : nlohmann::json(nullptr)},
                    {"impacts", r.result.impacts},
                    {"dc", r.result.dc},
                    {"energy_demand_kJ_m", r.result.energy_demand / units::kN},
                    {"capacity_kJ_m", r.result.capacity / units::kN},
                    {"d_control", r.d_control},
                    {"d_star", r.d_star},
                    {"collapse", r.collapse},
                    {"termination", to_string(r.result.termination)},
                    {"end", to_string(r.result.end)},
                    {"t_end", r.result.t_end},
                    {"motion_duration_s", r.result.motion_duration},
                    {"failed", !succeeded(r.result)}});
    if (r.result.ties.empty()) continue;
    // A wall held by tie rods: each level's outcome (body: per metre of wall; chain: the whole level).
    nlohmann::json lv = nlohmann::json::array();
    for (const TiedLevelResult& x : r.result.ties)
      lv.push_back({{"max_force_kN", x.max_force / units::kN},
                    {"max_elongation_mm", x.max_elongation * 1e3},
                    {"yielded", x.yielded},
                    {"plastic_elongation_mm", x.plastic_elongation * 1e3},
                    {"plastic_energy_kJ", x.plastic_energy / units::kN},
                    {"broken", x.broken},  // issue 29: the level broke (its force lost from then on)
                    {"broken_by_elongation", x.broken_by_elongation},
                    {"t_broken_s", x.broken ? nlohmann::json(x.t_broken) : nlohmann::json(nullptr)}});
    runs.back()["ties"] = lv;
    runs.back()["ties_per"] = a.dynamics.mechanism && a.dynamics.mechanism->single_body() ? "m of wall" : "level";
    runs.back()["rod_broken"] = r.ruptured;
  }
  return runs;
}

// The summary per restitution coefficient (Circ. 2019 C8.7.1.2.1.9).
nlohmann::json summaries_json(const FacadeAssessment& a) {
  nlohmann::json sums = nlohmann::json::array();
  for (const RestitutionSummary& s : a.dynamics.summaries)
    sums.push_back({{"restitution", describe(a.dynamics.spec->restitutions[s.restitution])},
                    {"e", s.e},
                    {"failed", s.failed},
                    {"analyses", s.analyses},
                    {"overturned", s.overturned},
                    {"rod_broken", s.ruptured},
                    {"mean_dc", s.mean_dc},
                    {"min_dc", s.min_dc},
                    {"max_dc", s.max_dc},
                    {"mean_theta_ratio", s.mean_theta_ratio},
                    {"mean_d_star", s.mean_d_star},
                    {"d_SLV", governing(a).result.d_SLV},
                    {"max_d_star", s.max_d_star},
                    {"records", s.records},
                    {"rule", s.rule},
                    {"d_demand", finite_or_null(s.d_demand)},
                    {"dc_slv", finite_or_null(s.dc_slv)},
                    {"collapsed", s.collapsed},
                    {"energy_dc", finite_or_null(s.energy_dc)},
                    {"mean_dc_survivors", finite_or_null(s.mean_dc_survivors)},
                    {"records_survived", s.records_survived},
                    {"d_demand_survivors", finite_or_null(s.d_demand_survivors)},
                    {"dc_survivors", finite_or_null(s.dc_survivors)},
                    {"any_collapse", s.any_collapse},
                    {"no_verdict", s.no_verdict},
                    {"slv_satisfied", s.no_verdict ? nlohmann::json(nullptr) : nlohmann::json(s.slv_satisfied)}});
  return sums;
}

}  // namespace

// ------------------------------------------------------------------ JSON

nlohmann::json facade_json(const FacadeAssessment& a) {
  nlohmann::json j;
  j["project"] = a.kase.project;
  j["case_file"] = a.kase.file;
  // Every value the case did not give that moves a result (issue 41).
  nlohmann::json defaults = nlohmann::json::array();
  for (const CaseDefault& x : assessment_defaults(a))
    defaults.push_back({{"path", x.path}, {"value", x.value}, {"effect", msg(Lang::en, x.effect)}});
  j["defaults"] = defaults;
  // The adopted verdict under the readings a verificatore questions first (sensitivity.hpp).
  nlohmann::json sens = nlohmann::json::array();
  for (const SensitivityRow& r : a.sensitivity)
    sens.push_back({{"parameter", r.parameter}, {"value", r.value}, {"adopted", r.adopted},
                    {"dc", finite_or_null(r.dc)}, {"satisfied", r.satisfied}});
  j["sensitivity"] = sens;
  if (a.kase.site) j["site"] = site_json(a);
  j["kinematic"] = kinematic_json(a.kase, a.kinematic);
  // The run's summary (with the dynamic rows) is the top-level "comparison"
  // and "overall"; the kinematic-only one would be a second, partial verdict.
  j["kinematic"].erase("summary");
  j["kinematic"].erase("warnings");
  nlohmann::json checks = nlohmann::json::array();
  for (const CheckRow& c : a.checks) checks.push_back(to_json(c));
  j["checks"] = checks;
  if (a.dynamics.spec) {
    nlohmann::json d;
    d["applies"] = a.dynamics.applies;
    d["note"] = note_text(Lang::en, a.dynamics.note);
    if (a.dynamics.applies) {
      d["model"] = dynamic_model_json(a);
      if (!a.curves.code_floor_Se.empty())
        d["floor_spectra"] = {{"periods_s", a.curves.periods}, {"floor_mean_psa_m_s2", a.curves.floor_mean_psa},
                              {"code_floor_Se_m_s2", a.curves.code_floor_Se}};
      d["records"] = records_json(a);
      d["record_failures"] = a.selection.record_failures;
      if (a.dynamics.compatibility.computed)
        d["compatibility"] = {{"T_min", a.dynamics.compatibility.range.T_min},
                              {"T_max", a.dynamics.compatibility.range.T_max},
                              {"min_ratio", a.dynamics.compatibility.min_ratio},
                              {"max_ratio", a.dynamics.compatibility.max_ratio},
                              {"band_satisfied", a.dynamics.compatibility.band_satisfied},
                              {"message", note_text(Lang::en, a.dynamics.compatibility.message)}};
      if (a.selection.result) d["selection"] = selection_json(a);
      d["duration"] = {{"whole_record", true},
                       {"free_motion_cap_s", a.dynamics.free_tail_s},
                       {"free_energy_fraction", free_energy_fraction}};
      d["analyses"] = analyses_json(a);
      d["summary"] = summaries_json(a);
    }
    // The other candidates' dynamic analyses (issue 24): the "dynamic" object
    // of each one's own assessment (the case restricted to that candidate).
    nlohmann::json others = nlohmann::json::array();
    for (std::size_t k = 0; k < a.other_dynamics.size(); ++k) {
      const std::size_t ci = a.other_dynamics_candidate[k];
      others.push_back({{"candidate", a.kinematic.candidates[ci].label},
                        {"candidate_index", ci},
                        {"dynamic", facade_json(a.other_dynamics[k])["dynamic"]}});
    }
    d["other_candidates"] = others;
    j["dynamic"] = d;
  }
  const nlohmann::json v = to_json(a.verdict);
  j["comparison"] = v["by_approach"];
  j["overall"] = v["overall"];
  nlohmann::json energy = nlohmann::json::array();
  for (const CheckRow& r : a.dynamics.energy_rows) energy.push_back(to_json(r));
  j["energy"] = energy;
  j["warnings"] = a.warnings;
  return j;
}

}  // namespace assess
