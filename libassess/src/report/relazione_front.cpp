// relazione_front.cpp: the opening of the relazione (issue 28, item 7):
// frontespizio, the verdict box, the contents, premessa, normativa, the
// description of the building, the survey and knowledge level, the masonry
// and the criteria of the mechanisms' choice.
#include "report/relazione_context.hpp"

#include "report/report_heading.hpp"
#include "report/text_format.hpp"

#include <cmath>
#include <map>

namespace assess::relazione {

using detail::code_name;

namespace {

std::string row_name(const Ctx& c, const VerdictRow& r) {
  return c.t("checks.verifica") + " " + r.limit_state + ", " + c.t("kind." + r.approach) + ", " +
         c.t("where." + r.location);
}

}  // namespace

void add_front_matter(Ctx& c) {
  const FacadeAssessment& a = c.a;
  const ReportInfo& r = a.kase.report;
  std::string meta;
  if (!a.kase.project.empty()) meta += c.t("doc.project") + ": " + a.kase.project + ". ";
  meta += c.t("doc.generated") + " " + c.t("doc.version") + " " + ASSESS_VERSION + ", " + c.t("doc.date") + " " +
          (c.o.date.empty() ? detail::today_utc() : c.o.date) + ".";
  c.d.set_subtitle(meta);
  // Frontespizio: who, what, where (the case key "report"; the site as the engine used it).
  std::vector<std::vector<Cell>> rows;
  auto row = [&](const std::string& key, const std::string& v, bool user = true) {
    if (v.empty()) return;
    Cell value(v);
    value.user = user;
    rows.push_back({Cell(c.t(key)), value});
  };
  row("front.client", r.client);
  row("front.work", r.work.empty() ? a.kase.project : r.work);
  row("front.location", r.location);
  if (a.kase.site) row("front.site", c.loc(a.site.description), false);
  row("front.engineer", r.engineer);
  row("front.registration", r.registration);
  row("front.date", c.o.date.empty() ? detail::today_utc() : c.o.date, false);
  row("front.revision", r.revision.empty() ? "0" : r.revision);
  row("front.case_file", detail::shown_file(a.kase.file));
  c.d.add_cell_table({Cell(c.t("front.item")), Cell(c.t("front.value"))}, rows, "", "front");
  add_verdict_box(c);
  c.d.add_contents(c.t("doc.contents"), 2);  // the sections; their parts are in the bookmarks (issue 36: length)
}

// The verdict box (issues 24, 28): the conclusion (the adopted method's
// verdict under NTC 2018), then per code the verdict of each method with its
// largest D/C, counts of the checks listed in the tables, and the check that
// governs it. Every colour, word and number is read from the Verdict.
void add_verdict_box(Ctx& c) {
  const Verdict& v = c.a.verdict;
  c.d.add_heading(c.t("verdict.heading"), 2, false, false);
  if (const MethodVerdict* m = v.conclusion()) {
    const Tone tone = verdict_tone(m->outcome());
    Box b{"conclusion", tone, {{"method", v.adopted}}, {}};
    b.content.push_back(Paragraph{{Span{c.t("verdict.conclusion"), true},
                                   Span{" (" + c.t("verdict.adopted") + ": " + c.t("method." + v.adopted) + ", " +
                                        code_name(m->code) + "): "},
                                   c.outcome_span(m->outcome()),
                                   Span{", D/C = " + c.n(m->max_dc, 3), true, tone}},
                                  "outcome-line", ""});
    // A verdict the judgement calls not robust carries that qualification where it is stated (issue 36, item 4).
    if (c.a.judgement) {
      const std::string q = judgement_qualifier(c, *c.a.judgement);
      if (!q.empty()) b.content.push_back(Paragraph{{Span{c.t("eval.not_robust_box") + ": " + q + "."}}, "note", ""});
    }
    c.d.add_box(std::move(b));
  } else if (!v.overall.empty()) {
    c.d.add_box(Box{"conclusion", Tone::fail, {}, {Paragraph{{Span{c.t("verdict.conclusion"), true},
                                                              Span{": " + c.t("verdict.no_method_checks") + "."}},
                                                             "", ""}}});
  }
  // A building's mechanism: the conclusion alone (every method's checks are in
  // its checks table, the building's summary compares them; issue 36: length).
  if (c.building && c.tabulati) return;
  Box all{"verdicts", Tone::plain, {}, {}};
  for (const CodeVerdict& cv : v.overall) {
    const MethodVerdict* adopted = nullptr;
    for (const MethodVerdict& m : v.methods)
      if (m.code == cv.code && m.method == v.adopted) adopted = &m;
    const Tone box_tone = verdict_tone(adopted ? adopted->outcome() : cv.outcome());
    Box b{"verdict", box_tone, {{"code", cv.code}}, {}};
    b.content.push_back(Paragraph{{Span{code_name(cv.code) + (cv.code == v.conclusion_code
                                                                   ? std::string()
                                                                   : " — " + c.t("verdict.comparison")),
                                        true}},
                                  "", ""});
    for (const MethodVerdict& m : v.methods) {
      if (m.code != cv.code) continue;
      const Tone tone = verdict_tone(m.outcome());
      Inline line{Span{c.t("method." + m.method) + (m.method == v.adopted ? " (" + c.t("verdict.adopted") + ")" : "") +
                       ": "},
                  c.outcome_span(m.outcome()), Span{", D/C = " + c.n(m.max_dc, 3), true, tone},
                  Span{" — " + msgf(c.L, m.checks == 1 ? "verdict.counts1" : "verdict.counts", m.checks, m.failing)}};
      if (m.no_verdict > 0) line.push_back(Span{", " + msgf(c.L, "verdict.counts_nv", m.no_verdict)});
      Box mb{"method", tone, {{"method", m.method}}, {Paragraph{line, "", ""}}};
      if (m.governing >= 0) {
        const VerdictRow& r = v.rows[std::size_t(m.governing)];
        std::string gov = c.t("verdict.governing") + ": " + row_name(c, r) + ", D/C = " + c.n(r.dc, 3) + " (" +
                          c.clause(r.clause) + (r.candidate.empty() ? "" : "; " + c.loc(r.candidate)) + ")";
        if (r.no_verdict) gov += " — " + c.t("verdict.untrusted");
        else if (!std::isfinite(r.dc) && !r.note.empty()) gov += " — " + c.note(r.note);
        mb.content.push_back(Paragraph{{Span{gov}}, "note", ""});
      }
      b.content.push_back(std::move(mb));
    }
    all.content.push_back(std::move(b));
  }
  if (v.overall.empty()) all.content.push_back(Paragraph{{Span{c.t("verdict.no_checks")}}, "", ""});
  c.d.add_box(std::move(all));
  c.d.add_paragraph(c.t("verdict.note"), "meta");
}

Inline tabulati_sentence(Lang L) {
  return {Span{msg(L, "doc.tabulati") + " "}, reference(msg(L, "doc.tabulati_ref"), "tabulati-intro", tabulati_key)};
}

void add_premessa(Ctx& c) {
  const FacadeAssessment& a = c.a;
  c.d.add_heading(c.t("doc.premessa"), 2, false, true, "premessa");
  c.d.add_paragraph(c.t("doc.premessa_text") + " " + mechanism_name(c.L, a.kase.mechanism.type) + ".");
  c.d.add_paragraph(c.t("doc.procedures") + " " + c.t("method." + a.verdict.adopted) + ". " + c.t("doc.procedures_why"));
  if (c.tabulati) c.d.add_paragraph(tabulati_sentence(c.L));
}

void add_normativa(Ctx& c) {
  c.d.add_heading(c.t("doc.normativa"), 2, false);
  std::vector<Inline> items;
  for (const char* k : {"norm.ntc2018", "norm.circ2019", "norm.ntc2008", "norm.dpcm2011", "norm.seed"})
    items.push_back({Span{c.t(k)}});
  c.d.add_list(items, "normativa");
}

// Descrizione dell'edificio, indagini e livello di conoscenza, muratura,
// criteri di scelta dei meccanismi (issue 28, item 7): the engineer's text
// from the case key "report", beside what the engine itself knows.
void add_building_description(Ctx& c) {
  const FacadeAssessment& a = c.a;
  const ReportInfo& r = a.kase.report;
  c.d.add_heading(c.t("desc.heading"), 2, false);
  if (r.description.empty()) c.d.add_paragraph(c.t("desc.none"));
  else c.d.add_paragraph(Inline{Span{r.description, false, Tone::plain, "", true}});
  if (a.kase.building) {
    const BuildingModel& b = *a.kase.building;
    c.d.add_paragraph(msgf(c.L, "desc.model", c.n(b.H, 2), b.storeys, c.n(b.T1, 3), c.n(b.damping_pct, 0)));
  }
  add_knowledge_level(c);
  std::vector<std::vector<Cell>> rows;
  Cell type(r.masonry.empty() ? c.t("masonry.none") : r.masonry);
  type.user = !r.masonry.empty();
  rows.push_back({Cell(c.t("masonry.type")), type, Cell(""), Cell(c.t("data.case"))});
  double gamma = 0.0;
  if (!a.kase.mechanism.candidates.empty() && !a.kase.mechanism.candidates.front().chain.blocks().empty())
    gamma = a.kase.mechanism.candidates.front().chain.blocks().front().unit_weight;
  if (gamma > 0.0) rows.push_back({Cell(c.t("data.gamma")), c.num(gamma / 1e3, 2), Cell("kN/m³"), Cell(c.t("data.case"))});
  auto par = [&](const char* key, double v) {
    if (std::isfinite(v)) rows.push_back({Cell(c.t(key)), c.num(v, 3), Cell("MPa"), Cell("Tab. C8.5.I")});
  };
  par("masonry.fm", r.fm);
  par("masonry.tau0", r.tau0);
  par("masonry.E", r.E);
  par("masonry.G", r.G);
  c.d.add_cell_table({Cell(c.t("kin.quantity")), Cell(c.t("kin.value")), Cell(c.t("kin.unit")), Cell(c.t("data.source"))},
                     rows, c.t("masonry.caption"));
  c.d.add_heading(c.t("criteria.heading"), 2, false);
  if (!r.mechanism_criteria.empty()) c.d.add_paragraph(Inline{Span{r.mechanism_criteria, false, Tone::plain, "", true}});
  // A building: its table of mechanisms follows (building_document.cpp), each
  // mechanism's candidates in its own section; not the first mechanism's here.
  if (c.building) return;
  const MechanismSet& ms = a.kase.mechanism;
  const std::size_t n = a.kinematic.candidates.size();
  std::string which = n == 1 ? msgf(c.L, "criteria.engine_one", mechanism_name(c.L, ms.type))
                             : msgf(c.L, "criteria.engine", mechanism_name(c.L, ms.type), n);
  if (n > 1) which += " " + msgf(c.L, "criteria.parameter", c.loc(ms.parameter_name));
  c.d.add_paragraph(which);
}

// Rilievo, indagini e livello di conoscenza (C8.5.4): the engineer's text and
// the level the case adopts, which has one source, the case key; a text that
// names another level is flagged here (issue 36, item 5).
void add_knowledge_level(Ctx& c) {
  const FacadeAssessment& a = c.a;
  const ReportInfo& r = a.kase.report;
  c.d.add_heading(c.t("survey.heading"), 2, false);
  if (r.investigations.empty()) c.d.add_paragraph(c.t("survey.none"));
  else c.d.add_paragraph(Inline{Span{r.investigations, false, Tone::plain, "", true}});
  if (a.kase.knowledge_level == "given")
    c.d.add_paragraph(msgf(c.L, "survey.fc_given", c.n(a.kase.options.FC, 2)));
  else
    c.d.add_paragraph(msgf(c.L, "survey.lc", a.kase.knowledge_level, c.n(a.kase.options.FC, 2)));
  for (const std::string& lc : knowledge_level_conflict(a.kase))
    c.d.add_paragraph(Inline{Span{msgf(c.L, "survey.conflict", lc,
                                       a.kase.knowledge_level == "given" ? "FC = " + c.n(a.kase.options.FC, 2)
                                                                         : a.kase.knowledge_level),
                                  true, Tone::fail}});
}

}  // namespace assess::relazione
