// facade_report.cpp: text, JSON and HTML reports of a façade assessment.
#include "assess/report/facade_report.hpp"

#include "assess/report/html_report.hpp"
#include "assess/report/kinematic_report.hpp"
#include "assess/report/plot.hpp"
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

// One row per approach and code, built once in the assessment layer
// (assessment/verdict.hpp): the report only formats it.
std::string approach_name(const VerdictRow& r) {
  if (r.code == "seed") return "seed energy D/C (mean), " + r.clause.substr(r.clause.rfind(", ") + 2);
  std::string n = r.code + " " + r.limit_state + " " + r.approach + " (" + r.location + ")";
  if (r.approach == "dynamic") n += ", " + r.clause.substr(r.clause.rfind(", ") + 2);
  return n;
}

const char* dyn_verdict(const RestitutionSummary& s) {
  return s.no_verdict ? "no verdict" : verdict(s.slv_satisfied);
}

}  // namespace

// ------------------------------------------------------------------ text

std::string facade_text(const FacadeAssessment& a) {
  std::string o;
  o += format("assess run: %s\n", a.kase.file.c_str());
  if (!a.kase.project.empty()) o += format("project: %s\n", a.kase.project.c_str());
  if (a.kase.site) {
    const SiteSpec& sp = *a.kase.site;
    o += "\n== Site and seismic action (NTC 2018 §2.4, §3.2) ==\n";
    o += format("site: %s; soil %s, topography %s; VN = %.0f years, CU = %.2f, VR = %.1f years\n",
                a.site_description.c_str(), to_string(sp.conditions.soil).c_str(),
                to_string(sp.conditions.topography).c_str(), sp.vn_years, sp.cu, a.VR);
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
  std::string kt = kinematic_text(a.kase, kin);
  const auto cut = kt.find("\nno site in the case");
  if (cut != std::string::npos) kt.erase(cut);
  o += kt;
  if (!a.checks.empty()) o += "\n== Checks ==\n" + checks_text(a.checks);

  if (a.dynamic) {
    o += "\n== Non-linear dynamic analysis (rocking; seed Eq. 1; Circ. 2019 C8.7.1.2.1.9) ==\n";
    if (!a.dynamic_applies) {
      o += "not applicable: " + a.dynamic_note + "\n";
    } else {
      const RockingBody& b = a.body->body;
      const RockingModel& m = *a.model;
      o += format("model: %s, %s; W = %.3f kN/m, b = %.4f m, R = %.4f m, alpha = %.5f rad, I0 = %.2f kg m2/m, "
                  "M_ext = %.3f kN m/m\n",
                  a.dynamic->smooth ? "smooth block on a Winkler foundation" : "rigid (Housner) block",
                  m.sidedness() == Sidedness::one_sided ? "one-sided" : "two-sided", b.W / units::kN, b.b, b.R,
                  b.alpha, b.I0, b.M_ext / units::kN);
      if (a.dynamic->smooth)
        o += format("       k = %.4g kN/m3, theta_cr = %.3e rad, ", a.dynamic->k / units::kN, m.theta_cr());
      else
        o += "       ";
      o += format("theta_u = %.5f rad, peak moment %.3f kN m/m, energy capacity %.4f kJ/m\n", m.theta_u(+1),
                  m.peak_moment(+1) / units::kN, m.capacity() / units::kN);
      if (a.selection) {
        o += format("records: %d selected from the catalogue, compatible with the SLV spectrum (5 %%) over "
                    "%.2f-%.2f s: %s\n",
                    int(a.records.size()), a.selection_range.T_min, a.selection_range.T_max,
                    a.selection->message.c_str());
      }
      if (a.compatibility.computed && !a.selection) o += "records listed in the case: " + a.compatibility.message + "\n";
      for (const std::string& f : a.record_failures) o += "  record skipped: " + f + "\n";
      o += format("  %-34s %7s %9s  %-18s\n", "record", "scale", "PGA (g)", "event / station");
      for (const RecordUsed& r : a.records)
        o += format("  %-34s %7.3f %9.4f  %s / %s\n", r.name.c_str(), r.scale, r.pga / g, r.event.c_str(),
                    r.station.c_str());
      o += format("\n  %-34s %-18s %9s %7s %9s %8s %8s %10s  %s\n", "record", "restitution", "th/th_u", "impacts",
                  "overturn", "energy", "d* (m)", "t_end (s)", "termination");
      for (const DynamicRun& r : a.runs)
        o += format("  %-34s %-18s %9.4f %7ld %9s %8.4f %8.4f %10.3f  %s\n", record_label(a, r).c_str(),
                    describe(a.dynamic->restitutions[r.restitution]).c_str(), r.theta_ratio, r.result.impacts,
                    r.result.overturned ? "yes" : "no", r.result.dc, r.d_star, r.result.t_end,
                    to_string(r.result.termination));
      o += format("\n  summary per restitution (energy D/C = demand/capacity, the seed paper's measure (seed §3.2), "
                  "not a code check; Circ. 2019 C8.7.1.2.1.9 acceptance: d0 never exceeded and peak d* <= d_SLV = "
                  "%.4f m, combined over the records by NTC 2018 §7.3.5: mean with >= 7 records, the most "
                  "unfavourable with 3 to 6, no verdict with fewer):\n",
                  governing(a).result.d_SLV);
      o += format("  %-18s %6s %-13s %10s %10s %10s %12s %12s %-17s %8s  %s\n", "restitution", "runs", "overturned",
                  "mean D/C", "max D/C", "mean th/u", "mean d* (m)", "max d* (m)", "rule (§7.3.5)", "D/C d*",
                  "verdict (C8.7.1.2.1.9)");
      for (const RestitutionSummary& s : a.summaries)
        o += format("  %-18s %6d %-13s %10.4f %10.4f %10.4f %12.4f %12.4f %-17s %8.3f  %s\n",
                    describe(a.dynamic->restitutions[s.restitution]).c_str(), s.analyses,
                    format("%d of %d", s.overturned, s.analyses).c_str(), s.mean_dc, s.max_dc, s.mean_theta_ratio,
                    s.mean_d_star, s.max_d_star, s.rule.c_str(), s.dc_slv, dyn_verdict(s));
    }
  }
  if (!a.verdict.rows.empty()) o += "\n== Verdict by approach (seed Fig. 8) ==\n" + verdict_text(a.verdict);
  if (!a.warnings.empty()) {
    o += "\n== Warnings ==\n";
    for (const std::string& w : a.warnings) o += "  " + w + "\n";
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
  // The run's summary (with the dynamic rows) is the top-level "comparison"
  // and "overall"; the kinematic-only one would be a second, partial verdict.
  j["kinematic"].erase("summary");
  j["kinematic"].erase("warnings");
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
      if (a.compatibility.computed)
        d["compatibility"] = {{"T_min", a.compatibility.range.T_min},
                              {"T_max", a.compatibility.range.T_max},
                              {"min_ratio", a.compatibility.min_ratio},
                              {"max_ratio", a.compatibility.max_ratio},
                              {"band_satisfied", a.compatibility.band_satisfied},
                              {"message", a.compatibility.message}};
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
                        {"max_d_star", s.max_d_star},
                        {"records", s.records},
                        {"rule", s.rule},
                        {"d_demand", s.d_demand},
                        {"dc_slv", s.dc_slv},
                        {"any_collapse", s.any_collapse},
                        {"no_verdict", s.no_verdict},
                        {"slv_satisfied", s.no_verdict ? nlohmann::json(nullptr) : nlohmann::json(s.slv_satisfied)}});
      d["summary"] = sums;
    }
    j["dynamic"] = d;
  }
  const nlohmann::json v = to_json(a.verdict);
  j["comparison"] = v["by_approach"];
  j["overall"] = v["overall"];
  nlohmann::json energy = nlohmann::json::array();
  for (const CheckRow& r : a.energy_rows) energy.push_back(to_json(r));
  j["energy"] = energy;
  j["warnings"] = a.warnings;
  return j;
}

// ------------------------------------------------------------------ HTML

namespace {

std::string fixed(double v, int prec) { return format("%.*f", prec, v); }

PlotSeries series(std::string name, PlotSeries::Style style, std::vector<double> x = {}, std::vector<double> y = {}) {
  PlotSeries s;
  s.name = std::move(name);
  s.style = style;
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}

}  // namespace

std::string facade_html(const FacadeAssessment& a) {
  HtmlReport h("libassess — " + (a.kase.project.empty() ? a.kase.file : a.kase.project));
  h.add_paragraph("Case file: " + a.kase.file + ". Generated by assess run. Every number below can be redone by hand "
                  "from the quantities listed; clauses are cited next to each quantity.");
  const KinematicResult& k = governing(a).result;

  // 1. Site and spectra.
  if (a.kase.site) {
    h.add_heading("Site and seismic action (NTC 2018 §2.4, §3.2)");
    const SiteSpec& sp = *a.kase.site;
    h.add_paragraph("Site: " + a.site_description + "; soil " + to_string(sp.conditions.soil) + ", topography " +
                    to_string(sp.conditions.topography) + "; VN = " + fixed(sp.vn_years, 0) + " years, CU = " +
                    fixed(sp.cu, 2) + ", VR = " + fixed(a.VR, 1) + " years.");
    std::vector<std::vector<std::string>> rows;
    for (const auto& [ls, act] : a.actions) {
      const ElasticSpectrum& s = a.spectra.at(ls);
      rows.push_back({to_string(ls), fixed(act.PVR * 100, 0), fixed(act.TR, 1), fixed(s.ag_g(), 4), fixed(s.F0(), 3),
                      fixed(s.Tc_star(), 3), fixed(s.SS(), 3), fixed(s.CC(), 3), fixed(s.ST(), 2), fixed(s.S(), 3),
                      fixed(s.TB(), 3), fixed(s.TC(), 3), fixed(s.TD(), 3)});
    }
    h.add_table({"LS", "P_VR (%)", "TR (years)", "ag (g)", "F0", "TC* (s)", "SS", "CC", "ST", "S", "TB (s)", "TC (s)",
                 "TD (s)"},
                rows);
    Plot p;
    p.title = "Elastic spectra (5 %) and record spectra";
    p.x_label = "T (s)";
    p.y_label = "Se, PSA (g)";
    for (const auto& [ls, se] : a.site_Se) {
      PlotSeries s;
      s.name = "Se " + to_string(ls);
      s.x = a.periods;
      for (double v : se) s.y.push_back(v / g);
      s.highlight = ls == LimitState::SLV;
      p.series.push_back(s);
    }
    for (std::size_t i = 0; i < a.record_psa.size(); ++i) {
      PlotSeries s;
      s.name = i == 0 ? "records (scaled)" : "";
      s.x = a.periods;
      for (double v : a.record_psa[i]) s.y.push_back(v / g);
      s.style = PlotSeries::Style::Dashed;
      s.color = "#999999";
      p.series.push_back(s);
    }
    if (!a.mean_psa.empty()) {
      PlotSeries s;
      s.name = "mean of the records";
      s.x = a.periods;
      for (double v : a.mean_psa) s.y.push_back(v / g);
      s.highlight = true;
      s.color = "#000000";
      p.series.push_back(s);
    }
    h.add_svg(render_svg(p), "The four limit-state elastic spectra (NTC 2018 [3.2.2], 5 %) with the scaled record "
                             "spectra and their mean.", "fig-spectra");
  }

  // 2. Kinematic.
  h.add_heading("Kinematic analysis (Circ. 617/2009 C8A.4; Circ. 7/2019 C8.7.1)");
  h.add_paragraph("Mechanism: " + a.kase.mechanism.type + ", governing candidate: " + governing(a).label + ".");
  if (a.kinematic.candidates.size() > 1) {
    std::vector<std::string> head{"candidate", "Z (m)", "alpha0", "a0* (m/s2)"};
    for (const auto& [code, gi] : a.kinematic.governing_by_code) head.push_back("D/C " + code);
    head.push_back("ag,cap (g)");
    head.push_back("governing for");
    std::vector<std::vector<std::string>> rows;
    for (std::size_t i = 0; i < a.kinematic.candidates.size(); ++i) {
      const CandidateResult& cr = a.kinematic.candidates[i];
      std::vector<std::string> r{cr.label, fixed(cr.Z, 2), fixed(cr.result.alpha0, 4), fixed(cr.result.a0_star, 4)};
      std::string gov;
      for (const auto& [code, gi] : a.kinematic.governing_by_code) {
        const auto it = cr.max_dc.find(code);
        r.push_back(it == cr.max_dc.end() ? "-" : fixed(it->second, 3));
        if (gi == i) gov += (gov.empty() ? "" : ", ") + code;
      }
      r.push_back(std::isfinite(cr.ag_capacity_min_g) ? fixed(cr.ag_capacity_min_g, 4) : "-");
      r.push_back(gov);
      rows.push_back(r);
    }
    h.add_paragraph("Candidates: the governing one of each code is the candidate with the largest D/C over its "
                    "checks (Circ. 2019 C8.7.1, C8A.4: the most unfavourable mechanism; for NTC 2018 the lowest ag "
                    "capacity).");
    h.add_table(head, rows);
  }
  h.add_table({"quantity", "value", "unit", "clause"},
              {{"alpha0", fixed(k.alpha0, 6), "-", "C8A.4.1 / C8.7.1.1"},
               {"M*", fixed(k.M_star / units::tonne, 4), "t", "C8A.4.2"},
               {"e*", fixed(k.e_star, 4), "-", "C8A.4.3 / C8.7.1.5"},
               {"FC", fixed(k.FC, 2), "-", a.kase.knowledge_level},
               {"a0*", fixed(k.a0_star, 4), "m/s2", "C8A.4.4 / C8.7.1.3"},
               {"dk0", fixed(k.dk0, 4), "m", "C8A.4.5"},
               {"d0*", fixed(k.d0_star, 4), "m", "C8A.4.5 / C8.7.1.4"},
               {"du* = d_SLV", fixed(k.du_star, 4), "m", "C8A.4 / C8.7.1.2.1.6"},
               {"Ts", fixed(k.Ts, 4), "s", "C8A.4 (2009)"},
               {"T_SLV", fixed(k.T_SLV, 4), "s", "C8.7.1.10"},
               {"d_SLC", fixed(k.d_SLC, 4), "m", "C8.7.1.2.1.6"},
               {"T_SLC", fixed(k.T_SLC, 4), "s", "C8.7.1.11"}});
  if (!k.curve.empty()) {
    Plot p;
    p.title = "Capacity curve of the equivalent oscillator";
    p.x_label = "d* (m)";
    p.y_label = "a* (m/s2)";
    PlotSeries c = series("a*(d*)", PlotSeries::Style::Line);
    for (const CapacityPoint& q : k.curve) c.x.push_back(q.d_star), c.y.push_back(q.a_star);
    c.highlight = true;
    p.series.push_back(c);
    for (const CheckRow& row : a.checks) {
      if (row.kind != "displacement" || row.location != "ground") continue;
      p.series.push_back(series(row.code + " " + row.limit_state + " capacity", PlotSeries::Style::Dashed,
                                {row.capacity, row.capacity}, {0.0, k.a0_star}));
      p.series.push_back(series(row.code + " " + row.limit_state + " demand", PlotSeries::Style::Line,
                                {row.demand, row.demand}, {0.0, k.a0_star}));
    }
    h.add_svg(render_svg(p), "Capacity curve a*-d* (C8A.4.5 / C8.7.1.4) with the displacement capacities (dashed) "
                             "and demands (solid) of the ground-level checks.", "fig-capacity");
  }

  // 3. Checks.
  if (!a.checks.empty()) {
    h.add_heading("Checks");
    std::vector<std::vector<std::string>> rows;
    for (const CheckRow& c : a.checks)
      rows.push_back({c.code, c.limit_state, c.kind, c.location, format("%.4g", c.demand), format("%.4g", c.capacity),
                      c.unit, fixed(c.dc, 3), verdict(c.satisfied), c.formula + "; " + c.clause});
    h.add_table({"code", "LS", "kind", "where", "demand", "capacity", "unit", "D/C", "verdict", "formula / clause"},
                rows);
  }

  // 4. Dynamic.
  if (a.dynamic) {
    h.add_heading("Non-linear dynamic analysis (rocking)");
    if (!a.dynamic_applies) {
      h.add_paragraph("Not applicable: " + a.dynamic_note);
    } else {
      const RockingModel& m = *a.model;
      h.add_paragraph(std::string(a.dynamic->smooth ? "Smooth block on a no-tension Winkler foundation"
                                                    : "Rigid (Housner) block") +
                      " (seed Eq. 1), " + (m.sidedness() == Sidedness::one_sided ? "one-sided" : "two-sided") +
                      " rocking; W = " + fixed(m.body().W / units::kN, 2) + " kN/m, b = " + fixed(m.body().b, 3) +
                      " m, R = " + fixed(m.body().R, 3) + " m, alpha = " + fixed(m.body().alpha, 5) +
                      " rad, theta_u = " + fixed(m.theta_u(+1), 5) + " rad, energy capacity " +
                      fixed(m.capacity() / units::kN, 4) + " kJ/m.");
      Plot mr;
      mr.title = "Moment-rotation curve of the rocking body";
      mr.x_label = "theta (rad)";
      mr.y_label = "M (kN m/m)";
      PlotSeries s = series("restoring moment", PlotSeries::Style::Line, a.mr_theta);
      for (double v : a.mr_moment) s.y.push_back(v / units::kN);
      s.highlight = true;
      mr.series.push_back(s);
      h.add_svg(render_svg(mr), "Net restoring moment about the toe up to theta_u; the area under it is the energy "
                                "capacity (seed §3.2, Fig. 3).", "fig-moment-rotation");
      std::vector<std::vector<std::string>> rrows;
      for (const RecordUsed& r : a.records)
        rrows.push_back({r.name, r.event, r.station, r.component, fixed(r.scale, 3), fixed(r.pga / g, 4)});
      h.add_table({"record", "event", "station", "component", "scale", "PGA (g)"}, rrows);
      if (a.selection)
        h.add_paragraph("Selection (REXEL's rule, mean within -10 %/+30 % of the SLV spectrum over " +
                        fixed(a.selection_range.T_min, 2) + "-" + fixed(a.selection_range.T_max, 2) +
                        " s): " + a.selection->message);
      std::vector<std::vector<std::string>> srows;
      for (const RestitutionSummary& x : a.summaries)
        srows.push_back({describe(a.dynamic->restitutions[x.restitution]), std::to_string(x.analyses),
                         std::to_string(x.overturned) + " of " + std::to_string(x.analyses), fixed(x.mean_dc, 3),
                         fixed(x.max_dc, 3), fixed(x.mean_d_star, 4), fixed(x.max_d_star, 4), x.rule,
                         fixed(x.dc_slv, 3), dyn_verdict(x)});
      h.add_table({"restitution", "analyses", "overturned", "mean energy D/C (seed)", "max energy D/C (seed)",
                   "mean peak d* (m)", "max peak d* (m)", "rule (NTC 2018 §7.3.5)", "D/C (d_SLV)", "C8.7.1.2.1.9"},
                  srows);
      if (a.compatibility.computed)
        h.add_paragraph("Records and the SLV spectrum: " + a.compatibility.message + ".");
      for (std::size_t ie = 0; ie < a.dynamic->restitutions.size(); ++ie) {
        Plot th;
        th.title = "theta/theta_u, " + describe(a.dynamic->restitutions[ie]);
        th.x_label = "t (s)";
        th.y_label = "theta/theta_u (-)";
        // Show the strong motion: up to 10 s after the latest peak (long
        // records have minutes of near-silence after it).
        double t_show = 0.0, t_last = 0.0;
        for (const DynamicRun& r : a.runs)
          if (r.restitution == ie) t_show = std::max(t_show, r.result.t_theta_max), t_last = std::max(t_last, r.result.t_end);
        th.x_min = 0.0;
        th.x_max = std::min(t_last, t_show + 10.0);
        if (!(th.x_max > 0.0)) th.x_max = 1.0;
        for (const DynamicRun& r : a.runs) {
          if (r.restitution != ie || r.result.history.t.empty()) continue;
          PlotSeries s = series(record_label(a, r), PlotSeries::Style::Line);
          const std::vector<double>& t = r.result.history.t;
          const std::size_t n = std::size_t(std::upper_bound(t.begin(), t.end(), th.x_max) - t.begin());
          const std::size_t step = std::max<std::size_t>(1, n / 3000);  // keep the SVG small
          for (std::size_t i = 0; i < n; i += step) {
            s.x.push_back(t[i]);
            s.y.push_back(r.result.history.theta[i] / r.result.theta_u);
          }
          th.series.push_back(s);
        }
        if (!th.series.empty())
          h.add_svg(render_svg(th), "Normalised rotation histories, " + describe(a.dynamic->restitutions[ie]) + ".",
                    "fig-history-" + std::to_string(ie));
      }
    }
  }

  // 5. D/C of all approaches: the summary built in the assessment layer.
  if (!a.verdict.rows.empty()) {
    h.add_heading("Verdict by approach (seed Fig. 8)");
    const std::vector<VerdictRow>& cmp = a.verdict.rows;
    Plot b;
    b.title = "D/C of the strength, displacement and dynamic approaches";
    b.y_label = "D/C (-)";
    b.x_label = "";
    PlotSeries bars = series("D/C", PlotSeries::Style::Bars);
    double dc_max = 1.0;
    for (std::size_t i = 0; i < cmp.size(); ++i) {
      const double dc = std::isfinite(cmp[i].dc) ? cmp[i].dc : 0.0;
      bars.x.push_back(double(i));
      bars.y.push_back(dc);
      b.x_tic_labels.push_back({double(i), std::to_string(i + 1)});
      dc_max = std::max(dc_max, dc);
    }
    b.series.push_back(bars);
    b.y_min = 0.0;
    b.y_max = 1.1 * dc_max;
    b.series.push_back(series("D/C = 1", PlotSeries::Style::Dashed, {-0.5, double(cmp.size()) - 0.5}, {1.0, 1.0}));
    std::vector<std::vector<std::string>> rows;
    for (std::size_t i = 0; i < cmp.size(); ++i)
      rows.push_back({std::to_string(i + 1), approach_name(cmp[i]), cmp[i].limit_state, cmp[i].location,
                      std::isfinite(cmp[i].dc) ? fixed(cmp[i].dc, 3) : "n/a", verdict_word(cmp[i]),
                      cmp[i].candidate + "; " + cmp[i].clause + (cmp[i].note.empty() ? "" : "; " + cmp[i].note)});
    h.add_svg(render_svg(b), "Demand/capacity ratios by approach (numbers as in the table below).", "fig-dc");
    h.add_table({"#", "approach", "LS", "where", "D/C", "verdict", "candidate; clause; notes"}, rows);
    std::vector<std::vector<std::string>> orows;
    for (const CodeVerdict& c : a.verdict.overall)
      orows.push_back({c.code, c.satisfied ? "verificato / satisfied" : "non verificato / not satisfied",
                       std::to_string(c.failing) + " of " + std::to_string(c.checks), fixed(c.max_dc, 3)});
    h.add_table({"code", "overall verdict", "checks failing", "largest D/C"}, orows);
  }
  if (!a.warnings.empty()) {
    h.add_heading("Warnings");
    for (const std::string& w : a.warnings) h.add_paragraph(w);
  }
  return h.str();
}

}  // namespace assess
