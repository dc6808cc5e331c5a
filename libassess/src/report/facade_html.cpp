// facade_html.cpp: the HTML relazione of a façade assessment, built in named
// steps (one function per section). Formatting only: every number comes from
// FacadeAssessment; every sentence from the message catalogue (messages.cpp).
#include "assess/report/facade_report.hpp"
#include "assess/report/tie_report.hpp"

#include "report/text_format.hpp"

#include "report/report_heading.hpp"
#include "report/xml_escape.hpp"

#include "assess/hazard/comuni.hpp"
#include "assess/report/html_report.hpp"
#include "assess/report/kinematic_report.hpp"
#include "assess/report/mechanism_drawing.hpp"
#include "assess/report/plot.hpp"
#include "assess/support/units.hpp"

#include <algorithm>
#include <cmath>
#include <ctime>
#include <filesystem>
#include <limits>
#include <map>

namespace assess {

namespace {

constexpr double g = units::g;
constexpr double pi = 3.14159265358979323846;
using detail::code_name;
using detail::shown_file;
using detail::today_utc;
using detail::xml_escape;

std::string fixed(double v, int prec) {
  if (!std::isfinite(v)) return v > 0 ? "∞" : "—";
  return format("%.*f", prec, v);
}

bool check_fails(const CheckRow& c) { return !c.satisfied || !std::isfinite(c.dc) || c.dc > 1.0; }

/// D/C cell, coloured: > 1 (or not finite) red, <= 1 green; 3 decimals.
HtmlCell dc_cell(double dc, bool fails) { return HtmlCell(fixed(dc, 3), fails ? "num dc-fail" : "num dc-ok"); }

HtmlCell num(double v, int prec, const std::string& extra = "") {
  return HtmlCell(fixed(v, prec), extra.empty() ? "num" : "num " + extra);
}


struct Ctx {
  const FacadeAssessment& a;
  const ReportOptions& o;
  Lang L;
  HtmlReport& h;
  const std::string& t(const std::string& key) const { return msg(L, key); }
  /// A text generated in English by the analysis (labels, notes, descriptions) in the report's language.
  std::string loc(const std::string& text) const { return localise(L, text); }
  const CandidateResult& gc() const { return a.kinematic.candidates[a.kinematic.governing]; }
  const KinematicResult& k() const { return gc().result; }
  /// "verifica allo SLV, lineare (resistenza), al piede"
  std::string check_name(const CheckRow& c) const {
    return t("checks.verifica") + " " + c.limit_state + ", " + kind_name(c.kind) + ", " + t("where." + c.location);
  }
  /// "lineare (resistenza)" ... for a kind of check or an approach.
  std::string kind_name(const std::string& kind) const {
    for (const char* k : {"strength", "displacement", "dynamic", "dynamic energy"})
      if (kind == k) return t("kind." + kind);
    return kind;
  }
  /// "verifica allo SLV, lineare (resistenza), al piede" for a summary row.
  std::string row_name(const VerdictRow& r) const {
    return t("checks.verifica") + " " + r.limit_state + ", " + kind_name(r.approach) + ", " + t("where." + r.location);
  }
  std::string restitution(std::size_t i) const { return loc(describe(a.dynamic->restitutions[i])); }
  std::string record_label(const DynamicRun& r) const {
    return a.records[r.record].name + (r.reversed ? " (" + t("dyn.reversed") + ")" : "");
  }
};

PlotSeries series(std::string name, PlotSeries::Style style, std::vector<double> x = {}, std::vector<double> y = {}) {
  PlotSeries s;
  s.name = std::move(name);
  s.style = style;
  s.x = std::move(x);
  s.y = std::move(y);
  return s;
}


// ------------------------------------------------------------ steps


void add_header(const Ctx& c) {
  std::string meta;
  if (!c.a.kase.project.empty()) meta += c.t("doc.project") + ": " + c.a.kase.project + ". ";
  meta += c.t("doc.case_file") + ": " + shown_file(c.a.kase.file) + ". " + c.t("doc.generated") + " " +
          c.t("doc.version") + " " + ASSESS_VERSION + ", " + c.t("doc.date") + " " +
          (c.o.date.empty() ? today_utc() : c.o.date) + ".";
  c.h.set_subtitle(meta);
  c.h.add_paragraph(c.t("doc.intro"));
}

// Premessa and normativa di riferimento (the opening of a relazione di calcolo).
void add_premessa(const Ctx& c) {
  const FacadeAssessment& a = c.a;
  c.h.add_heading(c.t("doc.premessa"), 2, false);
  std::string p = c.t("doc.premessa_text") + " " + mechanism_name(c.L, a.kase.mechanism.type) + ".";
  c.h.add_paragraph(p);  // the project, the user's own words, is in the header
  c.h.add_paragraph(c.t("doc.procedures") + " " + c.t("method." + a.verdict.adopted) + ".");
  c.h.add_heading(c.t("doc.normativa"), 2, false);
  c.h.add_raw_html("<ul class=\"normativa\">\n<li>" + xml_escape(c.t("norm.ntc2018")) + "</li>\n<li>" +
                   xml_escape(c.t("norm.circ2019")) + "</li>\n<li>" + xml_escape(c.t("norm.ntc2008")) + "</li>\n<li>" +
                   xml_escape(c.t("norm.dpcm2011")) + "</li>\n<li>" + xml_escape(c.t("norm.seed")) + "</li>\n</ul>");
}

// Dati (issue 24): the geometry and materials of the governing mechanism's
// blocks and the analysis parameters, each with its unit and where it comes
// from; the loads are in the virtual-work table (§ meccanismo).
void add_data(const Ctx& c) {
  const FacadeAssessment& a = c.a;
  c.h.add_heading(c.t("data.heading"), 2, false);
  std::vector<std::vector<HtmlCell>> rows;
  auto row = [&](const std::string& what, const std::string& v, const std::string& unit, const std::string& src) {
    rows.push_back({what, HtmlCell(v, "num"), unit, src});
  };
  const Chain& chain = a.kase.mechanism.candidates.at(a.kinematic.governing).chain;
  row(c.t("data.mechanism"), mechanism_name(c.L, a.kase.mechanism.type), "", c.t("data.case"));
  // Issue 33: a reduced chain (plan, projection) shows the mechanism's own geometry, not its blocks' extents.
  for (const MechanismQuantity& q : a.kase.mechanism.data)
    row(c.loc(q.label), q.unit.empty() ? "" : format("%.4g", q.value), q.unit == "-" ? "-" : q.unit,
        q.source == "input" ? c.t("data.case") : c.loc(q.source));
  for (std::size_t i = 0; i < chain.blocks().size() && a.kase.mechanism.data.empty(); ++i) {
    const Block& b = chain.blocks()[i];
    double x0 = 1e300, x1 = -1e300, z0 = 1e300, z1 = -1e300;
    for (const Eigen::Vector2d& v : b.polygon) {
      x0 = std::min(x0, v.x()), x1 = std::max(x1, v.x());
      z0 = std::min(z0, v.y()), z1 = std::max(z1, v.y());
    }
    // Blocks by number, bottom to top as in the chain (catalogue names are English phrases).
    const std::string name = c.t("data.block") + " " + std::to_string(i + 1);
    row(name + ": " + c.t("data.height"), fixed(z1 - z0, 3), "m", "z " + fixed(z0, 2) + "–" + fixed(z1, 2) + " m");
    row(name + ": " + c.t("data.thickness"), fixed(x1 - x0, 3), "m", c.t("data.bbox"));
    row(name + ": " + c.t("data.area"), fixed(chain.area(int(i)), 4), "m²", c.t("data.polygon"));
    row(name + ": " + c.t("data.gamma"), fixed(b.unit_weight / units::kN, 2), "kN/m³", c.t("data.case"));
    row(name + ": " + c.t("data.length"), fixed(b.length, 2), "m", c.t("data.case"));
    row(name + ": " + c.t("data.weight"), fixed(b.unit_weight * chain.area(int(i)) * b.length / units::kN, 2), "kN",
        "γ · A · L");
  }
  row(c.t("data.kl"), a.kase.knowledge_level, "", "C8.5.4");
  row("FC", fixed(c.k().FC, 2), "-", "C8.5.4, Tab. C8.5.IV");
  row("q", fixed(a.kase.checks.q, 2), "-", "C8.7.1.2.1.7");
  row("ξ SLV / SLC", fixed(a.kase.checks.damping_SLV_pct, 0) + " / " + fixed(a.kase.checks.damping_SLC_pct, 0), "%",
      "C8.7.1.2.1.8");
  if (a.kase.building) {
    const BuildingModel& b = *a.kase.building;
    row(c.t("data.H"), fixed(b.H, 2), "m", c.t("data.case"));
    row(c.t("data.N"), std::to_string(b.storeys), "-", c.t("data.case"));
    row("T1", fixed(b.T1, 3), "s", "NTC 2018 §7.3.3.2");
    row("ξ1", fixed(b.damping_pct, 0), "%", "C7.2.3");
  }
  if (a.dynamic) {
    const DynamicSpec& d = *a.dynamic;
    row(c.t("data.dyn_model"), c.t(d.smooth ? "data.smooth" : "data.rigid"), "", c.t("data.case"));
    if (d.smooth) row("k (Winkler)", format("%.4g", d.k / units::kN), "kN/m³", c.t("data.case"));
    std::string e;
    for (const Restitution& r : d.restitutions) e += (e.empty() ? "" : "; ") + c.loc(describe(r));
    if (!e.empty()) row(c.t("data.restitution"), e, "-", c.t("data.case"));
  }
  c.h.add_cell_table({c.t("kin.quantity"), HtmlCell(c.t("kin.value"), "num"), c.t("kin.unit"), c.t("data.source")},
                     rows, c.t(a.kase.mechanism.data.empty() ? "data.caption" : "data.caption_mechanism"));
}

// Conclusioni and the place/date/signature block.
void add_conclusions(const Ctx& c) {
  const Verdict& v = c.a.verdict;
  c.h.add_heading(c.t("doc.conclusioni"), 2, false);
  if (const MethodVerdict* m = v.conclusion()) {
    const bool ok = m->satisfied && std::isfinite(m->max_dc);
    c.h.add_paragraph(c.t("doc.concl_adopted") + " " + c.t("method." + m->method) + " (" + code_name(m->code) + "): " +
                      c.t(ok ? "verdict.ok" : "verdict.fail") + ", D/C = " + fixed(m->max_dc, 3) + ".");
    std::string others;
    for (const MethodVerdict& o : v.methods) {
      if (o.code != m->code || o.method == m->method) continue;
      const bool ook = o.satisfied && std::isfinite(o.max_dc);
      others += (others.empty() ? "" : "; ") + c.t("method." + o.method) + ": " +
                c.t(ook ? "verdict.ok" : "verdict.fail") + " (D/C = " + fixed(o.max_dc, 3) + ")";
    }
    if (!others.empty()) c.h.add_paragraph(c.t("doc.concl_others") + ": " + others + ".");
  } else {
    c.h.add_paragraph(c.t("verdict.no_method_checks") + ".");
  }
  c.h.add_raw_html("<div class=\"signature\"><p>" + xml_escape(c.t("doc.place_date")) +
                   ": ______________________</p><p>" + xml_escape(c.t("doc.engineer")) +
                   ": ______________________</p></div>");
}

// The verdict box (issue 24): per code, the verdict of each method
// (linear, non-linear, dynamic: alternative procedures of Circ. 2019
// C8.7.1.2), then the conclusion: the adopted method's verdict under NTC
// 2018; NTC 2008 is shown for comparison. Every count is a count of checks
// listed in the tables of §verifiche and the appendix.
void add_verdict_box(const Ctx& c) {
  const Verdict& v = c.a.verdict;
  std::string html = "<section class=\"verdicts\" aria-label=\"" + xml_escape(c.t("verdict.heading")) + "\">\n";
  html += "<h2 class=\"verdicts-heading\" style=\"border:none;margin-top:0.4em\">" + xml_escape(c.t("verdict.heading")) +
          "</h2>\n";
  const MethodVerdict* concl = v.conclusion();
  if (concl) {
    const bool ok = concl->satisfied && std::isfinite(concl->max_dc);
    html += std::string("<div class=\"conclusion ") + (ok ? "ok" : "fail") + "\" data-method=\"" + xml_escape(v.adopted) +
            "\"><strong>" + xml_escape(c.t("verdict.conclusion")) + "</strong> (" + xml_escape(c.t("verdict.adopted")) +
            ": " + xml_escape(c.t("method." + v.adopted)) + ", " + xml_escape(code_name(concl->code)) + "): " +
            "<span class=\"outcome\">" + xml_escape(c.t(ok ? "verdict.ok" : "verdict.fail")) + "</span> <span class=\"" +
            (concl->max_dc <= 1.0 ? "dc-ok" : "dc-fail") + "\">D/C = " + xml_escape(fixed(concl->max_dc, 3)) + "</span></div>\n";
  } else if (!v.overall.empty()) {
    html += "<div class=\"conclusion fail\"><strong>" + xml_escape(c.t("verdict.conclusion")) + "</strong>: " +
            xml_escape(c.t("verdict.no_method_checks")) + " (" + xml_escape(c.t("method." + v.adopted)) + ")</div>\n";
  }
  html += "<div class=\"verdicts\">\n";
  if (v.overall.empty()) html += "<p>" + xml_escape(c.t("verdict.no_checks")) + "</p>\n";
  for (const CodeVerdict& cv : v.overall) {
    // The box's colour: the adopted method's verdict in this code, else the worst of its methods.
    const MethodVerdict* adopted = nullptr;
    bool all_ok = true;
    for (const MethodVerdict& m : v.methods)
      if (m.code == cv.code) {
        all_ok = all_ok && m.satisfied && std::isfinite(m.max_dc);
        if (m.method == v.adopted) adopted = &m;
      }
    const bool box_ok = adopted ? adopted->satisfied && std::isfinite(adopted->max_dc) : all_ok;
    html += std::string("<div class=\"verdict ") + (box_ok ? "ok" : "fail") + "\" data-code=\"" + xml_escape(cv.code) +
            "\">\n";
    html += "<div class=\"code\">" + xml_escape(code_name(cv.code)) +
            (cv.code == v.conclusion_code ? std::string() : " — " + xml_escape(c.t("verdict.comparison"))) + "</div>\n";
    for (const MethodVerdict& m : v.methods) {
      if (m.code != cv.code) continue;
      const bool ok = m.satisfied && std::isfinite(m.max_dc);
      html += std::string("<div class=\"method ") + (ok ? "ok" : "fail") + "\" data-method=\"" + xml_escape(m.method) +
              "\">" + xml_escape(c.t("method." + m.method)) + (m.method == v.adopted ? " (" + xml_escape(c.t("verdict.adopted")) + ")" : "") +
              ": <span class=\"outcome\">" + xml_escape(c.t(ok ? "verdict.ok" : "verdict.fail")) + "</span> <span class=\"" +
              (m.max_dc <= 1.0 ? "dc-ok" : "dc-fail") + "\">D/C = " + xml_escape(fixed(m.max_dc, 3)) + "</span> — " +
              std::to_string(m.checks) + " " + xml_escape(c.t(m.checks == 1 ? "verdict.check1" : "verdict.checks")) +
              ", " + std::to_string(m.failing) + " " + xml_escape(c.t(m.failing == 1 ? "verdict.failing1" : "verdict.failing"));
      if (m.no_verdict > 0) html += ", " + std::to_string(m.no_verdict) + " " + xml_escape(c.t("verdict.no_verdict"));
      if (m.governing >= 0) {
        const VerdictRow& r = v.rows[std::size_t(m.governing)];
        html += "<div class=\"governing\">" + xml_escape(c.t("verdict.governing")) + ": " + xml_escape(c.row_name(r)) +
                ", D/C = " + xml_escape(fixed(r.dc, 3)) + " (" + xml_escape(c.loc(r.clause)) +
                (r.candidate.empty() ? "" : "; " + xml_escape(c.loc(r.candidate))) + ")";
        if (r.no_verdict || !std::isfinite(r.dc)) html += " — " + xml_escape(c.t("verdict.untrusted"));
        if (!r.note.empty()) html += " — " + xml_escape(c.loc(r.note));
        html += "</div>";
      }
      html += "</div>\n";
    }
    html += "</div>\n";
  }
  html += "</div>\n<p class=\"meta\">" + xml_escape(c.t("verdict.note")) + "</p>\n</section>";
  c.h.add_raw_html(html);
}

void add_site(const Ctx& c) {
  if (!c.a.kase.site) return;
  const FacadeAssessment& a = c.a;
  c.h.add_heading(c.t("site.heading"));
  const SiteSpec& sp = *a.kase.site;
  c.h.add_paragraph(c.t("site.site") + ": " + c.loc(a.site_description) + "; " + c.t("site.soil") + " " +
                    to_string(sp.conditions.soil) + ", " + c.t("site.topography") + " " +
                    to_string(sp.conditions.topography) + "; " + c.t("site.vn") + " = " + fixed(sp.vn_years, 0) + " " +
                    c.t("site.years") + ", " + c.t("site.cu") + " = " + fixed(sp.cu, 2) + ", " + c.t("site.vr") +
                    " = " + fixed(a.VR, 1) + " " + c.t("site.years") + " [2.4.1].");
  if (!sp.comune.empty()) c.h.add_paragraph(c.t("site.comune_note"));
  std::vector<std::vector<HtmlCell>> rows;
  for (const auto& [ls, act] : a.actions) {
    const ElasticSpectrum& s = a.spectra.at(ls);
    rows.push_back({to_string(ls), num(act.PVR * 100, 0), num(act.TR, 1), num(s.ag_g(), 4), num(s.F0(), 3),
                    num(s.Tc_star(), 3), num(s.SS(), 3), num(s.CC(), 3), num(s.ST(), 2), num(s.S(), 3),
                    num(s.TB(), 3), num(s.TC(), 3), num(s.TD(), 3)});
  }
  c.h.add_cell_table({c.t("site.ls"), HtmlCell("P_VR (%)", "num"), HtmlCell("TR", "num", c.t("site.years")),
                 HtmlCell("ag (g)", "num"), HtmlCell("F0", "num"), HtmlCell("TC* (s)", "num"), HtmlCell("SS", "num"),
                 HtmlCell("CC", "num"), HtmlCell("ST", "num"), HtmlCell("S", "num"), HtmlCell("TB (s)", "num"),
                 HtmlCell("TC (s)", "num"), HtmlCell("TD (s)", "num")},
                rows, c.t("site.table"));
  Plot p;
  p.title = c.t("site.fig_title");
  p.x_label = "T (s)";
  p.y_label = "Se, PSA (g)";
  for (const auto& [ls, se] : a.site_Se) {
    PlotSeries s = series("Se " + to_string(ls), PlotSeries::Style::Line, a.periods);
    for (double v : se) s.y.push_back(v / g);
    s.highlight = ls == LimitState::SLV;
    p.series.push_back(s);
  }
  for (std::size_t i = 0; i < a.record_psa.size(); ++i) {
    PlotSeries s = series(i == 0 ? c.t("site.records_scaled") : "", PlotSeries::Style::Dashed, a.periods);
    for (double v : a.record_psa[i]) s.y.push_back(v / g);
    s.color = "#999999";
    p.series.push_back(s);
  }
  if (!a.mean_psa.empty()) {
    PlotSeries s = series(c.t("site.records_mean"), PlotSeries::Style::Line, a.periods);
    for (double v : a.mean_psa) s.y.push_back(v / g);
    s.highlight = true;
    s.color = "#000000";
    p.series.push_back(s);
  }
  c.h.add_svg(render_svg(p), c.t("site.fig"), "fig-spectra");
}

// Issue 33: the quantities of the governing candidate's derivation (arch
// thrust, roof thrust, side walls' friction, alpha0 with and without a term,
// the axis of a corner) and the bound on its displacement capacity.
void add_derivation(const Ctx& c) {
  const MechanismCandidate& m = c.a.kase.mechanism.candidates.at(c.a.kinematic.governing);
  if (!m.quantities.empty()) {
    c.h.add_heading(c.t("mech.derivation"), 3);
    std::vector<std::vector<HtmlCell>> rows;
    for (const MechanismQuantity& q : m.quantities)
      rows.push_back({c.loc(q.label), HtmlCell(q.unit.empty() ? "" : format("%.4g", q.value), "num"),
                      q.unit == "-" ? "-" : q.unit, q.source == "input" ? c.t("data.case") : c.loc(q.source)});
    c.h.add_cell_table({c.t("kin.quantity"), HtmlCell(c.t("kin.value"), "num"), c.t("kin.unit"), c.t("data.source")},
                       rows, c.t("mech.derivation_cap"));
  }
  const KinematicResult& k = c.k();
  if (std::isfinite(k.d0_star_bound) && k.d0_star_bound < k.d0_star)
    c.h.add_paragraph(msgf(c.L, "mech.bound", format("%.3f", k.d0_star), format("%.3f", k.d0_star_bound),
                           c.loc(m.rotation_bound_reason)));
}

void add_mechanism(const Ctx& c) {
  const FacadeAssessment& a = c.a;
  c.h.add_heading(c.t("mech.heading"));
  const std::size_t gi = a.kinematic.governing;
  c.h.add_paragraph(c.t("mech.type") + ": " + mechanism_name(c.L, a.kase.mechanism.type) + "; " +
                    c.t("mech.governing") + ": " + c.loc(c.gc().label) + " (Z = " + fixed(c.gc().Z, 2) + " m).");
  const Chain& chain = a.kase.mechanism.candidates.at(gi).chain;
  bool welded = false;  // issue 33: the corner's pieces, projected on the plane normal to the axis
  for (const Constraint& k : chain.constraints()) welded = welded || k.type == ConstraintType::Weld;
  c.h.add_svg(mechanism_svg(chain, c.k(), c.L),
              c.t(chain.plan() ? "mech.fig_plan" : welded ? "mech.fig_projection" : "mech.fig"), "fig-mechanism");
  add_derivation(c);

  // Virtual-work table (C8A.4.1 / C8.7.1.1).
  c.h.add_heading(c.t("mech.vw"), 3);
  std::vector<std::vector<HtmlCell>> rows;
  for (const LoadWork& w : c.k().loads) {
    const bool weight = w.load.type == LoadType::Weight || w.load.type == LoadType::SelfWeight;
    rows.push_back({c.loc(w.load.name), c.t("load." + to_string(w.load.type)), num(w.load.point.x(), 3),
                    num(w.load.point.y(), 3), num((weight ? w.load.weight : w.load.force.norm()) / units::kN, 2),
                    num(w.dx, 4), num(w.dz, 4), num(w.W_dx / units::kN, 3), num(w.W_dx2 / units::kN, 3),
                    num(w.work / units::kN, 3)});
  }
  rows.push_back({HtmlCell(c.t("mech.sum"), "gov"), HtmlCell("", "gov"), HtmlCell("", "gov"), HtmlCell("", "gov"),
                  num(c.k().sum_W / units::kN, 2, "gov"), HtmlCell("", "gov"), HtmlCell("", "gov"),
                  num(c.k().sum_W_dx / units::kN, 3, "gov"), num(c.k().sum_W_dx2 / units::kN, 3, "gov"),
                  num(c.k().work_other / units::kN, 3, "gov")});
  c.h.add_cell_table({c.t("mech.load"), c.t("mech.kind"), HtmlCell("x (m)", "num"), HtmlCell("z (m)", "num"),
                 HtmlCell("W, F (kN)", "num"), HtmlCell("δx (m)", "num"), HtmlCell("δz (m)", "num"),
                 HtmlCell("W·δx (kN m)", "num"), HtmlCell("W·δx² (kN m²)", "num"),
                 HtmlCell(c.t("mech.work") + " (kN m)", "num")},
                rows, c.t(chain.plan() ? "mech.vw_cap_plan" : "mech.vw_cap"));

  // Candidates (the governing one of each code: the largest D/C over its checks, Circ. 2019 C8.7.1).
  if (a.kinematic.candidates.size() > 1) {
    c.h.add_heading(c.t("mech.candidates"), 3);
    std::vector<HtmlCell> head{c.t("mech.candidate"), HtmlCell(c.loc(a.kase.mechanism.parameter_name), "num"),
                               HtmlCell("Z (m)", "num"), HtmlCell("α0 (-)", "num"), HtmlCell("a0* (m/s²)", "num")};
    for (const auto& [code, g] : a.kinematic.governing_by_code) head.push_back(HtmlCell("D/C " + code_name(code), "num"));
    if (!a.kinematic.governing_by_code.empty()) head.push_back(HtmlCell("ag,cap (g)", "num"));
    head.push_back(c.t("mech.governs"));
    std::vector<std::vector<HtmlCell>> crows;
    for (std::size_t i = 0; i < a.kinematic.candidates.size(); ++i) {
      const CandidateResult& cr = a.kinematic.candidates[i];
      std::string gov;
      for (const auto& [code, g] : a.kinematic.governing_by_code)
        if (g == i) gov += (gov.empty() ? "" : ", ") + code_name(code);
      if (a.kinematic.governing_by_code.empty() && i == gi) gov = "α0 min";
      const std::string cls = gov.empty() ? "" : "gov";
      std::vector<HtmlCell> row{HtmlCell(c.loc(cr.label), cls), num(cr.parameter, 3, cls), num(cr.Z, 2, cls),
                                num(cr.result.alpha0, 4, cls), num(cr.result.a0_star, 3, cls)};
      for (const auto& [code, g] : a.kinematic.governing_by_code) {
        const auto it = cr.max_dc.find(code);
        if (it == cr.max_dc.end()) row.push_back(HtmlCell("—", "num " + cls));
        else {
          HtmlCell d = dc_cell(it->second, !(it->second <= 1.0));
          d.cls += cls.empty() ? "" : " " + cls;
          row.push_back(d);
        }
      }
      if (!a.kinematic.governing_by_code.empty()) row.push_back(num(cr.ag_capacity_min_g, 4, cls));
      row.push_back(HtmlCell(gov, cls));
      crows.push_back(row);
    }
    c.h.add_cell_table(head, crows, msgf(c.L, "mech.candidates_cap", c.loc(a.kase.mechanism.parameter_name)));
  }
}

void add_kinematic(const Ctx& c) {
  const KinematicResult& k = c.k();
  c.h.add_heading(c.t("kin.heading"));
  auto row = [&](const char* key, double v, int prec, const char* unit, const std::string& clause) {
    return std::vector<HtmlCell>{c.t(key), num(v, prec), unit, clause};
  };
  std::vector<std::vector<HtmlCell>> rows{
      row("kin.alpha0", k.alpha0, 4, "-", "C8A.4.1 / C8.7.1.1"),
      row("kin.M", k.M_star / units::tonne, 3, "t", "C8A.4.2"),
      row("kin.e", k.e_star, 4, "-", "C8A.4.3 / C8.7.1.5"),
      row("kin.FC", k.FC, 2, "-", c.a.kase.knowledge_level + ", C8.5.4"),
      row("kin.a0", k.a0_star, 4, "m/s²", "C8A.4.4 / C8.7.1.3"),
  };
  if (k.curve_complete()) {
    rows.push_back(row("kin.dk0", k.dk0, 4, "m", "C8A.4.5"));
    rows.push_back(row("kin.d0", k.d0_star, 4, "m", "C8A.4.5 / C8.7.1.4"));
    rows.push_back(row("kin.du", k.du_star, 4, "m", "C8A.4.7"));
    rows.push_back(row("kin.Ts", k.Ts, 3, "s", "C8A.4.7"));
    rows.push_back(row("kin.dSLV", k.d_SLV, 4, "m", "C8.7.1.2.1.6"));
    rows.push_back(row("kin.TSLV", k.T_SLV, 3, "s", "C8.7.1.10"));
    rows.push_back(row("kin.dSLC", k.d_SLC, 4, "m", "C8.7.1.2.1.6"));
    rows.push_back(row("kin.TSLC", k.T_SLC, 3, "s", "C8.7.1.11"));
  }
  c.h.add_cell_table({c.t("kin.quantity"), HtmlCell(c.t("kin.value"), "num"), c.t("kin.unit"), c.t("kin.clause")}, rows,
                "");
  if (!k.curve_complete()) {
    c.h.add_paragraph(c.t("kin.incomplete") + ": " + k.message);
    return;
  }
  if (k.curve.empty()) return;
  // ADRS: capacity curve, SLV/SLC demand spectra (Sa against SDe), check points.
  Plot p;
  p.title = c.t("kin.adrs_title");
  p.x_label = c.t("kin.adrs_x");
  p.y_label = c.t("kin.adrs_y");
  PlotSeries cap = series(c.t("kin.adrs_curve"), PlotSeries::Style::Line);
  for (const CapacityPoint& q : k.curve) cap.x.push_back(q.d_star), cap.y.push_back(q.a_star);
  cap.highlight = true;
  cap.color = "#000000";
  p.series.push_back(cap);
  double d_show = k.d0_star;
  // Each displacement check of the governing candidate (issue 24): its demand
  // curve at its own damping (floor spectrum at height), the secant line from
  // the origin through the point that defines its period, the demand on that
  // line and the capacity on the curve.
  const auto a_on_curve = [&](double d) {
    for (std::size_t i = 1; i < k.curve.size(); ++i)
      if (d <= k.curve[i].d_star) {
        const CapacityPoint &p0 = k.curve[i - 1], &p1 = k.curve[i];
        const double t = (p1.d_star > p0.d_star) ? (d - p0.d_star) / (p1.d_star - p0.d_star) : 0.0;
        return p0.a_star + t * (p1.a_star - p0.a_star);
      }
    return k.curve.back().a_star;
  };
  std::vector<const CheckRow*> disp_rows;
  for (const CheckRow& row : c.gc().checks)
    if (row.kind == "displacement") disp_rows.push_back(&row);
  static const char* palette[] = {"#1f5fbf", "#b3001b", "#2b7a2b", "#d9730d", "#8a3ea8", "#17becf"};
  for (std::size_t i = 0; i < disp_rows.size() && i < c.a.adrs.size(); ++i) {
    const CheckRow& row = *disp_rows[i];
    const AdrsDemand& dem = c.a.adrs[i];
    const std::string colour = palette[i % 6];
    const std::string who = code_name(row.code) + " " + row.limit_state +
                            (row.location == "height" ? " (" + c.t("where.height") + ")" : "");
    PlotSeries s = series(msgf(c.L, "kin.adrs_spectrum", code_name(row.code), row.limit_state +
                              (row.location == "height" ? " (" + c.t("where.height") + ")" : std::string()),
                              fixed(dem.xi_pct, 0)),
                          row.code == "NTC2008" ? PlotSeries::Style::Dashed : PlotSeries::Style::Line, dem.Sd, dem.Sa);
    s.color = colour;
    p.series.push_back(s);
    const double T = row.secant_T;
    if (T > 0.0 && row.secant_d > 0.0 && std::isfinite(row.demand)) {
      // The line of the period T at which the demand is read, Sa = (2 pi / T)^2 Sd; T is defined by the
      // point (secant_d, secant_a): NTC 2008 Ts = 2 pi sqrt(ds*/as*) [C8A.4.7] passes through it, NTC 2018
      // T_SLV = 1.68 pi sqrt(d/a(d)) [C8.7.1.10] (1.56 pi for SLC [C8.7.1.11]) is shorter than the secant
      // through the capacity point, so that line is steeper (the caption says so).
      const double slope = std::pow(2.0 * pi / T, 2);
      const double x_end = 1.1 * std::max({row.demand, row.capacity, row.secant_d});
      PlotSeries line = series(i == 0 ? msgf(c.L, "kin.adrs_secant", "") : "", PlotSeries::Style::Dashed,
                               {0.0, x_end}, {0.0, slope * x_end});
      line.color = "#888888";
      p.series.push_back(line);
      PlotSeries d = series(msgf(c.L, "kin.adrs_demand", who), PlotSeries::Style::Points, {row.demand},
                            {row.demand * slope});
      d.color = colour;
      d.point_size = 1.3;
      d.point_type = 7;
      p.series.push_back(d);
      if (row.code == "NTC2008") {  // the point that defines Ts (ds*, as*), not the capacity du* (NTC 2018: the capacity)
        PlotSeries q = series("", PlotSeries::Style::Points, {row.secant_d}, {row.secant_a});
        q.color = colour;
        q.point_type = 9;
        q.point_size = 1.1;
        p.series.push_back(q);
      }
      d_show = std::max(d_show, x_end);
    }
    PlotSeries q = series(msgf(c.L, "kin.adrs_capacity", who), PlotSeries::Style::Points, {row.capacity},
                          {a_on_curve(row.capacity)});
    q.color = colour;
    q.point_type = 5;
    q.point_size = 1.1;
    p.series.push_back(q);
  }
  p.x_min = 0.0;
  p.x_max = 1.05 * d_show;
  p.y_min = 0.0;
  // Show the capacity curve and the check points; the spectra's plateau may
  // be cut (the checks are made on the descending branch).
  double a_top = 3.0 * k.a0_star;
  for (const PlotSeries& s : p.series)
    if (s.style == PlotSeries::Style::Points) a_top = std::max(a_top, 1.3 * s.y[0]);
  p.y_max = a_top;
  p.key = "below";  // the legend under the plot: it never hides a curve or a check point
  p.height = 460 + 16 * int((p.series.size() + 1) / 2);
  c.h.add_svg(render_svg(p), c.t("kin.adrs_fig"), "fig-adrs");
}

// The rows of a checks table: every check with every input of its demand
// (issue 24), red only where the check fails, the reason in the same row.
std::vector<std::vector<HtmlCell>> check_rows(const Ctx& c, const std::vector<CheckRow>& checks) {
  std::vector<std::vector<HtmlCell>> rows;
  for (const CheckRow& r : checks) {
    const bool fails = check_fails(r);
    const int prec = 4;
    std::string inputs;  // every input of the demand (issue 24), "T1 (s) = 0.227"
    for (const auto& [name, v] : r.inputs) inputs += (inputs.empty() ? "; " : ", ") + name + " = " + format("%.4g", v);
    rows.push_back({code_name(r.code), HtmlCell(c.check_name(r), "", c.loc(r.formula + "; " + r.clause) + inputs),
                    num(r.demand, prec), num(r.capacity, prec), r.unit == "m/s2" ? "m/s²" : r.unit,
                    dc_cell(r.dc, !(r.dc <= 1.0)),
                    r.has_pga ? HtmlCell(fixed(r.ag_capacity_g, 3) + " / " + fixed(r.ag_demand_g, 3), "num")
                              : HtmlCell("—", "num"),
                    HtmlCell(c.t(fails ? "fail" : "ok"), fails ? "fail" : "ok",
                             fails && r.dc <= 1.0 ? c.loc(r.note) : "")});
  }
  return rows;
}

std::vector<HtmlCell> check_head(const Ctx& c) {
  return {c.t("checks.code"), c.t("checks.check"), HtmlCell(c.t("checks.demand"), "num"),
          HtmlCell(c.t("checks.capacity"), "num"), c.t("kin.unit"), HtmlCell("D/C", "num"),
          HtmlCell(c.t("checks.ag"), "num"), c.t("checks.outcome")};
}

// The checks of candidate i that are not in the body's table: those of the
// codes it does not govern (the body lists each code's governing candidate).
std::vector<CheckRow> appendix_checks(const FacadeAssessment& a, std::size_t i) {
  std::vector<CheckRow> out;
  for (const CheckRow& r : a.kinematic.candidates[i].checks) {
    const auto g = a.kinematic.governing_by_code.find(r.code);
    if (g == a.kinematic.governing_by_code.end() || g->second != i) out.push_back(r);
  }
  return out;
}

bool has_appendix_checks(const FacadeAssessment& a) {
  for (std::size_t i = 0; i < a.kinematic.candidates.size(); ++i)
    if (!appendix_checks(a, i).empty()) return true;
  return false;
}

void add_checks(const Ctx& c) {
  if (c.a.checks.empty()) return;
  c.h.add_heading(c.t("checks.heading"), 2, false);
  // The body: the checks of each code's governing candidate and every dynamic
  // check; the other candidates' checks are in the appendix, so that the
  // counts of the verdict box are the rows of these tables (issue 24).
  if (has_appendix_checks(c.a)) c.h.add_paragraph(c.t("checks.body_note"));
  c.h.add_cell_table(check_head(c), check_rows(c, c.a.checks), "", "checks");
}

// Appendix: every check of the other candidates, one table per candidate.
void add_checks_appendix(const Ctx& c) {
  if (!has_appendix_checks(c.a)) return;
  c.h.add_heading(c.t("checks_all.heading"));
  c.h.add_paragraph(c.t("checks_all.note"));
  for (std::size_t i = 0; i < c.a.kinematic.candidates.size(); ++i) {
    const std::vector<CheckRow> rows = appendix_checks(c.a, i);
    if (rows.empty()) continue;
    const CandidateResult& cr = c.a.kinematic.candidates[i];
    c.h.add_heading(c.loc(cr.label) + " (α0 = " + fixed(cr.result.alpha0, 4) + ", a0* = " + fixed(cr.result.a0_star, 3) +
                        " m/s²)",
                    3);
    c.h.add_cell_table(check_head(c), check_rows(c, rows), "", "checks");
  }
}

void add_records_compatibility(const Ctx& c) {
  const FacadeAssessment& a = c.a;
  const auto se = a.site_Se.find(LimitState::SLV);
  if (se == a.site_Se.end() || a.record_psa.empty()) return;
  Plot p;
  p.title = c.t("dyn.compat_title");
  p.x_label = "T (s)";
  p.y_label = "Se, PSA (g)";
  const PeriodRange& rg = a.compatibility.computed ? a.compatibility.range : a.selection_range;
  if (rg.T_max > rg.T_min) {
    PlotSeries band = series(c.t("dyn.band"), PlotSeries::Style::Band);
    for (std::size_t i = 0; i < a.periods.size(); ++i) {
      const double T = a.periods[i];
      if (T < rg.T_min || T > rg.T_max) continue;
      band.x.push_back(T);
      band.y.push_back(1.3 * se->second[i] / g);
      band.y_low.push_back(0.9 * se->second[i] / g);
    }
    band.color = "#1f5fbf";
    if (!band.x.empty()) p.series.push_back(band);
  }
  PlotSeries target = series("Se SLV", PlotSeries::Style::Line, a.periods);
  for (double v : se->second) target.y.push_back(v / g);
  target.color = "#1f5fbf";
  target.highlight = true;
  p.series.push_back(target);
  for (std::size_t i = 0; i < a.record_psa.size(); ++i) {
    PlotSeries s = series(i == 0 ? c.t("site.records_scaled") : "", PlotSeries::Style::Line, a.periods);
    for (double v : a.record_psa[i]) s.y.push_back(v / g);
    s.color = "#aaaaaa";
    p.series.push_back(s);
  }
  if (!a.mean_psa.empty()) {
    PlotSeries s = series(c.t("site.records_mean"), PlotSeries::Style::Line, a.periods);
    for (double v : a.mean_psa) s.y.push_back(v / g);
    s.color = "#000000";
    s.highlight = true;
    p.series.push_back(s);
  }
  double top = 0.0;
  for (double v : se->second) top = std::max(top, 1.3 * v / g);
  for (double v : a.mean_psa) top = std::max(top, v / g);
  if (rg.T_max > rg.T_min) {
    PlotSeries l1 = series(c.t("dyn.range"), PlotSeries::Style::Dashed, {rg.T_min, rg.T_min}, {0.0, 1.2 * top});
    PlotSeries l2 = series("", PlotSeries::Style::Dashed, {rg.T_max, rg.T_max}, {0.0, 1.2 * top});
    l1.color = l2.color = "#444444";
    p.series.push_back(l1);
    p.series.push_back(l2);
  }
  p.y_min = 0.0;
  p.y_max = 1.25 * top;
  p.x_min = 0.0;
  p.x_max = a.periods.empty() ? 4.0 : a.periods.back();
  c.h.add_svg(render_svg(p), c.t("dyn.compat_fig"), "fig-compatibility");
}

void add_histories(const Ctx& c) {
  const FacadeAssessment& a = c.a;
  std::vector<std::pair<std::string, std::string>> panels;
  static const char* colours[] = {"#1f5fbf", "#d9730d", "#2b7a2b", "#8a3ea8"};
  for (std::size_t ir = 0; ir < a.records.size(); ++ir) {
    Plot p;
    p.title = "";
    p.x_label = "t (s)";
    p.y_label = "θ/θu";
    p.width = 300;
    p.height = 190;
    p.font_size = 8;
    p.key = "off";
    double t_show = 0.0, t_last = 0.0;
    for (const DynamicRun& r : a.runs)
      if (r.record == ir) t_show = std::max(t_show, r.result.t_theta_max), t_last = std::max(t_last, r.result.t_end);
    p.x_min = 0.0;
    p.x_max = std::min(t_last, t_show + 10.0);
    if (!(p.x_max > 0.0)) p.x_max = 1.0;
    bool overturned = false;
    for (const DynamicRun& r : a.runs) {
      if (r.record != ir || r.result.history.t.empty()) continue;
      PlotSeries s = series("", r.reversed ? PlotSeries::Style::Dashed : PlotSeries::Style::Line);
      const std::vector<double>& t = r.result.history.t;
      const std::size_t n = std::size_t(std::upper_bound(t.begin(), t.end(), p.x_max) - t.begin());
      const std::size_t step = std::max<std::size_t>(1, n / 600);  // keep each panel small
      for (std::size_t i = 0; i < n; i += step) {
        s.x.push_back(t[i]);
        s.y.push_back(r.result.history.theta[i] / r.result.theta_u);
      }
      if (s.x.empty()) continue;
      s.color = colours[r.restitution % 4];
      p.series.push_back(s);
      if (r.result.overturned && r.result.t_overturn) {
        PlotSeries x = series("", PlotSeries::Style::Points, {*r.result.t_overturn}, {1.0});
        x.point_type = 2;
        x.point_size = 2.0;
        x.color = "#b3001b";
        p.series.push_back(x);
        overturned = true;
      }
    }
    if (p.series.empty()) continue;
    PlotSeries one = series("", PlotSeries::Style::Dashed, {0.0, p.x_max}, {1.0, 1.0});
    one.color = "#b3001b";
    p.series.push_back(one);
    p.y_min = -1.1;
    p.y_max = 1.1;
    panels.push_back({render_svg(p), a.records[ir].name + (overturned ? " — " + c.t("dyn.overturning") : "")});
  }
  if (!panels.empty()) c.h.add_svg_grid(panels, c.t("dyn.histories_fig"), "fig-histories");
}

// Analyses of restitution value `restitution` in which d0 was exceeded or the body overturned.
int collapses_of(const std::vector<DynamicRun>& runs, std::size_t restitution) {
  int n = 0;
  for (const DynamicRun& r : runs) n += r.restitution == restitution && r.collapse ? 1 : 0;
  return n;
}

// Why a restitution value's dynamic check fails (failed analyses, collapses,
// D/C > 1), for the outcome cell of its row; "" when satisfied or without a verdict.
std::string fail_reason(const Ctx& c, const std::vector<DynamicRun>& runs, const RestitutionSummary& x) {
  if (x.slv_satisfied || x.no_verdict) return "";
  const int collapses = collapses_of(runs, x.restitution);
  std::string why;
  if (x.failed > 0) why = msgf(c.L, "dyn.reason_failed", x.failed, x.analyses);
  if (collapses > 0) why += (why.empty() ? "" : "; ") + msgf(c.L, "dyn.reason_collapse", collapses, x.analyses);
  if (x.dc_slv > 1.0) why += (why.empty() ? "" : "; ") + c.t("dyn.reason_dc");
  return why;
}

// The dynamic analyses of the other candidates that govern a code or fail a
// kinematic check (issue 24): one row per candidate and restitution value,
// with the records each used (its own selection over its own periods).
void add_other_dynamics(const Ctx& c) {
  const FacadeAssessment& a = c.a;
  if (a.other_dynamics.empty()) return;
  c.h.add_heading(c.t("dyn.others"), 3);
  c.h.add_paragraph(c.t("dyn.others_text"));
  std::vector<std::vector<HtmlCell>> rows;
  for (std::size_t k = 0; k < a.other_dynamics.size(); ++k) {
    const FacadeAssessment& o = a.other_dynamics[k];
    const CandidateResult& cr = a.kinematic.candidates[a.other_dynamics_candidate[k]];
    if (!o.dynamic_applies) {
      rows.push_back({c.loc(cr.label), "—", "—", HtmlCell("—", "num"), HtmlCell("—", "num"), HtmlCell("—", "num"),
                      HtmlCell("—", "num"), HtmlCell("—", "num"), HtmlCell(c.t("dyn.na") + ": " + c.loc(o.dynamic_note))});
      continue;
    }
    std::string recs;
    for (const RecordUsed& r : o.records) recs += (recs.empty() ? "" : ", ") + r.name + " (" + fixed(r.scale, 2) + ")";
    for (const RestitutionSummary& x : o.summaries) {
      const int collapses = collapses_of(o.runs, x.restitution);
      const bool fails = !x.slv_satisfied || !std::isfinite(x.dc_slv);
      const std::string why = fail_reason(c, o.runs, x);
      rows.push_back({c.loc(cr.label), recs, c.loc(describe(o.dynamic->restitutions[x.restitution])),
                      HtmlCell(std::to_string(collapses) + " / " + std::to_string(x.analyses), "num"),
                      num(x.d_demand, 4), num(o.kinematic.candidates.front().result.d_SLV, 4),
                      x.no_verdict ? HtmlCell("—", "num") : dc_cell(x.dc_slv, !(x.dc_slv <= 1.0)),
                      num(x.mean_dc, 3),
                      x.no_verdict ? HtmlCell(c.t("verdict.no_verdict_short"), "fail")
                                   : HtmlCell(c.t(fails ? "fail" : "ok"), fails ? "fail" : "ok", why)});
    }
  }
  c.h.add_cell_table({c.t("dyn.candidate"), c.t("dyn.records_used"), c.t("dyn.restitution"),
                      HtmlCell(c.t("dyn.collapses"), "num"), HtmlCell(c.t("dyn.d_demand"), "num"),
                      HtmlCell("d_SLV (m)", "num"), HtmlCell(c.t("dyn.dc_slv"), "num"), HtmlCell(c.t("dyn.mean_dc"), "num"),
                      c.t("checks.outcome")},
                     rows, c.t("dyn.others_cap"));
}

void add_dynamic(const Ctx& c) {
  const FacadeAssessment& a = c.a;
  if (!a.dynamic) return;
  c.h.add_heading(c.t("dyn.heading"));
  if (!a.dynamic_applies) {
    c.h.add_paragraph(c.t("dyn.na") + ": " + c.loc(a.dynamic_note));
    return;
  }
  if (a.model) {
    const RockingModel& m = *a.model;
    c.h.add_paragraph(c.t(a.dynamic->smooth ? "dyn.smooth" : "dyn.rigid") + " (Lipo & de Felice 2017, Eq. 1), " +
                      c.t(m.sidedness() == Sidedness::one_sided ? "dyn.one_sided" : "dyn.two_sided") + "; W = " +
                      fixed(m.body().W / units::kN, 2) + " kN/m, b = " + fixed(m.body().b, 3) + " m, R = " +
                      fixed(m.body().R, 3) + " m, α = " + fixed(m.body().alpha, 4) + " rad, θu = " +
                      fixed(m.theta_u(+1), 4) + " rad, " + c.t("dyn.capacity") + " " +
                      fixed(m.capacity() / units::kN, 3) + " kJ/m.");
  }
  c.h.add_paragraph(c.t("dyn.model") + ": " + c.loc(a.mechanism_dynamics->describe()) + "; " + c.t("dyn.capacity") + " " +
                    fixed(a.mechanism_dynamics->capacity() / units::kN, 3) + " kJ/m.");
  Plot mr;
  mr.title = c.t("dyn.mr_title");
  mr.x_label = "θ (rad)";
  mr.y_label = "M (kN m/m)";
  PlotSeries s = series(c.t("dyn.mr_series"), PlotSeries::Style::Line, a.mr_theta);
  for (double v : a.mr_moment) s.y.push_back(v / units::kN);
  s.highlight = true;
  mr.series.push_back(s);
  mr.height = 320;
  c.h.add_svg(render_svg(mr), c.t(a.mechanism_dynamics->tied() ? "dyn.mr_fig_tied" : "dyn.mr_fig"), "fig-moment-rotation");
  if (!a.code_floor_Se.empty()) {
    Plot fp;
    fp.title = c.t("dyn.floor_title");
    fp.x_label = "T (s)";
    fp.y_label = "Sa (g)";
    PlotSeries fm = series(c.t("dyn.floor_series"), PlotSeries::Style::Line, a.periods);
    for (double v : a.floor_mean_psa) fm.y.push_back(v / g);
    fm.highlight = true;
    PlotSeries cf = series("S_eZ [C7.2.6]", PlotSeries::Style::Dashed, a.periods);
    for (double v : a.code_floor_Se) cf.y.push_back(v / g);
    fp.series.push_back(fm);
    fp.series.push_back(cf);
    c.h.add_svg(render_svg(fp), c.t("dyn.floor_fig"), "fig-floor-spectra");
  }

  c.h.add_heading(c.t("dyn.records"), 3);
  std::vector<std::vector<HtmlCell>> rrows;
  // Why each record was chosen (issue 24): magnitude, distance and its kind,
  // site class, scale, scaled PGA, individual deviation from the target and its rank.
  auto opt_num = [](double v, int prec) { return std::isfinite(v) ? num(v, prec) : HtmlCell("—", "num"); };
  for (const RecordUsed& r : a.records)
    rrows.push_back({r.name, r.event + " / " + r.station + ", " + r.component, opt_num(r.Mw, 2),
                     std::isfinite(r.distance_km) ? HtmlCell(fixed(r.distance_km, 1) + " " + r.distance_kind, "num")
                                                  : HtmlCell("—", "num"),
                     r.site_class.empty() ? HtmlCell("—") : HtmlCell(r.site_class), num(r.scale, 3), num(r.pga / g, 4),
                     opt_num(r.deviation, 3), r.rank > 0 ? num(r.rank, 0) : HtmlCell("—", "num"),
                     num(r.integrated_s, 1)});
  c.h.add_cell_table({c.t("dyn.record"), c.t("dyn.event_station"), HtmlCell("Mw", "num"), HtmlCell(c.t("dyn.distance"), "num"),
                      c.t("dyn.site_class"), HtmlCell(c.t("dyn.scale"), "num"), HtmlCell("PGA (g)", "num"),
                      HtmlCell(c.t("dyn.deviation"), "num"), HtmlCell(c.t("dyn.rank"), "num"),
                      HtmlCell(c.t("dyn.integrated"), "num")},
                     rrows, c.t("dyn.records_cap"));
  // The selection's caveats (default windows, relaxed site class): what a verificatore asks first.
  for (const std::string& w : a.selection_warnings) c.h.add_paragraph(c.t("dyn.selection_warning") + ": " + c.loc(w));
  for (const std::string& f : a.record_failures) c.h.add_paragraph(c.t("dyn.skipped") + ": " + f);
  if (a.selection)
    c.h.add_paragraph(msgf(c.L, "dyn.selection", fixed(a.selection_range.T_min, 2), fixed(a.selection_range.T_max, 2)) +
                      c.loc(a.selection->message));
  if (a.compatibility.computed) c.h.add_paragraph(c.t("dyn.compat_msg") + ": " + c.loc(a.compatibility.message) + ".");
  {
    std::map<std::string, int> ends;  // why each analysis ended (dynamics/analysis_end.hpp)
    for (const DynamicRun& r : a.runs) ++ends[to_string(r.result.end)];
    std::string list;
    for (const auto& [k, n] : ends) list += (list.empty() ? "" : ", ") + c.t("end." + k) + " " + std::to_string(n);
    c.h.add_paragraph(c.t("dyn.duration") + " " + fixed(a.free_tail_s, 0) + " s. " + c.t("dyn.ends") + ": " + list +
                      ".");
  }
  add_records_compatibility(c);
  c.h.add_heading(c.t("dyn.histories"), 3);
  add_histories(c);

  c.h.add_heading(c.t("dyn.summary"), 3);
  std::vector<std::vector<HtmlCell>> srows;
  for (const RestitutionSummary& x : a.summaries) {
    const bool fails = !x.slv_satisfied || !std::isfinite(x.dc_slv);
    srows.push_back({c.restitution(x.restitution), num(x.analyses, 0),
                     HtmlCell(std::to_string(x.overturned) + " / " + std::to_string(x.analyses) +
                                  (x.failed > 0 ? " (" + std::to_string(x.failed) + " " + c.t("dyn.failed") + ")" : ""),
                              x.failed > 0 ? "num fail" : "num"),
                     num(x.mean_dc, 3), num(x.max_dc, 3), num(x.mean_d_star, 4), num(x.max_d_star, 4), c.loc(x.rule),
                     // Red only where the D/C itself exceeds 1; a check that fails for another
                     // reason (d0 exceeded, a failed analysis) says why in its own row (issue 24).
                     x.no_verdict ? HtmlCell("—", "num") : dc_cell(x.dc_slv, !(x.dc_slv <= 1.0)),
                     x.no_verdict ? HtmlCell(c.t("verdict.no_verdict_short"), "fail")
                                  : HtmlCell(c.t(fails ? "fail" : "ok"), fails ? "fail" : "ok", fail_reason(c, a.runs, x))});
  }
  c.h.add_cell_table({c.t("dyn.restitution"), HtmlCell(c.t("dyn.analyses"), "num"),
                      HtmlCell(c.t("dyn.overturned"), "num"), HtmlCell(c.t("dyn.mean_dc"), "num"),
                      HtmlCell(c.t("dyn.max_dc"), "num"), HtmlCell(c.t("dyn.mean_d"), "num"),
                      HtmlCell(c.t("dyn.max_d"), "num"), c.t("dyn.rule"), HtmlCell(c.t("dyn.dc_slv"), "num"),
                      c.t("checks.outcome")},
                     srows, c.t("dyn.summary_cap"));
  add_other_dynamics(c);
}

// Grouped D/C bars (Lipo & de Felice 2017, Fig. 8) of the summary by approach
// built in the assessment (assessment/verdict.hpp): one group per code, one
// named bar per approach (limit state, location, restitution), the line D/C = 1;
// then the summary table and the overall verdict per code.
void add_comparison(const Ctx& c) {
  const Verdict& v = c.a.verdict;
  if (v.rows.empty()) return;
  c.h.add_heading(c.t("cmp.heading"));
  Plot p;
  p.title = c.t("cmp.title");
  p.y_label = "D/C (-)";
  p.bar_width = 0.8;
  p.rotate_x_tic_labels = true;
  p.height = 480;
  p.width = 720;
  p.key = "outside right top";
  static const char* colours[] = {"#1f5fbf", "#d9730d", "#2b7a2b", "#8a3ea8", "#7f7f7f", "#17becf"};
  auto bar_name = [&](const VerdictRow& r) {
    std::string n = c.kind_name(r.approach) + " " + r.limit_state;
    if (r.location == "height") n += " (" + c.t("where.height") + ")";
    if (r.approach == "dynamic" || r.approach == "dynamic energy") n += ", " + c.loc(r.clause.substr(r.clause.rfind(", ") + 2));
    return n;
  };
  // Short tick labels under the bars (the table below names each row in full).
  auto short_name = [&](const VerdictRow& r) {
    std::string n = c.t("short." + std::string(r.approach == "dynamic energy" ? "energy" : r.approach)) + " " +
                    r.limit_state;
    if (r.location == "height") n += " " + c.t("short.height");
    if (r.approach == "dynamic" || r.approach == "dynamic energy") {
      const std::string e = c.loc(r.clause.substr(r.clause.rfind(", ") + 2));
      n += " " + (e.rfind("e = ", 0) == 0 ? "e=" + e.substr(4) : e);
    }
    return n;
  };
  std::vector<std::string> groups;
  for (const VerdictRow& r : v.rows)
    if (std::find(groups.begin(), groups.end(), r.code) == groups.end()) groups.push_back(r.code);
  double x = 0.0, dc_max = 1.0;
  std::vector<std::vector<HtmlCell>> rows;
  for (std::size_t gi = 0; gi < groups.size(); ++gi) {
    PlotSeries bars = series(groups[gi] == "seed" ? c.t("cmp.group_seed") : code_name(groups[gi]), PlotSeries::Style::Bars);
    bars.color = colours[gi % 6];
    for (const VerdictRow& r : v.rows) {
      if (r.code != groups[gi]) continue;
      const double dc = std::isfinite(r.dc) ? r.dc : 0.0;
      bars.x.push_back(x);
      bars.y.push_back(dc);
      p.x_tic_labels.push_back({x, short_name(r)});
      dc_max = std::max(dc_max, dc);
      const bool fails = !r.satisfied || r.no_verdict || !std::isfinite(r.dc);
      std::string note = c.loc(r.candidate.empty() ? r.clause : r.candidate + "; " + r.clause);
      if (!r.note.empty()) note += "; " + c.loc(r.note);
      rows.push_back({groups[gi] == "seed" ? c.t("cmp.group_seed") : code_name(r.code), HtmlCell(bar_name(r), "", note),
                      r.no_verdict ? HtmlCell("—", "num") : dc_cell(r.dc, !(r.dc <= 1.0)),
                      r.code == "seed" ? HtmlCell(r.satisfied ? "≤ 1" : "> 1", r.satisfied ? "ok" : "fail")
                      : r.no_verdict   ? HtmlCell(c.t("verdict.no_verdict_short"), "fail")
                                       : HtmlCell(c.t(fails ? "fail" : "ok"), fails ? "fail" : "ok",
                                                  fails && r.dc <= 1.0 ? c.loc(r.note) : "")});
      x += 1.0;
    }
    p.series.push_back(bars);
    x += 0.6;  // gap between groups
  }
  PlotSeries one = series(c.t("cmp.line"), PlotSeries::Style::Dashed, {-0.6, x - 0.4}, {1.0, 1.0});
  one.color = "#b3001b";
  one.highlight = true;
  p.series.push_back(one);
  p.x_min = -0.6;
  p.x_max = x - 0.4;
  p.y_min = 0.0;
  p.y_max = 1.25 * dc_max;
  c.h.add_svg(render_svg(p), c.t("cmp.fig"), "fig-dc");
  c.h.add_cell_table({c.t("checks.code"), c.t("cmp.approach"), HtmlCell("D/C", "num"), c.t("checks.outcome")}, rows,
                     c.t("cmp.table_cap"));
  std::vector<std::vector<HtmlCell>> orows;
  for (const MethodVerdict& m : v.methods) {
    const bool ok = m.satisfied && std::isfinite(m.max_dc);
    orows.push_back({code_name(m.code) + (m.code == v.conclusion_code ? "" : " (" + c.t("verdict.comparison") + ")"),
                     c.t("method." + m.method) + (m.method == v.adopted ? " (" + c.t("verdict.adopted") + ")" : ""),
                     HtmlCell(c.t(ok ? "verdict.ok" : "verdict.fail"), ok ? "ok" : "fail"),
                     HtmlCell(std::to_string(m.failing) + " / " + std::to_string(m.checks), "num"),
                     num(m.no_verdict, 0), dc_cell(m.max_dc, !(m.max_dc <= 1.0))});
  }
  c.h.add_cell_table({c.t("checks.code"), c.t("cmp.method"), c.t("cmp.overall"), HtmlCell(c.t("cmp.failing"), "num"),
                      HtmlCell(c.t("verdict.no_verdict"), "num"), HtmlCell(c.t("cmp.max_dc"), "num")},
                     orows, "");
}

// The additional probabilistic result (issue 16; docs/theory/fragility.md §3):
// a neutral box after the verdicts by approach, labelled as not a code check,
// with the governing overturning fragility's median and beta, lambda_c, the
// return period 1/lambda_c and P = 1 - exp(-lambda_c VN) beside the code's SLV
// return period [NTC 2018 3.2.0]. Formatting only: numbers from the options.
void add_probabilistic(const Ctx& c) {
  if (!c.o.fragility) return;
  const ProbabilisticResult& r = *c.o.fragility;
  c.h.add_heading(c.t("prob.heading"), 2, false);
  std::string html = "<section class=\"probabilistic\" aria-label=\"" + xml_escape(c.t("prob.heading")) +
                     "\" style=\"border:2px solid #4a5a7a;border-radius:4px;background:#f2f4f8;padding:0.5em 0.8em;"
                     "margin:0.6em 0;break-inside:avoid\">\n";
  html += "<p><strong>" + xml_escape(c.t("prob.not_a_check")) + "</strong> " + xml_escape(c.t("prob.explain")) +
          "</p>\n";
  const std::string method = r.method == "ida" ? c.t("prob.method.ida") : c.t("prob.method.stripes");
  html += "<p class=\"meta\">" + xml_escape(c.t("prob.method")) + ": " + xml_escape(method) + "; " +
          std::to_string(r.analyses) + " " + xml_escape(c.t("prob.analyses")) + ", " + std::to_string(r.failed) + " " +
          xml_escape(c.t("prob.failed")) + ". " + xml_escape(c.t("prob.model")) + ": " + xml_escape(r.model) + ". " +
          xml_escape(c.t("prob.restitution")) + ": " + xml_escape(r.restitution) + ".</p>\n";
  auto row = [](const std::string& k, const std::string& v) {
    return "<tr><td>" + xml_escape(k) + "</td><td class=\"num\">" + xml_escape(v) + "</td></tr>\n";
  };
  const std::string years = " " + c.t("prob.years");
  html += "<table><thead><tr><th>" + xml_escape(c.t("prob.quantity")) + "</th><th class=\"num\">" +
          xml_escape(c.t("prob.value")) + "</th></tr></thead><tbody>\n";
  if (r.has_risk) {
    html += row(c.t("prob.median"), fixed(r.median_pga / g, 3) + " g");
    html += row(c.t("prob.beta"), fixed(r.beta, 3));
    html += row(c.t("prob.lambda"), format("%.3e", r.lambda) + c.t("prob.per_year"));
    html += row(c.t("prob.return_period"), fixed(r.return_period, 0) + years);
    html += row(c.t("prob.p_vn") + " (VN = " + fixed(r.VN, 0) + years + ")", fixed(100.0 * r.p_vn, 1) + " %");
  } else {
    html += row(c.t("prob.no_risk"), r.note);
  }
  html += row(c.t("prob.tr_slv"), fixed(r.TR_SLV, 0) + years);
  if (r.has_risk && std::isfinite(r.p_at_SLV))
    html += row(c.t("prob.p_at_slv") + " (" + fixed(r.pga_SLV / g, 3) + " g)", fixed(100.0 * r.p_at_SLV, 1) + " %");
  html += "</tbody></table>\n<p class=\"meta\">" + xml_escape(c.t("prob.cap")) + " " + xml_escape(c.t("prob.source")) +
          ": " + xml_escape(r.source) + "</p>\n</section>";
  c.h.add_raw_html(html);
}

void add_warnings(const Ctx& c) {
  if (c.a.warnings.empty()) return;
  c.h.add_heading(c.t("warnings.heading"), 2, false);
  // The warnings are the program's own sentences (English, as printed in the
  // terminal); marked lang="en" so the Italian edition declares them.
  if (c.L == Lang::it) c.h.add_paragraph(c.t("warnings.english"));
  std::string html = "<div class=\"warnings\" lang=\"en\">\n";
  for (const std::string& w : c.a.warnings) html += "<p>" + xml_escape(w) + "</p>\n";
  c.h.add_raw_html(html + "</div>");
}

void add_legend(const Ctx& c) {
  c.h.add_heading(c.t("legend.heading"), 2, false);
  c.h.add_raw_html("<ul class=\"legend\">\n<li>" + xml_escape(c.t("legend.VT")) + "</li>\n<li>" +
                   xml_escape(c.t("legend.VS")) + "</li>\n<li>" + xml_escape(c.t("legend.R")) + "</li>\n<li>" +
                   xml_escape(c.t("legend.dc")) + "</li>\n</ul>");
}

void add_appendix(const Ctx& c) {
  c.h.add_heading(c.t("appendix.heading"));
  c.h.add_paragraph(c.t("appendix.note") + " (" + shown_file(c.a.kase.file) + ")");
  c.h.add_pre(c.o.case_text.empty() ? c.t("appendix.missing") : c.o.case_text);
}

}  // namespace

int governing_verdict_row(const Verdict& v, const std::string& code) {
  auto rank = [](const VerdictRow& r) {
    if (r.no_verdict || !std::isfinite(r.dc)) return std::make_pair(2, 0.0);
    return std::make_pair(r.satisfied ? 0 : 1, r.dc);
  };
  int best = -1;
  for (std::size_t i = 0; i < v.rows.size(); ++i) {
    if (v.rows[i].code != code) continue;
    if (best < 0 || rank(v.rows[i]) > rank(v.rows[std::size_t(best)])) best = int(i);
  }
  return best;
}

std::string facade_html(const FacadeAssessment& a, const ReportOptions& options) {
  const Lang L = options.lang;
  HtmlReport h(msg(L, "doc.title"));
  h.set_lang(to_string(L));
  const Ctx c{a, options, L, h};
  add_header(c);
  add_verdict_box(c);
  add_premessa(c);
  add_data(c);
  add_site(c);
  add_mechanism(c);
  add_kinematic(c);
  add_checks(c);
  add_dynamic(c);
  add_comparison(c);
  // ---- issue 23: tie rods, a section of its own (tie_html.cpp) ----
  if (options.ties) {
    h.add_heading(tie_section_title(L));
    h.add_raw_html(tie_html_section(*options.ties, L));
  }
  // ---- end issue 23 ----
  add_probabilistic(c);
  add_warnings(c);
  add_conclusions(c);
  add_legend(c);
  add_checks_appendix(c);
  add_appendix(c);
  return h.str();
}

// The building relazione (issue 22, building_html.cpp) reuses these sections.
void facade_html_site_section(const FacadeAssessment& a, const ReportOptions& options, HtmlReport& h) {
  const Ctx c{a, options, options.lang, h};
  add_site(c);
}

void facade_html_mechanism_sections(const FacadeAssessment& a, const ReportOptions& options, HtmlReport& h) {
  const Ctx c{a, options, options.lang, h};
  add_verdict_box(c);
  add_data(c);
  add_mechanism(c);
  add_kinematic(c);
  add_checks(c);
  add_dynamic(c);
  add_comparison(c);
  // Issue 23: the mechanism's tie rods (the building's "ties"/"design"), as in
  // facade_html; ids prefixed and subheadings shifted with the nesting.
  if (options.ties) {
    h.add_heading(tie_section_title(c.L));
    h.add_raw_html(tie_html_section(*options.ties, c.L, h.id_prefix(), 3 + h.heading_shift()));
  }
  add_warnings(c);
  add_checks_appendix(c);  // every other candidate's checks: the verdict box counts are the rows shown
}

}  // namespace assess
