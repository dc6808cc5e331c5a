// tie_html.cpp: the section of the relazione on the tie rods (issues 23,
// 29): the stato di fatto and the stato di progetto, the ties drawn on the
// mechanism, each level's rod, ends, anchor and layout, the formulas with
// their sources, the checks (capacity design), the force each check needs,
// the two states side by side, the dynamic analyses with each tie's outcome,
// the detailing; and the readings adopted (tie_readings, for the appendix:
// the body carries no certainty tag). Formatting only; every sentence is in
// the message catalogue (messages_ties.cpp, keys "tie.*").
#include "assess/report/tie_report.hpp"

#include "assess/kinematic/tie_catalogue.hpp"
#include "assess/report/mechanism_drawing.hpp"
#include "assess/support/units.hpp"
#include "report/text_format.hpp"
#include "report/xml_escape.hpp"

#include <cmath>

namespace assess {
namespace {

using detail::xml_escape;
constexpr double kN = units::kN;

std::string td(const std::string& s) { return "<td>" + s + "</td>"; }
std::string tdn(const std::string& s) { return "<td class=\"num\">" + s + "</td>"; }
std::string th(const std::string& s) { return "<th>" + s + "</th>"; }
std::string fnum(double v, const char* f) { return std::isfinite(v) ? format(f, v) : std::string("–"); }

struct Ctx {
  Lang L;
  const std::string& t(const std::string& key) const { return msg(L, "tie." + key); }
  template <class... A>
  std::string f(const std::string& key, const A&... a) const {
    return msgf(L, "tie." + key, a...);
  }
  std::string ok(bool v) const {
    return std::string("<td style=\"color:") + (v ? "#1a7f37" : "#c62828") + "\">" + t(v ? "ok" : "ko") + "</td>";
  }
};

std::string component(const Ctx& c, const std::string& name) { return c.t("component." + name); }

std::string rod_cell(const Ctx& c, const Tie& x) {
  return (x.rod.diameter > 0.0 ? format("Ø%.0f mm", x.rod.diameter * 1e3) : format("A = %.0f mm²", x.rod.area * 1e6)) +
         " " + x.rod.grade + format(" (A = %.0f mm²)", x.rod.area * 1e6);
}

std::string ends_cell(const Ctx& c, const Tie& x) {
  return c.t("ends." + std::string(to_string(x.rod.ends))) + format(" M%.0f, A_res = %.1f mm²", x.rod.thread_diameter * 1e3,
                                                                     x.rod.thread_area * 1e6);
}

std::string anchor_cell(const Ctx& c, const Tie& x) {
  return x.anchor.type == AnchorType::Plate
             ? c.t("plate") + format(" %.0f × %.0f × %.0f mm ", x.anchor.a * 1e3, x.anchor.b * 1e3, x.anchor.t * 1e3) +
                   x.anchor.grade
             : c.t("bar") + format(" %.0f mm, Ø%.0f mm ", x.anchor.a * 1e3, x.anchor.b * 1e3) + x.anchor.grade;
}

std::string layout_cell(const Ctx& c, const Tie& x) {
  const TieLayout& L = x.layout;
  std::string s = c.f("layout_n", L.count, format("%.2f", L.wall_length));
  if (L.count > 1) s += ", " + c.f("layout_i", format("%.2f", L.centre_spacing()));
  return s + ", " + c.f("layout_e", format("%.2f", L.edge_distance));
}

// The governing candidate's chain of a state with each level drawn as a tie
// arrow of its design strength, labelled per tie and per level.
std::string drawing(const Ctx& c, const CaseFile& kase, const KinematicCaseResult& r,
                    const std::vector<TieLevelResult>& levels) {
  const CandidateResult& cr = r.candidates[r.governing];
  const Chain& chain = kase.mechanism.candidates[r.governing].chain;
  std::vector<Load> loads;
  for (const Load& l : chain.loads())
    if (l.type != LoadType::SelfWeight) loads.push_back(l);
  for (const TieWork& w : cr.result.ties) {
    Load l;
    l.type = LoadType::Tie;
    l.name = w.tie.name;
    l.block = w.tie.block;
    l.point = w.tie.point;
    l.force = w.tie.capacity * w.tie.direction;
    for (const TieLevelResult& x : levels)
      if (x.tie.name == w.tie.name)
        l.label = c.f("drawing_label", format("%.1f", x.resistance.design / kN),
                      format("%.1f", x.resistance.design * x.tie.layout.count / kN));
    loads.push_back(l);
  }
  try {
    const Chain drawn(chain.blocks(), chain.constraints(), loads);
    return mechanism_svg(drawn, cr.result, c.L);
  } catch (const std::exception&) {
    return mechanism_svg(chain, cr.result, c.L);
  }
}

std::string levels_table(const Ctx& c, const std::vector<TieLevelResult>& levels) {
  std::string h = "<table class=\"data\"><tr>" + th(c.t("level")) + th(c.t("state")) + th(c.t("rod")) + th(c.t("ends")) +
                  th(c.t("anchor")) + th(c.t("layout")) + th(c.t("free_length")) + th(c.t("pretension")) +
                  th(c.t("T_Rd_tie")) + th(c.t("T_Rd_level")) + th(c.t("behaviour")) + "</tr>\n";
  for (const TieLevelResult& L : levels) {
    const Tie& x = L.tie;
    h += "<tr>" + td(xml_escape(x.name)) + td(c.t(x.existing ? "existing" : "new")) + td(rod_cell(c, x)) +
         td(ends_cell(c, x)) + td(anchor_cell(c, x)) + td(layout_cell(c, x)) + tdn(format("%.2f", x.free_length)) +
         tdn(format("%.1f", x.pretension / kN)) +
         td(format("%.1f", L.resistance.design / kN) + " (" + component(c, L.resistance.governing) + ")") +
         tdn(format("%.1f", L.resistance.design * x.layout.count / kN)) +
         td(c.t(L.resistance.ductile ? "ductile" : "elastic")) + "</tr>\n";
  }
  return h + "</table>\n";
}

std::string formulas(const Ctx& c) {
  std::string h = "<ul class=\"formulas\">\n";
  for (const char* k : {"f.rod", "f.thread", "f.bearing", "f.punching", "f.plate", "f.bar", "f.hierarchy", "f.elastic",
                        "f.elongation", "f.capacity", "f.layout"})
    h += "<li>" + c.t(k) + "</li>\n";
  return h + "</ul>\n<p>" + c.t("f.note") + "</p>\n";
}

std::string checks_table(const Ctx& c, const TieLevelResult& L) {
  std::string h = "<table class=\"data\"><tr>" + th(c.t("check")) + th(c.t("clause")) + th(c.t("demand")) +
                  th(c.t("capacity")) + th(c.t("unit")) + th("D/C") + th(c.t("outcome")) + "</tr>\n";
  for (const TieCheckRow& r : L.checks) {
    const double s = r.unit == "mm" ? 1e3 : r.unit == "kN" ? 1.0 / kN : 1.0;
    const bool count = r.unit == "analyses";
    const std::string clause = r.clause.empty() ? "" : c.t("clause." + r.check);
    std::string demand = !r.reachable ? c.t("unreachable") : count ? format("%.0f", r.demand) : fnum(r.demand * s, "%.2f");
    std::string capacity = count ? "0" : fnum(r.capacity * s, "%.2f");
    std::string unit = count ? c.t("unit_analyses") : r.unit;
    h += "<tr>" + td(c.t("check." + r.check)) + td(xml_escape(clause)) + tdn(demand) + tdn(capacity) + td(unit) +
         tdn(r.reachable && !count ? fnum(r.dc, "%.3f") : "–") + c.ok(r.satisfied) + "</tr>\n";
  }
  return h + "</table>\n";
}

std::string required_table(const Ctx& c, const TieLevelResult& L) {
  std::string h = "<table class=\"data\"><tr>" + th(c.t("code")) + th(c.t("ls")) + th(c.t("kind")) + th(c.t("where")) +
                  th(c.t("per_tie")) + th(c.t("per_level")) + th(c.t("per_metre")) + th(c.t("dc_without")) + "</tr>\n";
  for (const RequiredTieForce& f : L.required) {
    h += "<tr>" + td(f.code) + td(f.limit_state) + td(c.t("kind." + f.kind)) + td(c.t("where." + f.location));
    if (f.reachable)
      h += tdn(format("%.2f", f.per_tie / kN)) + tdn(format("%.2f", f.per_tie * L.tie.layout.count / kN)) +
           tdn(format("%.2f", f.per_metre / kN));
    else
      h += "<td colspan=\"3\">" + c.t("unreachable") + ": " + c.t("unreachable_why") + "</td>";
    h += tdn(fnum(f.dc_without, "%.3f")) + "</tr>\n";
  }
  return h + "</table>\n";
}

std::string level_block(const Ctx& c, const TieLevelResult& L, const std::string& state, const std::string& ho,
                        const std::string& hc) {
  std::string h = ho + c.t("checks_title") + " — " + xml_escape(L.tie.name) + " (" + state + ")" + hc + "\n";
  const TieResistance& r = L.resistance;
  h += "<p>" +
       (r.ductile ? c.f("ductile_text", format("%.1f", r.hierarchy_demand / kN), component(c, r.weakest_brittle),
                        format("%.1f", r.weakest_brittle_capacity / kN), format("%.0f", r.ultimate_elongation * 1e3))
                  : c.f("elastic_text", component(c, r.weakest_brittle), format("%.1f", r.weakest_brittle_capacity / kN),
                        format("%.1f", r.hierarchy_demand / kN), format("%.2f", L.demand.elastic_demand() / kN))) +
       "</p>\n";
  std::string dem = c.f("demand_static", format("%.2f", L.demand.static_force / kN));
  if (L.demand.curve_force) dem += "; " + c.f("demand_curve", format("%.2f", *L.demand.curve_force / kN));
  if (L.demand.dynamic_force)
    dem += "; " + c.f("demand_dynamic", format("%.2f", *L.demand.dynamic_force / kN), L.demand.dynamic_runs);
  if (L.demand.dynamic_breaks > 0)
    dem += "; " + c.f("demand_broken", L.demand.dynamic_breaks, L.demand.dynamic_runs,
                      component(c, L.demand.dynamic_component));
  h += "<p>" + dem + ".</p>\n" + checks_table(c, L);
  h += ho + c.t("required_title") + " — " + xml_escape(L.tie.name) + hc + "\n" + required_table(c, L);
  return h;
}

std::string states_table(const Ctx& c, const TieInterventionResult& t) {
  const KinematicResult& b = t.before.candidates[t.before.governing].result;
  const KinematicResult& a = t.after.candidates[t.after.governing].result;
  auto dk = [](const KinematicResult& k, double v) { return k.curve_complete() ? fnum(v, "%.4f") : std::string("–"); };
  std::string h = "<table class=\"data\"><tr>" + th("") + th(c.t("before")) + th(c.t("after")) + "</tr>\n";
  auto row = [&](const std::string& label, const std::string& x, const std::string& y) {
    h += "<tr>" + td(label) + tdn(x) + tdn(y) + "</tr>\n";
  };
  row("α0", fnum(b.alpha0, "%.4f"), fnum(a.alpha0, "%.4f"));
  row("a0* (m/s²)", fnum(b.a0_star, "%.4f"), fnum(a.a0_star, "%.4f"));
  row("d0* (m)", dk(b, b.d0_star), dk(a, a.d0_star));
  row(c.t("d_tie"), dk(b, b.d_star_tie_limit), dk(a, a.d_star_tie_limit));
  row("d_SLV (m)", dk(b, b.d_SLV), dk(a, a.d_SLV));
  row("d_SLC (m)", dk(b, b.d_SLC), dk(a, a.d_SLC));
  row(c.t("d_SLV_plastic"), dk(b, b.d_SLV_plastic), dk(a, a.d_SLV_plastic));
  row(c.t("zeta"), fnum(t.zetaE_before, "%.3f"), fnum(t.zetaE_after, "%.3f"));
  h += "<tr>" + td(c.t("all_checks")) + c.ok(t.passes_before) + c.ok(t.passes_after) + "</tr>\n";
  const CandidateResult& cb = t.before.candidates[t.before.governing];
  const CandidateResult& ca = t.after.candidates[t.after.governing];
  for (const CheckRow& r : cb.checks) {
    const CheckRow* r2 = nullptr;
    for (const CheckRow& x : ca.checks)
      if (x.code == r.code && x.limit_state == r.limit_state && x.kind == r.kind && x.location == r.location) r2 = &x;
    auto mark = [&](const CheckRow* x) { return x && x->without_ties ? c.t("bare_mark") : std::string(); };
    row(r.code + " " + r.limit_state + " " + c.t("kind." + r.kind) + " " + c.t("where." + r.location) + " D/C",
        fnum(r.dc, "%.3f") + mark(&r), r2 ? fnum(r2->dc, "%.3f") + mark(r2) : "–");
  }
  return h + "</table>\n<p>" + c.t("plastic_note") + "</p>\n";
}

std::string run_outcome(const Ctx& c, const TieDynamicRun& r) {
  if (r.failed) return c.t("run_failed");
  for (const TieLevelRun& l : r.levels)
    if (l.broken)
      return "<span style=\"color:#c62828\">" +
             c.f("run_broken", xml_escape(l.name), component(c, l.component), format("%.2f", l.t_broken)) + "</span>";
  if (r.yielded) return c.f("run_yielded", format("%.1f", r.plastic_elongation * 1e3));
  return c.t("run_elastic");
}

std::string dynamics(const Ctx& c, const TieInterventionResult& t, const std::string& ho, const std::string& hc) {
  const TieDynamicResult& d = t.dynamics;
  std::string h = ho + c.t("dyn_title") + hc + "\n";
  if (!d.applies) return h + "<p>" + c.t("dyn_not") + "</p>\n";
  h += "<p>" + c.t(t.intervention ? "dyn_intro" : "dyn_intro_existing") + "</p>\n<table class=\"data\"><tr>" +
       th(c.t("dyn_e")) + th(c.t("dyn_N")) + th(c.t("dyn_over")) + th(c.t("dyn_d")) + th(c.t("dyn_dslv")) +
       th(c.t("dyn_yield")) + th(c.t("dyn_broken")) + th(c.t("dyn_verdict")) + "</tr>\n";
  for (const TieDynamicSummary& x : d.summaries)
    h += "<tr>" + tdn(format("%.3f", x.e)) + tdn(format("%d", x.records)) +
         tdn(format("%d / %d", x.overturned_before, x.overturned_after)) +
         tdn(format("%.4f / %.4f", x.d_demand_before, x.d_demand_after)) +
         tdn(format("%.4f / %.4f", x.d_SLV_before, x.d_SLV_after)) +
         tdn(format("%d / %d", x.yielded_before, x.yielded_after)) + tdn(format("%d / %d", x.broken_before, x.broken_after)) +
         "<td>" + c.t(x.satisfied_before ? "ok" : "ko") + " → " + c.t(x.satisfied_after ? "ok" : "ko") + "</td></tr>\n";
  h += "</table>\n<p>" + c.t("dyn_runs_intro") + "</p>\n<table class=\"data\"><tr>" + th(c.t("dyn_record")) +
       th(c.t("dyn_e")) + th(c.t("dyn_polarity")) + th("θ_max (rad)") + th(c.t("dyn_fmax")) + th(c.t("dyn_outcome")) +
       "</tr>\n";
  for (const TieDynamicRun& r : d.runs)
    h += "<tr>" + tdn(format("%zu", r.record + 1)) + tdn(format("%.3f", r.e)) +
         td(c.t(r.reversed ? "reversed" : "normal")) + tdn(format("%.5f", r.theta_max)) +
         tdn(format("%.2f", r.max_force / kN)) + td(run_outcome(c, r)) + "</tr>\n";
  return h + "</table>\n";
}

std::string detailing(const Ctx& c, const TieInterventionResult& t, const std::string& ho, const std::string& hc) {
  std::string h = ho + c.t("det_title") + hc + "\n<ul class=\"detailing\">\n";
  for (const TieLevelResult& L : t.levels) {
    const Tie& x = L.tie;
    const tie_catalogue::Thread* th = tie_catalogue::find_thread(x.rod.thread_diameter);
    std::string item = "<strong>" + xml_escape(x.name) + "</strong> (" + c.t(x.existing ? "existing" : "new") + "): ";
    item += c.f("det_anchor", anchor_cell(c, x), c.t(x.anchor.type == AnchorType::Plate ? "det_plate" : "det_bar"));
    if (th)
      item += " " + c.f("det_nut", format("%.0f", th->d * 1e3), format("%.0f", th->s * 1e3), format("%.1f", th->m * 1e3),
                        format("%.0f × %.1f", th->dw * 1e3, th->hw * 1e3));
    item += " " + c.t("det_ends." + std::string(to_string(x.rod.ends)));
    item += " " + c.f("det_layout", layout_cell(c, x));
    if (x.pretension > 0.0)
      item += " " + c.f("det_pretension", format("%.1f", x.pretension / kN),
                        format("%.0f", 100.0 * x.pretension / L.resistance.design));
    else
      item += " " + c.t("det_pretension_none");
    h += "<li>" + item + "</li>\n";
  }
  for (const char* k : {"det_far_end", "det_corrosion", "det_execution"}) h += "<li>" + c.t(k) + "</li>\n";
  return h + "</ul>\n";
}

}  // namespace

std::string tie_section_title(Lang lang) { return msg(lang, "tie.title"); }

std::string tie_html_section(const TieInterventionResult& t, Lang lang, const std::string& id_prefix,
                             int heading_level) {
  const Ctx c{lang};
  // Headings at `heading_level`; every id (the section's, the drawing's
  // markers) prefixed, so that several sections share a page (the building).
  const std::string ho = "<h" + std::to_string(heading_level) + ">";
  const std::string hc = "</h" + std::to_string(heading_level) + ">";
  auto prefixed = [&](std::string svg) {
    for (const char* key : {"id=\"", "url(#"})
      for (std::size_t at = svg.find(key); !id_prefix.empty() && at != std::string::npos;
           at = svg.find(key, at + std::string(key).size() + id_prefix.size()))
        svg.insert(at + std::string(key).size(), id_prefix);
    return svg;
  };
  std::string h = "<div class=\"ties\" id=\"" + xml_escape(id_prefix) + "ties\">\n";
  h += "<p>" + c.t(t.designed ? "intro_design" : t.intervention ? "intro_given" : "intro_existing") + "</p>\n";
  if (t.designed && t.found) h += "<p>" + c.t(t.regime == "ductile" ? "regime_ductile" : "regime_elastic") + "</p>\n";
  if (t.designed && !t.found) h += "<p style=\"color:#c62828\">" + c.t("not_found") + "</p>\n";
  h += "<figure>" +
       prefixed(drawing(c, t.intervention ? t.case_after : t.case_before, t.intervention ? t.after : t.before, t.levels)) +
       "<figcaption>" + c.t("drawing") + "</figcaption></figure>\n";
  h += ho + c.t("levels_title") + hc + "\n" + levels_table(c, t.levels);
  h += ho + c.t("formulas_title") + hc + "\n" + formulas(c);
  for (const TieLevelResult& L : t.levels_before) h += level_block(c, L, c.t("state_before"), ho, hc);
  if (t.intervention)
    for (const TieLevelResult& L : t.levels) h += level_block(c, L, c.t("state_after"), ho, hc);
  h += ho + c.t("before_after") + hc + "\n" + states_table(c, t);
  h += dynamics(c, t, ho, hc);
  h += detailing(c, t, ho, hc);
  h += "</div>\n";
  return h;
}

std::vector<TieReading> tie_readings(const TieInterventionResult& t, Lang lang) {
  std::vector<TieReading> out;
  for (int i = 1; i <= 14; ++i) {
    const std::string k = "tie.reading." + std::to_string(i);
    out.push_back({msg(lang, k + ".q"), msg(lang, k + ".r"), msg(lang, k + ".b")});
  }
  (void)t;
  return out;
}

}  // namespace assess
