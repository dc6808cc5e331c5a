// facade_report.cpp: text, JSON and HTML reports of a façade assessment.
#include "assess/report/facade_report.hpp"

#include "assess/hazard/comuni.hpp"
#include "assess/report/kinematic_report.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>

namespace assess {

namespace {

constexpr double g = units::g;

const CandidateResult& governing(const FacadeAssessment& a) {
  return a.kinematic.candidates[a.kinematic.governing];
}

std::string record_label(const FacadeAssessment& a, const DynamicRun& r) {
  return a.records[r.record].name + (r.reversed ? " (reversed)" : "");
}

// One value per approach, seed Eq. 8 and Fig. 8.
struct Approach {
  std::string name;
  double dc;
};

std::vector<Approach> comparison(const FacadeAssessment& a) {
  std::vector<Approach> out;
  for (const CheckRow& c : a.checks) {
    if (c.limit_state != "SLV" || c.location != "ground") continue;
    if (c.kind == "dynamic") continue;
    out.push_back({c.code + " SLV " + c.kind, c.dc});
  }
  if (a.dynamic) {
    for (const RestitutionSummary& s : a.summaries) {
      const std::string e = describe(a.dynamic->restitutions[s.restitution]);
      out.push_back({"dynamic energy D/C, " + e, s.mean_dc});
      out.push_back({"dynamic C8.7.1.2.1.9, " + e, s.dc_slv});
    }
  }
  return out;
}

}  // namespace

// ------------------------------------------------------------------ text

std::string facade_text(const FacadeAssessment& a, TextWidth width) {
  const bool wide = width == TextWidth::wide;
  // Long prose lines wrapped to 120 columns (continuation indented by `ind`).
  auto para = [&](const std::string& line, std::size_t ind) { return wide ? line : wrap_text(line, ind); };
  std::string o;
  o += format("assess run: %s\n", a.kase.file.c_str());
  if (!a.kase.project.empty()) o += format("project: %s\n", a.kase.project.c_str());
  if (a.kase.site) {
    const SiteSpec& sp = *a.kase.site;
    o += "\n== Site and seismic action (NTC 2018 §2.4, §3.2) ==\n";
    o += para(format("site: %s; soil %s, topography %s; VN = %.0f years, CU = %.2f, VR = %.1f years",
                     a.site_description.c_str(), to_string(sp.conditions.soil).c_str(),
                     to_string(sp.conditions.topography).c_str(), sp.vn_years, sp.cu, a.VR),
                6) +
         "\n";
    if (!sp.comune.empty()) o += "note: " + comune_note() + "\n";
    o += format("  %-4s %8s %9s %8s %7s %7s %6s %6s %6s %6s %6s %6s %6s\n", "LS", "P_VR %", "TR (yr)", "ag (g)", "F0",
                "TC* s", "SS", "CC", "ST", "S", "TB s", "TC s", "TD s");
    for (const auto& [ls, act] : a.actions) {
      const ElasticSpectrum& s = a.spectra.at(ls);
      o += format("  %-4s %8.0f %9.2f %8.4f %7.4f %7.4f %6.3f %6.3f %6.3f %6.3f %6.3f %6.3f %6.3f\n",
                  to_string(ls).c_str(), act.PVR * 100, act.TR, s.ag_g(), s.F0(), s.Tc_star(), s.SS(), s.CC(), s.ST(),
                  s.S(), s.TB(), s.TC(), s.TD());
    }
  }
  o += "\n== Kinematic analysis (Circ. 617/2009 C8A.4; Circ. 7/2019 C8.7.1) ==\n";
  KinematicCaseResult kin = a.kinematic;
  kin.checks.clear();
  std::string kt = kinematic_text(a.kase, kin, width);
  const auto cut = kt.find("\nno site in the case");
  if (cut != std::string::npos) kt.erase(cut);
  o += kt;
  if (!a.checks.empty()) o += "\n== Checks ==\n" + checks_text(a.checks, width);

  if (a.dynamic) {
    o += "\n== Non-linear dynamic analysis (rocking; seed Eq. 1; Circ. 2019 C8.7.1.2.1.9) ==\n";
    if (!a.dynamic_applies) {
      o += "not applicable: " + a.dynamic_note + "\n";
    } else {
      const RockingBody& b = a.body->body;
      const RockingModel& m = *a.model;
      o += para(format("model: %s, %s; W = %.3f kN/m, b = %.4f m, R = %.4f m, alpha = %.5f rad, I0 = %.2f kg m2/m, "
                  "M_ext = %.3f kN m/m",
                  a.dynamic->smooth ? "smooth block on a Winkler foundation" : "rigid (Housner) block",
                  m.sidedness() == Sidedness::one_sided ? "one-sided" : "two-sided", b.W / units::kN, b.b, b.R,
                  b.alpha, b.I0, b.M_ext / units::kN), 7) + "\n";
      std::string line = "       ";
      if (a.dynamic->smooth)
        line += format("k = %.4g kN/m3, theta_cr = %.3e rad, ", a.dynamic->k / units::kN, m.theta_cr());
      line += format("theta_u = %.5f rad, peak moment %.3f kN m/m, energy capacity %.4f kJ/m", m.theta_u(+1),
                     m.peak_moment(+1) / units::kN, m.capacity() / units::kN);
      o += para(line, 7) + "\n";
      if (a.selection) {
        o += para(format("records: %d selected from the catalogue, compatible with the SLV spectrum (5 %%) over "
                         "%.2f-%.2f s: %s",
                         int(a.records.size()), a.selection_range.T_min, a.selection_range.T_max,
                         a.selection->message.c_str()),
                  9) +
             "\n";
      }
      for (const std::string& f : a.record_failures) o += "  record skipped: " + f + "\n";
      const int rw = wide ? 34 : 32;  // record column
      o += format("  %-*s %7s %9s  %-18s\n", rw, "record", "scale", "PGA (g)", "event / station");
      for (const RecordUsed& r : a.records)
        o += para(format("  %-*s %7.3f %9.4f  %s / %s", rw, r.name.c_str(), r.scale, r.pga / g, r.event.c_str(),
                         r.station.c_str()),
                  rw + 22) +
             "\n";
      o += format(wide ? "\n  %-*s %-18s %9s %7s %9s %8s %8s %10s  %s\n" : "\n  %-*s %-12s %7s %7s %8s %7s %7s %9s  %s\n",
                  rw, "record", "restitution", "th/th_u", "impacts", "overturn", "energy", "d* (m)", "t_end (s)",
                  "termination");
      for (const DynamicRun& r : a.runs)
        o += format(wide ? "  %-*s %-18s %9.4f %7ld %9s %8.4f %8.4f %10.3f  %s\n"
                         : "  %-*s %-12s %7.4f %7ld %8s %7.4f %7.4f %9.3f  %s\n",
                    rw, record_label(a, r).c_str(),
                    describe(a.dynamic->restitutions[r.restitution]).c_str(), r.theta_ratio, r.result.impacts,
                    r.result.overturned ? "yes" : "no", r.result.dc, r.d_star, r.result.t_end,
                    to_string(r.result.termination));
      o += "\n" + para(format("  summary per restitution (energy D/C = demand/capacity, seed §3.2; Circ. 2019 "
                              "acceptance: d0 never exceeded and mean peak d* <= d_SLV = %.4f m):",
                              governing(a).result.d_SLV),
                       4) +
           "\n";
      o += format(wide ? "  %-18s %6s %6s %10s %10s %10s %12s %8s  %s\n" : "  %-12s %5s %6s %9s %9s %9s %11s %7s  %s\n",
                  "restitution", "runs", "overt.", "mean D/C", "max D/C", "mean th/u", "mean d* (m)", "D/C d*",
                  "verdict (C8.7.1.2.1.9)");
      for (const RestitutionSummary& s : a.summaries)
        o += format(wide ? "  %-18s %6d %6d %10.4f %10.4f %10.4f %12.4f %8.3f  %s\n"
                         : "  %-12s %5d %6d %9.4f %9.4f %9.4f %11.4f %7.3f  %s\n",
                    describe(a.dynamic->restitutions[s.restitution]).c_str(), s.analyses, s.overturned, s.mean_dc,
                    s.max_dc, s.mean_theta_ratio, s.mean_d_star, s.dc_slv, verdict(s.slv_satisfied));
    }
  }
  const std::vector<Approach> cmp = comparison(a);
  if (!cmp.empty()) {
    o += "\n== Demand/capacity by approach (SLV, seed Fig. 8) ==\n";
    for (const Approach& x : cmp)
      o += format("  %-48s D/C = %7.3f  %s\n", x.name.c_str(), x.dc, x.dc <= 1 ? "<= 1" : "> 1");
  }
  return o;
}

// ------------------------------------------------------------------ JSON

nlohmann::json facade_json(const FacadeAssessment& a) {
  nlohmann::json j;
  j["project"] = a.kase.project;
  j["case_file"] = a.kase.file;
  if (a.kase.site) {
    const SiteSpec& sp = *a.kase.site;
    nlohmann::json s{{"description", a.site_description}, {"soil", to_string(sp.conditions.soil)},
                     {"topography", to_string(sp.conditions.topography)}, {"VN", sp.vn_years}, {"CU", sp.cu},
                     {"VR", a.VR}};
    nlohmann::json ls_arr = nlohmann::json::array();
    for (const auto& [ls, act] : a.actions) {
      const ElasticSpectrum& e = a.spectra.at(ls);
      ls_arr.push_back({{"limit_state", to_string(ls)}, {"PVR", act.PVR}, {"TR", act.TR}, {"ag_g", e.ag_g()},
                        {"F0", e.F0()}, {"Tc_star", e.Tc_star()}, {"SS", e.SS()}, {"CC", e.CC()}, {"ST", e.ST()},
                        {"S", e.S()}, {"TB", e.TB()}, {"TC", e.TC()}, {"TD", e.TD()}});
    }
    s["limit_states"] = ls_arr;
    j["site"] = s;
  }
  j["kinematic"] = kinematic_json(a.kase, a.kinematic);
  nlohmann::json checks = nlohmann::json::array();
  for (const CheckRow& c : a.checks) checks.push_back(to_json(c));
  j["checks"] = checks;
  if (a.dynamic) {
    nlohmann::json d;
    d["applies"] = a.dynamic_applies;
    d["note"] = a.dynamic_note;
    if (a.dynamic_applies) {
      const RockingBody& b = a.body->body;
      const RockingModel& m = *a.model;
      d["model"] = {{"type", a.dynamic->smooth ? "smooth" : "rigid"},
                    {"k_kN_m3", a.dynamic->smooth ? nlohmann::json(a.dynamic->k / units::kN) : nlohmann::json(nullptr)},
                    {"sidedness", m.sidedness() == Sidedness::one_sided ? "one-sided" : "two-sided"},
                    {"polarity", to_string(a.dynamic->polarity)},
                    {"W_kN_m", b.W / units::kN}, {"b", b.b}, {"R", b.R}, {"alpha", b.alpha}, {"I0", b.I0},
                    {"M_ext_kNm_m", b.M_ext / units::kN},
                    {"theta_cr", a.dynamic->smooth ? nlohmann::json(m.theta_cr()) : nlohmann::json(nullptr)},
                    {"theta_u", m.theta_u(+1)}, {"peak_moment_kNm_m", m.peak_moment(+1) / units::kN},
                    {"capacity_kJ_m", m.capacity() / units::kN}};
      nlohmann::json recs = nlohmann::json::array();
      for (const RecordUsed& r : a.records)
        recs.push_back({{"name", r.name}, {"file", r.file}, {"event", r.event}, {"station", r.station},
                        {"component", r.component}, {"scale", r.scale}, {"pga_g", r.pga / g}});
      d["records"] = recs;
      d["record_failures"] = a.record_failures;
      if (a.selection)
        d["selection"] = {{"status", to_string(a.selection->status)},
                          {"T_min", a.selection_range.T_min},
                          {"T_max", a.selection_range.T_max},
                          {"min_ratio", a.selection->min_ratio},
                          {"max_ratio", a.selection->max_ratio},
                          {"band_satisfied", a.selection->band_satisfied},
                          {"message", a.selection->message}};
      nlohmann::json runs = nlohmann::json::array();
      for (const DynamicRun& r : a.runs)
        runs.push_back({{"record", a.records[r.record].name},
                        {"scale", a.records[r.record].scale},
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
                        {"termination", to_string(r.result.termination)}});
      d["analyses"] = runs;
      nlohmann::json sums = nlohmann::json::array();
      for (const RestitutionSummary& s : a.summaries)
        sums.push_back({{"restitution", describe(a.dynamic->restitutions[s.restitution])},
                        {"e", s.e},
                        {"analyses", s.analyses},
                        {"overturned", s.overturned},
                        {"mean_dc", s.mean_dc},
                        {"min_dc", s.min_dc},
                        {"max_dc", s.max_dc},
                        {"mean_theta_ratio", s.mean_theta_ratio},
                        {"mean_d_star", s.mean_d_star},
                        {"d_SLV", governing(a).result.d_SLV},
                        {"dc_slv", s.dc_slv},
                        {"any_collapse", s.any_collapse},
                        {"slv_satisfied", s.slv_satisfied}});
      d["summary"] = sums;
    }
    j["dynamic"] = d;
  }
  nlohmann::json cmp = nlohmann::json::array();
  for (const Approach& x : comparison(a)) cmp.push_back({{"approach", x.name}, {"dc", x.dc}});
  j["comparison"] = cmp;
  return j;
}

}  // namespace assess
