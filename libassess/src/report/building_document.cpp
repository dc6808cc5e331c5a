// building_document.cpp: the relazione of a building (issues 22, 28) as a
// document: frontespizio, the building's verdict (one sentence: verdict,
// zetaE,edificio and the mechanisms that fail), contents; premessa,
// normativa, description, survey, criteria (the mechanisms examined); the
// seismic action once; the formulas; the summary of every mechanism (table
// with per-approach alpha0, a0*, D/C and zetaE, the zetaE chart, NTC 2008,
// the record sets, the ties); one section per mechanism made of the façade
// relazione's own sections; interventions; conclusions and signature;
// appendices (every mechanism's other candidates, warnings, legend, readings,
// the case file). Every verdict read from BuildingAssessment.
#include "assess/report/building_report.hpp"
#include "assess/report/note_text.hpp"

#include "report/message_tables.hpp"
#include "report/relazione_context.hpp"
#include "report/report_heading.hpp"
#include "report/text_format.hpp"
#include "report/xml_escape.hpp"

#include "assess/report/html_writer.hpp"
#include "assess/report/tie_report.hpp"

#include <algorithm>
#include <cmath>
#include <map>
#include <stdexcept>
#include <set>

namespace assess {

namespace {

using detail::code_name;
using detail::xml_escape;

// The building report's own phrases, Italian and English (messages/building.json).
const std::string& bt(Lang L, const std::string& key) {
  static const std::map<std::string, detail::Message> m = detail::message_table("building");
  const auto it = m.find(key);
  if (it == m.end()) throw std::logic_error("building messages: no entry '" + key + "'");
  return L == Lang::it ? it->second.it : it->second.en;
}


std::string esc(const std::string& s) { return xml_escape(s); }

// "12,3" in Italian, "∞" and "—" (relazione::Ctx::n without a context).
std::string fx(Lang L, double v, int prec) {
  if (std::isnan(v)) return "—";
  if (!std::isfinite(v)) return v > 0 ? "∞" : "−∞";
  std::string s = format("%.*f", prec, v);
  if (L == Lang::it)
    for (char& c : s)
      if (c == '.') c = ',';
  return s;
}

// The engineer's own words (names of walls and mechanisms): printed as written.
Cell user_cell(const std::string& text, const std::string& note = "") {
  Cell c(text, note);
  c.user = true;
  return c;
}

Cell num(Lang L, double v, int prec) {
  Cell c(fx(L, v, prec));
  c.numeric = true;
  return c;
}

Cell dc_cell(Lang L, double dc, Outcome o) {
  Cell c(o == Outcome::no_verdict ? "—" : fx(L, dc, relazione::dc_decimals(dc, o == Outcome::satisfied)));
  c.numeric = true;
  c.tone = verdict_tone(o);
  c.strong = o != Outcome::no_verdict;
  return c;
}

// zetaE coloured by the verdict of its approach (issue 41: never by zeta >= 1 on its own).
Cell zeta_cell(Lang L, const SafetyIndex* s, bool governing) {
  if (!s || !s->has_checks || !s->defined) return num(L, std::nan(""), 3);
  Cell c((governing ? "★ " : "") + fx(L, s->index.zeta, 3));
  c.numeric = true;
  c.tone = verdict_tone(s->outcome());
  return c;
}

std::string record_set_text(Lang L, const BuildingAssessment& b, std::size_t i) {
  const BuildingMechanism& m = b.building.mechanisms[i];
  const FacadeAssessment& a = b.results[i].a;
  std::string s;
  switch (m.record_set) {
    case RecordSetKind::none: return bt(L, "set_none");
    case RecordSetKind::listed: s = bt(L, "set_listed"); break;
    case RecordSetKind::own: s = bt(L, "set_own"); break;
    case RecordSetKind::shared: s = bt(L, "set_shared") + " " + m.record_group; break;
  }
  if (a.dynamics.spec && a.dynamics.applies)
    s += " (" + std::to_string(a.dynamics.records.size()) + ", " + fx(L, a.selection.range.T_min, 2) + "–" +
         fx(L, a.selection.range.T_max, 2) + " s)";
  else if (!a.dynamics.applies && a.dynamics.spec)
    s = bt(L, "set_none");
  return s;
}

std::string record_set_short(Lang L, const BuildingAssessment& b, std::size_t i) {
  const BuildingMechanism& m = b.building.mechanisms[i];
  const FacadeAssessment& a = b.results[i].a;
  if (!a.dynamics.spec || !a.dynamics.applies) return "—";
  switch (m.record_set) {
    case RecordSetKind::none: return "—";
    case RecordSetKind::listed: return bt(L, "listed_short");
    case RecordSetKind::own: return bt(L, "own_short");
    case RecordSetKind::shared: return m.record_group;
  }
  return "—";
}

// The bar chart of zetaE per mechanism against 1 (inline SVG; the colours of
// the approaches as in the façade's figures).
std::string zeta_chart(Lang L, const BuildingAssessment& b, bool* designed_out) {
  const std::size_t n = b.building.mechanisms.size();
  const double W = 680, H = 300, left = 48, right = 12, top = 28, bottom = 40;
  double zmax = 1.2;
  for (const BuildingMechanismResult& r : b.results)
    for (const char* ap : {"strength", "displacement"})
      if (const SafetyIndex* s = r.index("NTC2018", ap))
        if (s->defined && std::isfinite(s->index.zeta)) zmax = std::max(zmax, std::min(s->index.zeta, 4.0) * 1.1);
  const double plot_w = W - left - right, plot_h = H - top - bottom;
  auto y_of = [&](double z) { return top + plot_h * (1.0 - std::min(z, zmax) / zmax); };
  std::string svg = format("<svg xmlns=\"http://www.w3.org/2000/svg\" viewBox=\"0 0 %.0f %.0f\" width=\"%.0f\" height=\"%.0f\" "
                           "font-family=\"DejaVu Sans, sans-serif\" font-size=\"11\" role=\"img\" aria-label=\"%s\">\n",
                           W, H, W, H, esc(bt(L, "chart_title")));
  svg += format("<text x=\"%.0f\" y=\"16\" font-size=\"13\" text-anchor=\"middle\">%s</text>\n", W / 2, esc(bt(L, "chart_title")));
  const double step = zmax > 3 ? 1.0 : zmax > 1.5 ? 0.5 : 0.25;
  for (double z = 0.0; z <= zmax + 1e-9; z += step) {
    const double y = y_of(z);
    svg += format("<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#ddd\"/>\n", left, W - right, y, y);
    svg += format("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"end\">%s</text>\n", left - 4, y + 4, fx(L, z, 2));
  }
  svg += format("<text x=\"12\" y=\"%.1f\" transform=\"rotate(-90 12 %.1f)\" text-anchor=\"middle\">ζE (–)</text>\n",
                top + plot_h / 2, top + plot_h / 2);
  const double group = plot_w / double(std::max<std::size_t>(n, 1));
  const double bw = std::min(28.0, group * 0.36);
  static const char* colour[] = {"#1f5fbf", "#d9730d"};
  bool designed = false;
  for (std::size_t i = 0; i < n; ++i) {
    const double x0 = left + group * double(i) + group / 2.0;
    int k = 0;
    for (const char* ap : {"strength", "displacement"}) {
      const double x = x0 + (k == 0 ? -bw - 1 : 1);
      const SafetyIndex* s = b.results[i].index("NTC2018", ap);
      if (s && s->defined) {
        const double z = s->index.zeta;
        const double y = y_of(std::isfinite(z) ? z : zmax);
        svg += format("<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"%s\"><title>%s %s: ζE = %s</title></rect>\n",
                      x, y, bw, top + plot_h - y, colour[k], esc(b.building.mechanisms[i].id), esc(bt(L, ap)), esc(fx(L, z, 3)));
        if (!std::isfinite(z) || z > zmax)
          svg += format("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"9\">%s</text>\n", x + bw / 2,
                        y + 10, esc(fx(L, z, 2)));
      }
      ++k;
    }
    const BuildingMechanismResult& r = b.results[i];
    if (r.ties && r.ties->designed && std::isfinite(r.zeta_after)) {
      const double y = y_of(r.zeta_after);
      svg += format("<path d=\"M %.1f %.1f l 6 6 l -6 6 l -6 -6 z\" fill=\"#1a7f37\" stroke=\"#fff\"><title>%s %s: ζE = %s"
                    "</title></path>\n",
                    x0, y - 6, esc(b.building.mechanisms[i].id), esc(bt(L, "chart_designed")), esc(fx(L, r.zeta_after, 3)));
      if (r.zeta_after > zmax)
        svg += format("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\" font-size=\"9\" fill=\"#1a7f37\">%s</text>\n",
                      x0, y + 18, esc(fx(L, r.zeta_after, 2)));
      designed = true;
    }
    svg += format("<text x=\"%.1f\" y=\"%.1f\" text-anchor=\"middle\">%s</text>\n", x0, top + plot_h + 16,
                  esc(b.building.mechanisms[i].id));
  }
  const double y1 = y_of(1.0);
  svg += format("<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#b3001b\" stroke-width=\"2\" "
                "stroke-dasharray=\"6 3\"/>\n<text x=\"%.1f\" y=\"%.1f\" fill=\"#b3001b\" text-anchor=\"start\">ζE = 1</text>\n",
                left, W - right, y1, y1, left + 2, y1 - 4);
  svg += format("<line x1=\"%.1f\" x2=\"%.1f\" y1=\"%.1f\" y2=\"%.1f\" stroke=\"#333\"/>\n", left, W - right,
                top + plot_h, top + plot_h);
  for (int k = 0; k < 2; ++k) {
    const double lx = left + 8 + 190.0 * k, ly = H - 10;
    svg += format("<rect x=\"%.1f\" y=\"%.1f\" width=\"12\" height=\"10\" fill=\"%s\"/><text x=\"%.1f\" y=\"%.1f\">%s</text>\n",
                  lx, ly - 9, colour[k], lx + 16, ly, esc(bt(L, k == 0 ? "strength" : "displacement")));
  }
  if (designed) {
    const double lx = left + 8 + 380.0, ly = H - 10;
    svg += format("<path d=\"M %.1f %.1f l 6 6 l -6 6 l -6 -6 z\" fill=\"#1a7f37\"/><text x=\"%.1f\" y=\"%.1f\">%s</text>\n",
                  lx + 6, ly - 11, lx + 16, ly, esc(bt(L, "chart_designed")));
  }
  *designed_out = designed;
  return svg + "</svg>";
}

// The tie rods of a mechanism in one state in a few words (issue 29): the
// existing ties, then the new ones (count, rod, anchor; "n levels").
std::string tie_label(Lang L, const TieInterventionResult& t, bool after) {
  std::string out;
  for (const TieGroup& g : tie_groups(t, after)) {
    const Tie* x = g.first;
    std::string s = msg(L, g.existing ? "tie.existing" : "tie.new") + ": " + std::to_string(x->layout.count) + " × " +
                    (x->rod.diameter > 0.0 ? "Ø" + fx(L, x->rod.diameter * 1e3, 0) + " mm " + x->rod.grade
                                           : "A = " + fx(L, x->rod.area * 1e6, 0) + " mm² " + x->rod.grade);
    s += x->anchor.type == AnchorType::Plate
             ? ", " + bt(L, "ties_plate") + " " + fx(L, x->anchor.a * 1e3, 0) + " × " + fx(L, x->anchor.b * 1e3, 0) +
                   " × " + fx(L, x->anchor.t * 1e3, 0) + " mm"
             : ", " + bt(L, "ties_bar") + " " + fx(L, x->anchor.a * 1e3, 0) + " mm";
    if (g.levels > 1) s += " (" + std::to_string(g.levels) + " " + bt(L, "ties_levels") + ")";
    out += (out.empty() ? "" : "; ") + s;
  }
  // Issue 37: the existing levels the design changed.
  if (after)
    for (const TieChange& c : t.changes)
      out += (out.empty() ? "" : "; ") + msg(L, "tie.existing") + ": " +
             (c.kind == "removed" ? msg(L, "tie.change.removed")
                                  : msg(L, c.kind == "anchor" ? "tie.change_short.anchor" : "tie.change_short.rod"));
  if (after && t.designed && !t.found) out = bt(L, "ties_not_found") + " (" + out + ")";
  return out.empty() ? "—" : out;
}

Cell pass_cell(Lang L, bool ok) {
  const Outcome o = outcome_of(ok, false);
  Cell c(verdict_word(L, o));
  c.tone = verdict_tone(o);
  return c;
}

// The building's index in one state (issue 29: one index per state), one sentence.
std::string tie_index_text(Lang L, const BuildingAssessment& b, bool after) {
  const BuildingTieIndex& ti = b.tie_index;
  const BuildingCase& bc = b.building;
  const int k = after ? ti.mechanism_after : ti.mechanism_before;
  return msgf(L, after ? "tie.bld.index_after" : "tie.bld.index_before", fx(L, after ? ti.zeta_after : ti.zeta_before, 3),
              k >= 0 ? bc.mechanisms[std::size_t(k)].id : std::string("—"),
              after ? ti.passing_after : ti.passing_before, bc.mechanisms.size());
}

// The building in its stato di fatto and in its stato di progetto (issues 23,
// 29): one table and one index per state.
void add_ties_summary(Lang L, const BuildingAssessment& b, DocumentBuilder& d) {
  const BuildingCase& bc = b.building;
  d.add_heading(bt(L, "ties_title"), 3, false);
  auto z = [&](double v) {
    Cell c = num(L, v, 3);
    c.tone = v >= 1.0 ? Tone::ok : Tone::fail;
    return c;
  };
  Cell zh("ζE");
  zh.numeric = true;
  for (bool after : {false, true}) {
    std::vector<std::vector<Cell>> rows;
    for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
      const BuildingMechanism& m = bc.mechanisms[i];
      const BuildingMechanismResult& r = b.results[i];
      const TieInterventionResult* x = r.ties ? &*r.ties : nullptr;
      Cell dyn("—");
      if (x && x->dynamics.applies && !x->dynamics.summaries.empty()) {
        bool ok = true;
        for (const TieDynamicSummary& y : x->dynamics.summaries) ok = ok && (after ? y.satisfied_after : y.satisfied_before);
        dyn = pass_cell(L, ok);
      }
      Cell id(m.id);
      id.link = m.id;
      rows.push_back({id, user_cell(m.name), Cell(x ? tie_label(L, *x, after) : "—"),
                      z(after ? r.zeta_after : r.zeta_before), pass_cell(L, after ? r.passes_after : r.passes_before),
                      dyn});
    }
    d.add_cell_table({Cell(bt(L, "id")), Cell(bt(L, "wall_mech")),
                      Cell(msg(L, after ? "tie.bld.ties_after" : "tie.bld.ties_before")), zh,
                      Cell(bt(L, "checks_all")), Cell(bt(L, "dyn_check"))},
                     rows, msg(L, after ? "tie.bld.cap_after" : "tie.bld.cap_before"));
    d.add_paragraph(tie_index_text(L, b, after));
  }
}

// The building's verdict in one sentence (issue 28, item 4).
Inline verdict_sentence(Lang L, const BuildingAssessment& b) {
  const BuildingVerdict& v = b.verdict;
  const BuildingCase& bc = b.building;
  std::string failing;
  for (int i : v.failing) failing += (failing.empty() ? "" : ", ") + bc.mechanisms[std::size_t(i)].id;
  Inline out;
  const Outcome o = v.outcome();
  if (o == Outcome::satisfied)
    out.push_back(Span{fmt::format(fmt::runtime(bt(L, "verdict_ok")), v.mechanisms), true, verdict_tone(o)});
  else if (o == Outcome::not_satisfied)
    out.push_back(Span{fmt::format(fmt::runtime(bt(L, v.failing.size() == 1 ? "verdict_fail_one" : "verdict_fail")),
                                   v.failing.size(), v.mechanisms, failing),
                       true, verdict_tone(o)});
  else
    out.push_back(Span{fmt::format(fmt::runtime(bt(L, v.undecided.size() == 1 ? "verdict_none_one" : "verdict_none")),
                                   v.undecided.size(), v.mechanisms),
                       true, verdict_tone(o)});
  std::string tail;
  if (!v.undecided.empty()) {
    std::string u;
    for (int i : v.undecided) u += (u.empty() ? "" : ", ") + bc.mechanisms[std::size_t(i)].id;
    tail += "; " + fmt::format(fmt::runtime(bt(L, "verdict_undecided")), u);
  }
  if (v.zeta_mechanism >= 0)
    tail += "; " + fmt::format(fmt::runtime(bt(L, "verdict_zeta")), fx(L, v.zeta, 3), bc.mechanisms[std::size_t(v.zeta_mechanism)].id);
  if (v.dc_mechanism >= 0)
    tail += "; " + fmt::format(fmt::runtime(bt(L, "verdict_dc")), fx(L, v.max_dc, 3), bc.mechanisms[std::size_t(v.dc_mechanism)].id);
  // The verdicts the judgement calls not robust (issue 36, item 4).
  std::string fragile;
  for (std::size_t i = 0; i < b.results.size(); ++i) {
    const std::optional<Judgement>& j = b.results[i].a.judgement;
    if (j && !j->robust && j->outcome != Outcome::no_verdict) fragile += (fragile.empty() ? "" : ", ") + bc.mechanisms[i].id;
  }
  if (!fragile.empty()) tail += "; " + fmt::format(fmt::runtime(bt(L, "verdict_fragile")), fragile);
  out.push_back(Span{tail + "."});
  return out;
}

void add_verdict(Lang L, const BuildingAssessment& b, DocumentBuilder& d) {
  d.add_heading(bt(L, "verdict_heading"), 2, false, false);
  Box box{"conclusion", verdict_tone(b.verdict.outcome()), {{"building", "verdict"}}, {}};
  box.content.push_back(Paragraph{verdict_sentence(L, b), "", ""});
  d.add_box(std::move(box));
  // The governing mechanism of each approach.
  std::vector<Inline> items;
  const BuildingCase& bc = b.building;
  for (const BuildingGoverning& g : b.governing) {
    const BuildingMechanism& m = bc.mechanisms[std::size_t(g.mechanism)];
    const SafetyIndex* s = b.results[std::size_t(g.mechanism)].index(g.code, g.approach);
    const Outcome go = summary_outcome(g.assessed, g.failing, g.no_verdict);
    Inline line{Span{code_name(g.code) + ", " + bt(L, g.approach) + ": "}, Span{m.id, true, Tone::plain, ""},
                Span{" " + m.wall + ": " + m.name}};
    if (s && s->defined) {
      line.push_back(Span{", ζE = " + fx(L, s->index.zeta, 3), true, verdict_tone(s->outcome())});
      const bool ext = s->index.extrapolated;
      const std::string trc = ext ? (s->index.TR_capacity > 2475.0 ? "> 2475" : "< 30") : fx(L, s->index.TR_capacity, 0);
      line.push_back(Span{" (PGA_C = " + fx(L, s->index.ag_capacity_g, 3) + " g / PGA_D = " + fx(L, s->index.ag_demand_g, 3) +
                          " g, " + s->limit_state + "; TR_C = " + trc + " " + bt(L, "years") + ", TR_D = " +
                          fx(L, s->index.TR_demand, 0) + " " + bt(L, "years") + ")"});
    } else {
      line.push_back(Span{", D/C = " + fx(L, g.dc, 3), true, verdict_tone(go)});
      line.push_back(Span{" (" + bt(L, "no_zeta") + ")"});
    }
    line.push_back(Span{"; " + bt(L, "satisfied_of") + ": " + std::to_string(g.satisfied) + " " + bt(L, "of") + " " +
                        std::to_string(g.assessed) + ", " + bt(L, "failing") + ": " + std::to_string(g.failing) +
                        (g.no_verdict ? ", " + bt(L, "no_verdict") + ": " + std::to_string(g.no_verdict) : "")});
    items.push_back(line);
  }
  d.add_paragraph(bt(L, "governing") + ":", "");
  d.add_list(items, "governing");
}

// Every mechanism examined, wall by wall (the criteria's list).
void add_mechanism_list(Lang L, const BuildingAssessment& b, DocumentBuilder& d) {
  std::vector<std::vector<Cell>> rows;
  for (std::size_t i = 0; i < b.building.mechanisms.size(); ++i) {
    const BuildingMechanism& m = b.building.mechanisms[i];
    Cell wall(m.wall), name(m.name);
    wall.user = name.user = true;
    rows.push_back({Cell(m.id), wall, name, Cell(mechanism_name(L, m.kase.mechanism.type)),
                    Cell(msg(L, "method." + b.results[i].a.verdict.adopted))});
  }
  d.add_cell_table({Cell(bt(L, "id")), Cell(bt(L, "wall_col")), Cell(bt(L, "mech_col")), Cell(bt(L, "mech_type")),
                    Cell(bt(L, "method_col"))},
                   rows, bt(L, "mechanisms_cap"));
}

// A shared record set used by a mechanism's dynamic analysis (described in the tabulati).
bool has_shared_set(const BuildingAssessment& b) {
  for (std::size_t i = 0; i < b.building.mechanisms.size(); ++i) {
    const FacadeAssessment& a = b.results[i].a;
    if (b.building.mechanisms[i].record_set == RecordSetKind::shared && a.dynamics.spec && a.dynamics.applies) return true;
  }
  return false;
}

void add_record_sets(Lang L, const BuildingAssessment& b, DocumentBuilder& t, const ReportOptions& options, int level = 2);

// `tabulati`: the relazione, whose record sets are in its tabulati; the
// terminal's summary (no tabulati) describes them itself.
void add_summary(Lang L, const BuildingAssessment& b, DocumentBuilder& d, const ReportOptions& options, bool tabulati) {
  const BuildingCase& bc = b.building;
  d.add_heading(bt(L, "summary"), 2, true, true, "summary");
  d.add_paragraph(bt(L, "site_line") + ": " + relazione::decimal_comma(L == Lang::it ? localise(L, b.site_description) : b.site_description) +
                  ". " + bt(L, "slv_line") + " TR = " + fx(L, b.TR_SLV, 0) + " " + bt(L, "years") + ", ag = " +
                  fx(L, b.ag_SLV_g, 4) + " g; VR = " + fx(L, b.VR, 0) + " " + bt(L, "years") + ".");
  auto gov_of = [&](const std::string& code, const char* ap, std::size_t i) {
    const BuildingGoverning* g = b.governing_of(code, ap);
    return g && g->mechanism == int(i);
  };
  std::vector<std::vector<Cell>> rows;
  for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
    const BuildingMechanism& m = bc.mechanisms[i];
    const BuildingMechanismResult& r = b.results[i];
    Cell id(m.id);
    id.link = m.id;
    Cell name(m.name, m.wall);
    name.user = true;
    std::vector<Cell> row{id, name};
    for (const char* ap : {"strength", "displacement"}) {
      const SafetyIndex* s = r.index("NTC2018", ap);
      if (s && s->has_checks) {
        Cell al = num(L, s->dc_alpha0, 4);
        al.note = s->dc_candidate == r.a.kinematic.candidates.front().label && r.a.kinematic.candidates.size() == 1
                      ? ""
                      : relazione::decimal_comma(L == Lang::it ? localise(L, s->dc_candidate) : s->dc_candidate);
        row.push_back(al);
        row.push_back(dc_cell(L, s->dc, s->outcome()));
      } else {
        row.push_back(num(L, std::nan(""), 4));
        row.push_back(num(L, std::nan(""), 3));
      }
      row.push_back(zeta_cell(L, s, gov_of("NTC2018", ap, i)));
    }
    const SafetyIndex* dy = r.index("NTC2018", "dynamic");
    if (dy && dy->has_checks) {
      Cell c = dc_cell(L, dy->dc, dy->outcome());
      if (gov_of("NTC2018", "dynamic", i)) c.text = "★ " + c.text;
      if (dy->dc == 0.0) c.note = msg(L, "dyn.no_uplift");  // the wall never lifted: a computed zero, said why
      row.push_back(c);
    } else {
      row.push_back(num(L, std::nan(""), 3));
    }
    row.push_back(Cell(record_set_short(L, b, i)));
    if (const MethodVerdict* c = r.a.verdict.conclusion()) {
      Cell out(verdict_word(L, c->outcome()));
      out.tone = verdict_tone(c->outcome());
      if (r.a.verdict.adopted != "nonlinear") out.note = bt(L, r.a.verdict.adopted == "linear" ? "strength" : "dynamic");
      row.push_back(out);
    } else {
      row.push_back(Cell("—"));
    }
    rows.push_back(row);
  }
  // Short approach names under the headings (the caption spells them out): the
  // table fits the page at its type size (issue 28, item 9).
  const std::string lin = bt(L, "strength_short"), nl = bt(L, "displacement_short");
  d.add_cell_table({Cell(bt(L, "id")), Cell(bt(L, "wall_mech")), numeric_cell("α0", lin), numeric_cell("D/C", lin), numeric_cell("ζE", lin), numeric_cell("α0", nl),
                    numeric_cell("D/C", nl), numeric_cell("ζE", nl), numeric_cell("D/C", bt(L, "dynamic_short")), Cell(bt(L, "records_short")),
                    Cell(bt(L, "outcome"))},
                   rows, bt(L, "table_cap") + " " + bt(L, "approach_abbrev"), "building-summary");
  bool designed = false;
  const std::string chart = zeta_chart(L, b, &designed);
  d.add_svg(chart, bt(L, designed ? "chart_cap" : "chart_cap_plain"), "fig-zeta");

  if (std::find(b.codes.begin(), b.codes.end(), "NTC2008") != b.codes.end()) {
    std::vector<std::vector<Cell>> rows08;
    for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
      std::vector<Cell> row{Cell(bc.mechanisms[i].id), user_cell(bc.mechanisms[i].name, bc.mechanisms[i].wall)};
      for (const char* ap : {"strength", "displacement"}) {
        const SafetyIndex* s = b.results[i].index("NTC2008", ap);
        row.push_back(s && s->has_checks ? dc_cell(L, s->dc, s->outcome()) : num(L, std::nan(""), 3));
        row.push_back(zeta_cell(L, s, gov_of("NTC2008", ap, i)));
        row.push_back(s && s->defined ? num(L, s->index.ag_capacity_g, 3) : num(L, std::nan(""), 3));
      }
      rows08.push_back(row);
    }
    d.add_cell_table({Cell(bt(L, "id")), Cell(bt(L, "wall_mech")), numeric_cell("D/C", lin), numeric_cell("ζE", lin), numeric_cell("PGA_C (g)", lin),
                      numeric_cell("D/C", nl), numeric_cell("ζE", nl), numeric_cell("PGA_C (g)", nl)},
                     rows08, bt(L, "table08_cap"));
  }
  d.add_heading(bt(L, "sets"), 3, false);
  d.add_paragraph(bt(L, "sets_text"));
  // One line per record set with the mechanisms that use it (issue 36: the
  // body's length; the summary table names each mechanism's set too).
  std::vector<std::pair<std::string, std::string>> sets;  // set text, mechanisms
  for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
    const std::string text = record_set_text(L, b, i);
    auto it = std::find_if(sets.begin(), sets.end(), [&](const auto& x) { return x.first == text; });
    if (it == sets.end()) it = sets.insert(sets.end(), {text, ""});
    it->second += (it->second.empty() ? "" : ", ") + bc.mechanisms[i].id;
  }
  std::vector<Inline> items;
  for (const auto& [text, ids] : sets) items.push_back({Span(text, true), Span{": " + ids}});
  d.add_list(items);
  for (const SharedSelection& s : bc.selections)
    if (s.fell_back) d.add_paragraph(s.id + ": " + (L == Lang::it ? relazione::decimal_comma(note_text(L, s.note)) : note_text(L, s.note)));
  // Each shared set is described in the tabulati (add_record_sets; issue 36: the body's length).
  if (has_shared_set(b) && tabulati)
    d.add_paragraph(Inline{reference(bt(L, "sets_in_tab"), "record-sets", tabulati_key)}, "note");
  else
    add_record_sets(L, b, d, options, 3);
  if (b.tie_index.any_ties) add_ties_summary(L, b, d);
}

// Each shared set described once (its first member's records, flags, selection and compatibility),
// in the tabulati: the mechanisms' dynamic sections refer to it (issue 28, item 11; issue 36).
void add_record_sets(Lang L, const BuildingAssessment& b, DocumentBuilder& t, const ReportOptions& options, int level) {
  if (!has_shared_set(b)) return;
  const BuildingCase& bc = b.building;
  if (level == 2) t.add_heading(bt(L, "sets"), 2, false, true, "record-sets");
  std::set<std::string> shown;
  for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
    const BuildingMechanism& m = bc.mechanisms[i];
    const FacadeAssessment& a = b.results[i].a;
    if (m.record_set != RecordSetKind::shared || !a.dynamics.spec || !a.dynamics.applies || !shown.insert(m.record_group).second)
      continue;
    t.add_heading(bt(L, "set") + " " + m.record_group, level + 1, false, true, "set-" + m.record_group);
    ReportOptions ro = options;
    relazione::Ctx c{a, ro, L, t, nullptr};
    relazione::add_record_set(c, a, "fig-compatibility-" + m.record_group);
  }
}

// The mechanisms whose verdict the judgement calls not robust (issue 36, item
// 4): each with its verdict and why, as the building's interventions and
// conclusions state them.
std::vector<Inline> fragile_items(Lang L, const BuildingAssessment& b, const ReportOptions& options) {
  std::vector<Inline> items;
  for (std::size_t i = 0; i < b.results.size(); ++i) {
    const FacadeAssessment& a = b.results[i].a;
    if (!a.judgement || a.judgement->robust || a.judgement->outcome == Outcome::no_verdict) continue;
    DocumentBuilder scratch("", to_string(L));
    relazione::Ctx c{a, options, L, scratch, nullptr};
    const BuildingMechanism& m = b.building.mechanisms[i];
    Span id(m.id, true);
    id.link = m.id;
    items.push_back({id, Span{" (" + m.wall + ": " + m.name + "): "}, c.outcome_span(a.judgement->outcome),
                     Span{", D/C = " + fx(L, a.judgement->dc, 3) + " — " + relazione::judgement_qualifier(c, *a.judgement)}});
  }
  return items;
}

// Interventions (issues 28, 36): where any mechanism fails, which and what it
// needs; where a verdict is not robust, which and why.
void add_interventions(Lang L, const BuildingAssessment& b, DocumentBuilder& d, const ReportOptions& options) {
  d.add_heading(bt(L, "interventions"), 2, true, true, "interventions");
  const std::vector<Inline> fragile = fragile_items(L, b, options);
  if (b.verdict.failing.empty() && !b.tie_index.any_ties && fragile.empty()) {
    d.add_paragraph(bt(L, "int_none"));
    return;
  }
  if (!b.verdict.failing.empty()) d.add_paragraph(bt(L, "int_failing"));
  std::vector<Inline> items;
  for (std::size_t i = 0; i < b.results.size(); ++i) {
    const BuildingMechanismResult& r = b.results[i];
    const bool fails = std::find(b.verdict.failing.begin(), b.verdict.failing.end(), int(i)) != b.verdict.failing.end();
    const BuildingMechanism& m = b.building.mechanisms[i];
    const std::string who = m.id + " (" + m.wall + ": " + m.name + ")";
    if (r.ties)
      items.push_back({Span{fmt::format(fmt::runtime(bt(L, "int_ties")), who, tie_label(L, *r.ties, true))}});
    else if (fails) {
      const MethodVerdict* c = r.a.verdict.conclusion();
      items.push_back({Span{fmt::format(fmt::runtime(bt(L, "int_no_ties")), who, fx(L, c ? c->max_dc : std::nan(""), 3))}});
    }
  }
  if (!items.empty()) d.add_list(items);
  if (!fragile.empty()) {
    d.add_paragraph(bt(L, "int_fragile"));
    d.add_list(fragile);
  }
  if (b.tie_index.any_ties) {
    d.add_paragraph(tie_index_text(L, b, false));
    d.add_paragraph(tie_index_text(L, b, true));
  }
}

// The modelling choices of the building (issue 36, item 3): one table, each
// choice and alternative with the mechanisms it applies to, the largest
// change of their adopted D/C and the mechanisms whose verdict it changes;
// each mechanism's choices in full in the tabulati; the defaults the case did
// not give, once.
void add_building_choices(Lang L, const BuildingAssessment& b, DocumentBuilder& d, const ReportOptions& options) {
  d.add_heading(msg(L, "choice.heading"), 2, false, true, "choices");
  d.add_paragraph(msg(L, "choice.intro_building"));
  struct Group {
    std::string key, alternative, adopted;
    bool same_adopted = true;
    std::vector<std::string> members, flips;
    double worst = 0.0;  // the largest |D/C change|
    std::string worst_text;
  };
  std::vector<Group> groups;
  for (std::size_t i = 0; i < b.results.size(); ++i) {
    const FacadeAssessment& a = b.results[i].a;
    DocumentBuilder scratch("", to_string(L));
    relazione::Ctx c{a, options, L, scratch, nullptr};
    for (const ModellingChoice& x : a.choices) {
      static const std::set<std::string> by_value{"FC", "dSLV_over_d0", "dSLC_over_d0", "xi_SLV_pct", "xi_SLC_pct",
                                                  "friction_activation", "seat_friction", "selection_window"};
      const std::string alt = by_value.count(x.key) ? relazione::choice_value(c, x, true) : msg(L, "choice." + x.key + ".alt");
      const std::string adopted = by_value.count(x.key) ? relazione::choice_value(c, x, false) : msg(L, "choice." + x.key + ".adopted");
      auto g = std::find_if(groups.begin(), groups.end(), [&](const Group& y) { return y.key == x.key && y.alternative == alt; });
      if (g == groups.end()) {
        groups.push_back({x.key, alt, adopted, true, {}, {}, -1.0, ""});
        g = groups.end() - 1;
      }
      if (g->adopted != adopted) g->same_adopted = false;
      const std::string id = b.building.mechanisms[i].id;
      g->members.push_back(id);
      if (x.flips()) g->flips.push_back(id);
      if (x.computed()) {
        // ∞ → ∞ (an overturning with both) is no change.
        const double change = x.dc == x.dc_alternative ? 0.0
                              : std::isfinite(x.dc) && std::isfinite(x.dc_alternative)
                                  ? std::abs(x.dc_alternative - x.dc)
                                  : std::numeric_limits<double>::infinity();
        auto dc_text = [&](double v) {
          return fx(L, v, 3) + (x.method == "dynamic" && std::isinf(v) ? " " + msg(L, "dyn.overturning") : "");
        };
        if (change > g->worst) {
          g->worst = change;
          g->worst_text = id + ": " + dc_text(x.dc) + " → " + dc_text(x.dc_alternative) + " (" + msg(L, "method." + x.method) + ")";
        }
      }
    }
  }
  auto join = [](const std::vector<std::string>& xs) {
    std::string s;
    for (const std::string& x : xs) s += (s.empty() ? "" : ", ") + x;
    return s;
  };
  std::vector<std::vector<Cell>> rows;
  for (const Group& g : groups) {
    Cell flips(g.flips.empty() ? msg(L, "choice.none_changes") : join(g.flips));
    if (!g.flips.empty()) flips.tone = Tone::fail;
    rows.push_back({Cell(relazione::choice_name(L, g.key), relazione::choice_where(L, g.key)),
                    Cell(g.same_adopted ? g.adopted : msg(L, "choice.per_mechanism")), Cell(g.alternative), Cell(join(g.members)),
                    Cell(g.worst_text.empty() ? "—" : g.worst_text), flips});
  }
  // The defaults the case did not give (issue 41), once for the building.
  std::vector<std::vector<Cell>> defaults;
  std::vector<std::string> seen;
  for (const BuildingMechanismResult& r : b.results)
    for (const CaseDefault& x : assessment_defaults(r.a)) {
      if (std::find(seen.begin(), seen.end(), x.path) != seen.end()) continue;
      seen.push_back(x.path);
      bool covered = false;
      for (const BuildingMechanismResult& q : b.results)
        for (const ModellingChoice& y : q.a.choices) covered = covered || y.case_key == x.path;
      if (covered) continue;
      defaults.push_back({Cell(msg(L, x.effect)), Cell(x.path), Cell(relazione::default_value_text(L, x))});
    }
  d.add_cell_table({Cell(msg(L, "choice.col_choice")), Cell(msg(L, "choice.col_adopted")), Cell(msg(L, "choice.col_alternative")),
                    Cell(msg(L, "choice.col_members")), Cell(msg(L, "choice.col_largest")), Cell(msg(L, "choice.col_changes"))},
                   rows, msg(L, "choice.cap_building"), "choices");
  // The values assumed without an alternative, in a table of their own (issue 36: one line each).
  if (!defaults.empty())
    d.add_cell_table({Cell(msg(L, "choice.col_default")), Cell(msg(L, "choice.col_key")), Cell(msg(L, "choice.col_value"))}, defaults,
                     msg(L, "choice.defaults_cap"), "defaults");
}

void add_warnings(Lang L, const BuildingAssessment& b, DocumentBuilder& d) {
  if (b.warnings.empty()) return;
  d.add_heading(bt(L, "warnings"));
  d.add_paragraph(msg(L, "warnings.intro"));
  std::vector<Inline> items;
  for (const std::string& w : b.warnings)
    items.push_back({Span{L == Lang::it ? relazione::decimal_comma(localise(L, w)) : w}});
  d.add_list(items, "warnings");
}

// The frontespizio's table: client, work, site, engineer, date, revision, case file.
void add_front_table(Lang L, const BuildingAssessment& b, const ReportOptions& options, DocumentBuilder& d) {
  const BuildingCase& bc = b.building;
  const ReportInfo& info = bc.report;
  std::vector<std::vector<Cell>> rows;
  auto row = [&](const char* key, const std::string& v) {
    if (v.empty()) return;
    Cell value(v);
    value.user = std::string(key) != "front.site" && std::string(key) != "front.date";
    rows.push_back({Cell(msg(L, key)), value});
  };
  row("front.client", info.client);
  row("front.work", info.work.empty() ? bc.project : info.work);
  row("front.location", info.location);
  row("front.site", L == Lang::it ? relazione::decimal_comma(localise(L, b.site_description)) : b.site_description);
  row("front.engineer", info.engineer);
  row("front.registration", info.registration);
  row("front.date", options.date.empty() ? detail::today_utc() : options.date);
  row("front.revision", info.revision.empty() ? "0" : info.revision);
  row("front.case_file", detail::shown_file(bc.file));
  d.add_cell_table({Cell(msg(L, "front.item")), Cell(msg(L, "front.value"))}, rows, "", "front");
}

// The general part, as the single relazione writes it from the first
// mechanism's case: premessa, normativa, description, the mechanisms' list,
// the site, the modelling choices, the formulas, the building's summary.
void add_general_part(Lang L, const BuildingAssessment& b, const ReportOptions& options, const ReportOptions& mo,
                      DocumentBuilder& d, std::set<std::string>& readings) {
  const BuildingCase& bc = b.building;
  const FacadeAssessment& a0 = b.results.front().a;
  {
    relazione::Ctx c{a0, mo, L, d, &readings, true, true};
    d.add_heading(bt(L, "premessa"), 2, false, true, "premessa");
    d.add_paragraph(bt(L, "premessa_text"));
    d.add_paragraph(bt(L, "intro"));
    d.add_paragraph(relazione::tabulati_sentence(L));
    relazione::add_normativa(c);
    relazione::add_building_description(c);
    add_mechanism_list(L, b, d);
  }
  facade_site_section(a0, options, d);
  bool one_set = true;
  for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
    const FacadeAssessment& a = b.results[i].a;
    if (!a.dynamics.spec || !a.dynamics.applies) continue;
    const BuildingMechanism& m = bc.mechanisms[i];
    if (!(m.record_set == RecordSetKind::shared && m.record_group == bc.mechanisms.front().record_group)) one_set = false;
  }
  if (!one_set && !a0.curves.record_psa.empty()) d.add_paragraph(bt(L, "site_records_note"));
  add_building_choices(L, b, d, mo);
  {
    relazione::Ctx c{a0, mo, L, d, &readings, true, true};
    relazione::add_formulas(c);
  }
  add_summary(L, b, d, options, true);
}

// Each mechanism's section in the body and its part of the tabulati, in the
// order of the building; the first tie intervention met (for the readings).
const TieInterventionResult* add_mechanism_parts(Lang L, const BuildingAssessment& b, ReportOptions& mo,
                                                 DocumentBuilder& d, DocumentBuilder& t,
                                                 std::set<std::string>& readings) {
  const BuildingCase& bc = b.building;
  const TieInterventionResult* any_ties = nullptr;
  for (std::size_t i = 0; i < bc.mechanisms.size(); ++i) {
    const BuildingMechanism& m = bc.mechanisms[i];
    const BuildingMechanismResult& r = b.results[i];
    for (DocumentBuilder* x : {&d, &t}) {
      x->set_id_prefix("");
      x->set_heading_shift(0);
    }
    // No new page per mechanism (issue 36: the body of a building at most 60 pages).
    d.add_heading(m.id + " — " + m.wall + ": " + m.name, 2, false, true, m.id);
    d.add_paragraph(bt(L, "mech_type") + ": " + mechanism_name(L, m.kase.mechanism.type) + ". " + bt(L, "mech_path") +
                    ": " + m.json_path + ". " + bt(L, "mech_records") + ": " + record_set_text(L, b, i) + ".");
    t.add_heading(m.id + " — " + m.wall + ": " + m.name, 2, true, true, m.id);
    t.add_paragraph(Inline{reference(msg(L, "tab.mechanism_in_body"), m.id, relazione_key)}, "note");
    for (DocumentBuilder* x : {&d, &t}) {
      x->set_id_prefix(m.id + "-");
      x->set_heading_shift(1);
    }
    mo.ties = r.ties ? &*r.ties : nullptr;
    if (r.ties && !any_ties) any_ties = &*r.ties;
    mo.shared_records = m.record_set == RecordSetKind::shared ? m.record_group : "";
    facade_mechanism_sections(r.a, mo, d, &t, &readings);
  }
  for (DocumentBuilder* x : {&d, &t}) {
    x->set_heading_shift(0);
    x->set_id_prefix("");
  }
  return any_ties;
}

// Issue 37: the ties of each wall once, with the mechanisms they restrain.
void add_wall_ties(Lang L, const BuildingAssessment& b, ReportOptions& mo, DocumentBuilder& d, DocumentBuilder& t,
                   std::set<std::string>& readings) {
  const BuildingCase& bc = b.building;
  for (std::size_t w = 0; w < bc.doc.at("walls").size(); ++w) {
    std::vector<std::pair<std::string, const TieInterventionResult*>> members;
    const FacadeAssessment* first = nullptr;
    std::string wall;
    for (std::size_t i = 0; i < bc.mechanisms.size(); ++i)
      if (bc.mechanisms[i].wall_index == w && bc.mechanisms[i].wall_ties && b.results[i].ties &&
          b.results[i].ties->wall_members.size() > 1) {
        members.push_back({bc.mechanisms[i].id + " " + bc.mechanisms[i].name, &*b.results[i].ties});
        if (!first) first = &b.results[i].a, wall = bc.mechanisms[i].wall;
      }
    if (members.empty()) continue;
    mo.ties = members.front().second;
    for (DocumentBuilder* x : {&d, &t}) x->set_id_prefix("wall" + std::to_string(w + 1) + "-");
    relazione::Ctx c{*first, mo, L, d, &readings, true, true};
    relazione::add_wall_tie_section(c, wall, members, &t);
    for (DocumentBuilder* x : {&d, &t}) x->set_id_prefix("");
  }
}

// The conclusions: the building's verdict, the governing mechanism of each
// approach, the mechanisms whose verdict is not robust, the tie index.
void add_conclusions(Lang L, const BuildingAssessment& b, const ReportOptions& options, DocumentBuilder& d) {
  const BuildingCase& bc = b.building;
  d.add_heading(bt(L, "conclusioni"), 2, false, true, "conclusions");  // after the interventions, on their page
  d.add_paragraph(verdict_sentence(L, b));
  for (const BuildingGoverning& g : b.governing) {
    if (g.code != "NTC2018") continue;
    const BuildingMechanism& m = bc.mechanisms[std::size_t(g.mechanism)];
    const SafetyIndex* s = b.results[std::size_t(g.mechanism)].index(g.code, g.approach);
    d.add_paragraph(bt(L, "concl_gov") + " (" + bt(L, g.approach) + ", " + code_name(g.code) + "): " + m.id + " " + m.wall +
                    ": " + m.name + (s && s->defined ? ", ζE = " + fx(L, s->index.zeta, 3) : ", D/C = " + fx(L, g.dc, 3)) + "; " +
                    bt(L, "satisfied_of") + ": " + std::to_string(g.satisfied) + " " + bt(L, "of") + " " +
                    std::to_string(g.assessed) + ".");
  }
  // The mechanisms' judgements reach the conclusions (issue 36, item 4).
  const std::vector<Inline> fragile = fragile_items(L, b, options);
  if (fragile.empty()) {
    d.add_paragraph(bt(L, "concl_all_robust"));
  } else {
    // One sentence naming them (their reasons are listed in the interventions, issue 36: length).
    Inline p{Span{bt(L, "concl_fragile_ids") + " "}};
    bool first = true;
    for (const Inline& item : fragile) {
      if (!first) p.push_back(Span{", "});
      first = false;
      p.push_back(item.front());  // the mechanism's id, linked to its section
    }
    p.push_back(Span{" "});
    p.push_back(reference(bt(L, "concl_fragile_tail"), "interventions"));
    d.add_paragraph(p);
  }
  if (b.tie_index.any_ties) {
    d.add_paragraph(tie_index_text(L, b, false));
    d.add_paragraph(tie_index_text(L, b, true));
  }
}

}  // namespace

Document building_summary(const BuildingAssessment& b, const ReportOptions& options) {
  const Lang L = options.lang;
  const BuildingCase& bc = b.building;
  DocumentBuilder d(bt(L, "sum_title"), to_string(L));
  d.set_subtitle((bc.project.empty() ? "" : bc.project + ". ") + msg(L, "front.case_file") + ": " +
                 detail::shown_file(bc.file) + ". " + msg(L, "sum.full"));
  add_verdict(L, b, d);
  facade_site_section(b.results.front().a, options, d);
  add_summary(L, b, d, options, false);
  add_interventions(L, b, d, options);
  add_warnings(L, b, d);
  return d.document();
}

Relazione building_relazione(const BuildingAssessment& b, const ReportOptions& options) {
  const Lang L = options.lang;
  const BuildingCase& bc = b.building;
  DocumentBuilder d(bt(L, "title"), to_string(L));
  DocumentBuilder t(msg(L, "tab.title"), to_string(L));
  d.set_key(relazione_key);
  t.set_key(tabulati_key);
  t.set_number_prefix("T");
  std::set<std::string> readings;
  const ReportInfo& info = bc.report;
  std::string meta;
  if (!bc.project.empty()) meta += bt(L, "project") + ": " + bc.project + ". ";
  meta += bt(L, "generated") + " " + ASSESS_VERSION + ", " + bt(L, "date") + " " +
          (options.date.empty() ? detail::today_utc() : options.date) + ".";
  d.set_subtitle(meta);
  t.set_subtitle(meta);
  add_front_table(L, b, options, d);
  add_verdict(L, b, d);
  d.add_contents(msg(L, "doc.contents"), 2);

  const FacadeAssessment& a0 = b.results.front().a;
  ReportOptions mo = options;  // the general part's and the mechanisms' options: no case text, no fragility
  mo.case_text.clear();
  mo.fragility.reset();
  add_general_part(L, b, options, mo, d, readings);

  // The tabulati: what they hold, then each mechanism's part in the order of the body.
  t.add_contents(msg(L, "doc.contents"), 2);
  {
    relazione::Ctx x{a0, mo, L, t, &readings, true, true};
    relazione::add_tab_intro(x);
  }
  add_record_sets(L, b, t, options);
  const TieInterventionResult* any_ties = add_mechanism_parts(L, b, mo, d, t, readings);
  add_wall_ties(L, b, mo, d, t, readings);
  mo.ties = nullptr;
  mo.shared_records.clear();
  add_interventions(L, b, d, options);

  add_conclusions(L, b, options, d);
  {
    std::vector<std::pair<std::string, const FacadeAssessment*>> ms;
    for (std::size_t i = 0; i < bc.mechanisms.size(); ++i)
      ms.push_back({bc.mechanisms[i].id + " " + bc.mechanisms[i].wall + ": " + bc.mechanisms[i].name, &b.results[i].a});
    relazione::Ctx c{a0, mo, L, d, &readings, true, true};
    relazione::add_code_chapter(c, ms);
  }
  add_warnings(L, b, d);
  {
    relazione::Ctx c{a0, mo, L, d, &readings, true, true};
    relazione::add_legend(c);
  }
  d.add_signature({bt(L, "place_date") + ": " + (info.place.empty() ? "______________________" : info.place + ", ______________"),
                   bt(L, "engineer") + ": " + (info.engineer.empty() ? "______________________" : info.engineer) +
                       (info.registration.empty() ? "" : " (" + info.registration + ")")});

  // The tabulati's readings (with the tie rods' when a mechanism has ties) and the case file.
  {
    mo.ties = any_ties;
    relazione::Ctx x{a0, mo, L, t, &readings, true, true};
    relazione::add_readings_appendix(x);
    mo.ties = nullptr;
  }
  t.add_heading(bt(L, "appendix"), 2, false, true, "case-file");
  t.add_paragraph(detail::shown_file(bc.file));
  t.add_pre(options.case_text);
  Relazione r{d.document(), t.document()};
  // The body flows from section to section (issue 36: the house's body at most
  // 60 pages): no page is left short by a forced break.
  for (DocBlock& x : r.body.blocks)
    if (auto* h = std::get_if<Heading>(&x.value)) h->new_page = false;
  resolve_references({&r.body, &r.tabulati});
  return r;
}

}  // namespace assess
