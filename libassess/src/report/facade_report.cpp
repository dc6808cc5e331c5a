// facade_report.cpp: text, JSON and HTML reports of a façade assessment.
#include "assess/report/facade_report.hpp"

#include "report/number_text.hpp"
#include "report/text_format.hpp"

#include "assess/hazard/comuni.hpp"
#include "assess/report/kinematic_report.hpp"
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

std::string record_label(const FacadeAssessment& a, const DynamicRun& r) {
  return a.records[r.record].name + (r.reversed ? " (reversed)" : "");
}

// JSON has no infinity: an unbounded or undefined figure is null (its meaning beside it).
nlohmann::json finite_or_null(double v) { return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr); }

std::string dyn_verdict(const RestitutionSummary& s) {
  return s.no_verdict ? "no verdict" : verdict(s.slv_satisfied);
}

// Issue 28: beside a D/C of +inf (a collapse or a failed analysis), the
// figure over the records that neither collapsed nor failed, never the verdict.
std::string survivors_text(const RestitutionSummary& s) {
  if (std::isfinite(s.dc_slv)) return "";
  std::string t = s.collapsed > 0 ? format("; collapse in %d of %d analyses", s.collapsed, s.analyses)
                                  : format("; %d of %d analyses failed", s.failed, s.analyses);
  if (std::isfinite(s.dc_survivors))
    t += format(" (the %d records without a collapse: d* %.4f m, D/C %.3f)", s.records_survived, s.d_demand_survivors,
                s.dc_survivors);
  return t;
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
      o += para("not applicable: " + a.dynamic_note, 2) + "\n";
    } else {
      const MechanismDynamics& md = *a.mechanism_dynamics;
      if (a.model) {
        const RockingBody& b = a.body->body;
        const RockingModel& m = *a.model;
        o += para(format("model: %s, %s; W = %.3f kN/m, b = %.4f m, R = %.4f m, alpha = %.5f rad, I0 = %.2f kg m2/m, "
                         "M_ext = %.3f kN m/m",
                         a.dynamic->smooth ? "smooth block on a Winkler foundation" : "rigid (Housner) block",
                         m.sidedness() == Sidedness::one_sided ? "one-sided" : "two-sided", b.W / units::kN, b.b, b.R,
                         b.alpha, b.I0, b.M_ext / units::kN),
                  7) +
             "\n";
        std::string line = "       ";
        if (a.dynamic->smooth)
          line += format("k = %.4g kN/m3, theta_cr = %.3e rad, ", a.dynamic->k / units::kN, m.theta_cr());
        line += format("theta_u = %.5f rad, peak moment %.3f kN m/m, energy capacity %.4f kJ/m", m.theta_u(+1),
                       m.peak_moment(+1) / units::kN, m.capacity() / units::kN);
        o += para(line, 7) + "\n";
      } else {
        const ChainDynamics& c = *md.chain;
        o += para(format("model: %s chain, %s; M(0) = %.2f kg m2, B(0) = %.2f kg m, q_u = %.5f rad, energy "
                         "capacity %.4f kJ/m",
                         a.dynamic->smooth ? "smooth (Winkler bed under the ground-hinge block)" : "rigid",
                         md.sidedness == Sidedness::two_sided ? "two-sided" : "one-sided", c.mass(0.0),
                         c.coupling(0.0), c.q_u(), c.capacity() / md.length / units::kN),
                  7) +
             "\n";
        if (a.dynamic->smooth)
          o += format("       k = %.4g kN/m3, N = %.3f kN, b = %.4f m, q_cr = %.3e rad\n", a.dynamic->k / units::kN,
                      c.N() / units::kN, c.half_base(), c.q_cr());
      }
      o += para("  " + md.describe(), 4) + "\n";
      if (md.tied_envelope)
        o += para(format("  with the ties at their strength (docs/theory/ties.md §6): collapse rotation %.5f rad, "
                         "energy capacity %.4f kJ/m (the analyses' th/th_u and energy D/C refer to these)",
                         md.q_u(), md.capacity() / units::kN),
                  4) +
             "\n";
      if (!a.code_floor_Se.empty()) {
        o += "  floor motions, 5 % spectrum (mean of the records) vs the code's floor spectrum S_eZ [C7.2.6] (SLV, 5 %):\n";
        o += format("  %8s %14s %14s %8s\n", "T (s)", "floor (g)", "code (g)", "ratio");
        for (std::size_t j = 0; j < a.periods.size(); j += 4)
          o += format("  %8.3f %14.4f %14.4f %8.3f\n", a.periods[j], a.floor_mean_psa[j] / g, a.code_floor_Se[j] / g,
                      a.code_floor_Se[j] > 0 ? a.floor_mean_psa[j] / a.code_floor_Se[j] : 0.0);
      }
      if (a.selection) {
        o += para(format("records: %d selected from the catalogue (%zu candidates after the filters, %zu within the "
                         "per-record limits), compatible with the %s spectrum (5 %%) over %.2f-%.2f s (around the "
                         "mechanism periods %.2f-%.2f s): %s",
                         int(a.records.size()), a.selection_candidates, a.selection->eligible,
                         a.selection_limit_state.c_str(), a.selection_range.T_min, a.selection_range.T_max,
                         a.selection_T_first, a.selection_T_last, a.selection->message.c_str()),
                  9) +
             "\n";
        o += para(format("  limits: each scale <= %.2f, mean scale %.3f <= %.2f, largest scaled PGA %.3f g <= %.2f ag S "
                         "= %.3f g",
                         a.selection_max_scale, a.selection->mean_scale, a.selection_max_mean_scale,
                         a.selection->max_scaled_pga / g, a.selection_max_pga_ratio,
                         a.selection_max_pga_ratio * a.selection->target_pga / g),
                  10) +
             "\n";
        for (const std::string& w : a.selection_warnings) o += para("  warning: " + w, 11) + "\n";
        o += para("  range: " + a.selection_range_note, 4) + "\n";
        if (!a.selection_shared_note.empty()) o += para("  candidates: " + a.selection_shared_note, 4) + "\n";
        for (const std::string& st : a.selection_steps) o += para("  site classes tried: " + st, 4) + "\n";
        o += para(format("  rules: site class first (relaxed only without a compatible set); near-fault and pulse-like "
                         "records %s (%zu left out; distance < %.0f km or pulse-like); misfit flagged above %.2f; "
                         "candidates' spectra %s",
                         a.selection_include_near_fault ? "admitted" : "left out", a.selection_near_fault_excluded,
                         a.selection_near_fault_km, a.selection_max_misfit,
                         a.selection_spectra == "precomputed" ? "precomputed (spectra.bin, log-log interpolation)"
                                                              : "integrated"),
                  4) +
             "\n";
      }
      if (a.compatibility.computed && !a.selection) o += "records listed in the case: " + a.compatibility.message + "\n";
      for (const std::string& f : a.record_failures) o += para("  record skipped: " + f, 4) + "\n";
      const int rw = wide ? 34 : 32;  // record column
      // Each record: scale, scaled PGA, misfit to the target and its rank, Mw, distance and its kind,
      // site class, seconds integrated; below it the event, date, station, country, Vs30 with the class
      // basis, the usable period and the flags (120 columns). "—" where the catalogue says nothing.
      // Padding by display width (a dash is one column, three bytes).
      auto pad = [](const std::string& t, int width, bool left) {
        int cols = 0;
        for (unsigned char ch : t) cols += (ch & 0xC0) != 0x80;
        const std::string fill(std::size_t(std::max(0, width - cols)), ' ');
        return left ? t + fill : fill + t;
      };
      const std::string dash = "\u2014";
      auto cell = [&](double v, int width, int prec) {
        return pad(std::isfinite(v) ? format("%.*f", prec, v) : dash, width, false);
      };
      auto or_dash = [&](const std::string& t) { return t.empty() ? dash : t; };
      o += format("  %-*s %7s %8s %6s %4s %5s %7s %-4s %2s %8s\n", rw, "record", "scale", "PGA (g)", "misfit", "rank",
                  "Mw", "R (km)", "kind", "cl", "used (s)");
      for (const RecordUsed& r : a.records) {
        o += format("  %-*s %7.3f %8.4f %s %s %s %s %s %s %8.1f\n", rw, r.name.c_str(), r.scale, r.pga / g,
                    cell(r.deviation, 6, 3).c_str(), pad(r.rank > 0 ? std::to_string(r.rank) : dash, 4, false).c_str(),
                    cell(r.Mw, 5, 2).c_str(), cell(r.distance_km, 7, 1).c_str(), pad(or_dash(r.distance_kind), 4, true).c_str(),
                    pad(or_dash(r.site_class), 2, false).c_str(), r.integrated_s);
        if (r.in_catalogue) {
          o += para(format("    %s, %s / %s%s, %s (+ %s); %s", or_dash(r.event).c_str(), or_dash(r.date).c_str(),
                           or_dash(r.station).c_str(), r.station_code.empty() ? "" : (" (" + r.station_code + ")").c_str(),
                           or_dash(r.component).c_str(), or_dash(r.positive_direction).c_str(),
                           or_dash(r.country).c_str()),
                    6) +
               "\n";
          o += para("    Vs30 " + (std::isfinite(r.vs30_m_s) ? format("%.0f m/s", r.vs30_m_s) : dash) + ", class " +
                        or_dash(r.site_class) +
                        (r.site_class_basis == "stated" ? " (stated by the source)"
                         : r.site_class_basis == "Vs30" ? " (from Vs30, NTC 2018 Tab. 3.2.II)"
                                                        : "") +
                        "; usable to " + (std::isfinite(r.usable_period_s) ? format("%.2f s", r.usable_period_s)
                                                                           : dash + " (not given by the source)") +
                        "; pulse: " + (r.pulse.empty() ? dash + " (not classified)" : r.pulse),
                    6) +
               "\n";
        } else {
          // A listed file outside the library: what its header says, if anything.
          std::string what = r.file;
          if (!r.event.empty() || !r.station.empty())
            what += ": " + or_dash(r.event) + " / " + or_dash(r.station) + ", " + or_dash(r.component);
          o += para("    " + what, 6) + "\n";
        }
        for (const std::string& f : r.flags) o += para("    FLAG: " + f, 10) + "\n";
      }
      o += para(format("  each record integrated to its last sample, then the free motion until rest, until the "
                       "energy after an impact can no longer reach the peak rotation, or for at most %.0f s "
                       "(column 'end': why each analysis ended)",
                       a.free_tail_s),
                4) +
           "\n";
      o += format(wide ? "\n  %-*s %-18s %9s %7s %9s %8s %8s %10s  %s\n" : "\n  %-*s %-12s %7s %7s %8s %7s %7s %9s  %s\n",
                  rw, "record", "restitution", "th/th_u", "impacts", "overturn", "energy", "d* (m)", "t_end (s)",
                  "end");
      for (const DynamicRun& r : a.runs)
        if (!succeeded(r.result))  // a failed analysis shows no numbers
          o += para(format("  %-*s %-18s FAILED (%s): %s", rw, record_label(a, r).c_str(),
                           describe(a.dynamic->restitutions[r.restitution]).c_str(), to_string(r.result.termination),
                           r.result.message.c_str()),
                    4) +
               "\n";
        else
          o += format(wide ? "  %-*s %-18s %9.4f %7ld %9s %8.4f %8.4f %10.3f  %s\n"
                           : "  %-*s %-12s %7.4f %7ld %8s %7.4f %7.4f %9.3f  %s\n",
                      rw, record_label(a, r).c_str(),
                    describe(a.dynamic->restitutions[r.restitution]).c_str(), r.theta_ratio, r.result.impacts,
                    r.result.overturned ? "yes" : "no", r.result.dc, r.d_star, r.result.t_end,
                    to_string(r.result.end));
      o += "\n" +
           para(format("  summary per restitution (energy D/C = demand/capacity, the seed paper's measure (seed §3.2), "
                       "not a code check; Circ. 2019 C8.7.1.2.1.9 acceptance: d0 never exceeded and peak d* <= d_SLV = "
                       "%.4f m, combined over the records by NTC 2018 §7.3.5: mean with >= 7 records, the most "
                       "unfavourable with 3 to 6, no verdict with fewer):",
                       governing(a).result.d_SLV),
                4) +
           "\n";
      if (wide) {
        o += format("  %-18s %6s %-13s %10s %10s %10s %12s %12s %-17s %8s  %s\n", "restitution", "runs", "overturned",
                    "mean D/C", "max D/C", "mean th/u", "mean d* (m)", "max d* (m)", "rule (§7.3.5)", "D/C d*",
                    "verdict (C8.7.1.2.1.9)");
        for (const RestitutionSummary& s : a.summaries)
          o += format("  %-18s %6d %-13s %s %10.4f %10.4f %12.4f %12.4f %-17s %s  %s\n",
                      describe(a.dynamic->restitutions[s.restitution]).c_str(), s.analyses,
                      format("%d of %d", s.overturned, s.analyses).c_str(), number_text(s.energy_dc, "%.4f", 10),
                      s.max_dc, s.mean_theta_ratio, s.mean_d_star, s.max_d_star, s.rule.c_str(),
                      number_text(s.dc_slv, "%.3f", 8), dyn_verdict(s) + survivors_text(s));
      } else {  // 120 columns: the verdict on its own line under each row, never cut mid-phrase
        o += format("  %-12s %4s %-10s %8s %8s %9s %9s %9s %-14s %6s\n", "restitution", "runs", "overturned",
                    "mean D/C", "max D/C", "mean th/u", "mean d*", "max d*", "rule (§7.3.5)", "D/C d*");
        o += format("  %-12s %s\n", "", "verdict (C8.7.1.2.1.9)");
        for (const RestitutionSummary& s : a.summaries)
          o += format("  %-12s %4d %-10s %s %8.4f %9.4f %9.4f %9.4f %-14s %s\n",
                      describe(a.dynamic->restitutions[s.restitution]).c_str(), s.analyses,
                      format("%d of %d", s.overturned, s.analyses).c_str(), number_text(s.energy_dc, "%.4f", 8),
                      s.max_dc, s.mean_theta_ratio, s.mean_d_star, s.max_d_star, s.rule.c_str(),
                      number_text(s.dc_slv, "%.3f", 6)) +
               wrap_text(std::string(15, ' ') + dyn_verdict(s) + survivors_text(s), 17) + "\n";
      }
    }
  }
  if (!a.other_dynamics.empty()) {
    // The other candidates that govern a code or fail a kinematic check, each
    // analysed as the case restricted to it (issue 24).
    o += "\n" +
         para("dynamic analysis of the other candidates that govern a code or fail a kinematic check (each as if it "
              "were the only mechanism of the case: records selected over its own periods; the dynamic verdict is "
              "the worst over every candidate):",
              2) +
         "\n";
    o += format("  %-16s %9s %10s %10s %7s  %s\n", "restitution", "d0 exc.", "demand d*", "d_SLV (m)", "D/C",
                "verdict (C8.7.1.2.1.9)");
    for (std::size_t k = 0; k < a.other_dynamics.size(); ++k) {
      const FacadeAssessment& s = a.other_dynamics[k];
      const std::string label = a.kinematic.candidates[a.other_dynamics_candidate[k]].label;
      if (!s.dynamic_applies) {
        o += para("  " + label + ": not applicable: " + s.dynamic_note, 4) + "\n";
        continue;
      }
      o += "  " + label + ":\n";
      for (const RestitutionSummary& x : s.summaries) {
        int collapses = 0;
        for (const DynamicRun& r : s.runs) collapses += r.restitution == x.restitution && r.collapse ? 1 : 0;
        o += para(format("    %-14s %9s %s %10.4f %s  %s", describe(s.dynamic->restitutions[x.restitution]).c_str(),
                         format("%d of %d", collapses, x.analyses).c_str(), number_text(x.d_demand, "%.4f", 10),
                         s.kinematic.candidates.front().result.d_SLV, number_text(x.dc_slv, "%.3f", 7),
                         dyn_verdict(x) + survivors_text(x)),
                  58) +
             "\n";
      }
      std::string recs;
      for (const RecordUsed& r : s.records) recs += (recs.empty() ? "" : ", ") + r.name + format(" (%.2f)", r.scale);
      o += para("    records (scale): " + recs, 6) + "\n";
    }
  }
  if (!a.verdict.rows.empty()) o += "\n== Verdict by approach (seed Fig. 8) ==\n" + verdict_text(a.verdict, width);
  if (!a.warnings.empty()) {
    o += "\n== Warnings ==\n";
    for (const std::string& w : a.warnings) o += para("  " + w, 4) + "\n";
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
      const MechanismDynamics& md = *a.mechanism_dynamics;
      if (a.model) {
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
      } else {
        const ChainDynamics& c = *md.chain;
        d["model"] = {{"type", a.dynamic->smooth ? "smooth" : "rigid"},
                      {"k_kN_m3", a.dynamic->smooth ? nlohmann::json(a.dynamic->k / units::kN) : nlohmann::json(nullptr)},
                      {"sidedness", md.sidedness == Sidedness::two_sided ? "two-sided" : "one-sided"},
                      {"polarity", to_string(a.dynamic->polarity)},
                      {"chain_blocks", c.chain().blocks().size()},
                      {"M0_kg_m2", c.mass(0.0)}, {"B0_kg_m", c.coupling(0.0)},
                      {"theta_cr", a.dynamic->smooth ? nlohmann::json(c.q_cr()) : nlohmann::json(nullptr)},
                      {"theta_u", c.q_u()}, {"capacity_kJ_m", c.capacity() / md.length / units::kN}};
      }
      if (md.tied_envelope)  // the ties at their strength (docs/theory/ties.md §6)
        d["model"]["tied"] = {{"levels", md.ties.size()},
                              {"theta_collapse", md.q_u()},
                              {"capacity_kJ_m", md.capacity() / units::kN}};
      d["model"]["kind"] = md.single_body() ? "rocking body" : "chain";
      d["model"]["Z"] = md.Z;
      d["model"]["input"] = md.floor_input ? "floor motions given" : md.filter ? "floor motions (first-mode filter)" : "ground motions";
      if (md.filter)
        d["model"]["floor_filter"] = {{"T1_s", md.filter->T1}, {"damping_pct", md.filter_damping_pct},
                                      {"gamma_psi", md.filter->gamma_psi}};
      if (!a.code_floor_Se.empty())
        d["floor_spectra"] = {{"periods_s", a.periods}, {"floor_mean_psa_m_s2", a.floor_mean_psa},
                              {"code_floor_Se_m_s2", a.code_floor_Se}};
      nlohmann::json recs = nlohmann::json::array();
      for (const RecordUsed& r : a.records)
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
                        {"flags", r.flags}});
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
                          {"message", a.selection->message},
                          {"limit_state", a.selection_limit_state},
                          {"mechanism_periods_s", {a.selection_T_first, a.selection_T_last}},
                          {"band", {1.0 - 0.10, 1.0 + 0.30}},
                          {"candidates", a.selection_candidates},
                          {"eligible", a.selection->eligible},
                          {"combinations", a.selection->combinations},
                          {"site_classes", a.selection_site_classes},
                          {"site_class_steps", a.selection_steps},
                          {"warnings", a.selection_warnings},
                          {"range_note", a.selection_range_note},
                          {"shared_note", a.selection_shared_note},
                          {"spectra", a.selection_spectra},
                          {"max_scale", a.selection_max_scale},
                          {"max_mean_scale", a.selection_max_mean_scale},
                          {"max_misfit", a.selection_max_misfit},
                          {"include_near_fault", a.selection_include_near_fault},
                          {"near_fault_km", a.selection_near_fault_km},
                          {"near_fault_excluded", a.selection_near_fault_excluded},
                          {"mean_scale", a.selection->mean_scale},
                          {"max_scaled_pga_g", a.selection->max_scaled_pga / g},
                          {"max_pga_ratio", a.selection_max_pga_ratio},
                          {"target_pga_g", a.selection->target_pga / g},
                          {"periods_s", a.selection->periods},
                          {"target_m_s2", a.selection->target},
                          {"mean_psa_m_s2", a.selection->mean_psa},
                          {"record_psa_m_s2", [&] {
                             nlohmann::json rp = nlohmann::json::array();
                             for (const auto& sr : a.selection->records) rp.push_back(sr.psa);
                             return rp;
                           }()}};
      d["duration"] = {{"whole_record", true},
                       {"free_motion_cap_s", a.free_tail_s},
                       {"free_energy_fraction", free_energy_fraction}};
      nlohmann::json runs = nlohmann::json::array();
      for (const DynamicRun& r : a.runs) {
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
        runs.back()["ties_per"] = a.mechanism_dynamics && a.mechanism_dynamics->single_body() ? "m of wall" : "level";
        runs.back()["rod_broken"] = r.ruptured;
      }
      d["analyses"] = runs;
      nlohmann::json sums = nlohmann::json::array();
      for (const RestitutionSummary& s : a.summaries)
        sums.push_back({{"restitution", describe(a.dynamic->restitutions[s.restitution])},
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
      d["summary"] = sums;
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
  for (const CheckRow& r : a.energy_rows) energy.push_back(to_json(r));
  j["energy"] = energy;
  j["warnings"] = a.warnings;
  return j;
}

}  // namespace assess
