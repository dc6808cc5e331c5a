// facade_document.cpp: the relazione of a façade assessment as its two
// documents (issues 28, 36): the body — the sections of relazione_*.cpp in
// the order of a relazione di calcolo (relazione.md §2) — and the tabulati di
// calcolo, built once from the same assessment; the writers render them.
#include "assess/report/facade_report.hpp"

#include "report/relazione_context.hpp"
#include "report/report_heading.hpp"

#include "assess/report/html_writer.hpp"

#include <set>

namespace assess {

Relazione facade_relazione(const FacadeAssessment& a, const ReportOptions& options) {
  const Lang L = options.lang;
  DocumentBuilder d(msg(L, "doc.title"), to_string(L));
  DocumentBuilder t(msg(L, "tab.title"), to_string(L));
  d.set_key(relazione_key);
  t.set_key(tabulati_key);
  t.set_number_prefix("T");
  std::set<std::string> readings;
  relazione::Ctx c{a, options, L, d, &readings, true, false};
  relazione::Ctx x{a, options, L, t, &readings, true, false};
  // The body: general part, the mechanism, the checks and results, the
  // judgement, the conclusions, the §10.2 chapter.
  relazione::add_front_matter(c);
  relazione::add_premessa(c);
  relazione::add_normativa(c);
  relazione::add_building_description(c);
  relazione::add_site(c);
  relazione::add_choices(c);
  relazione::add_formulas(c);
  relazione::add_mechanism(c);
  relazione::add_checks(c);
  relazione::add_dynamic(c);
  relazione::add_safety_indices(c);
  relazione::add_comparison(c);
  relazione::add_interventions(c);
  relazione::add_probabilistic(c);
  relazione::add_evaluation(c);
  relazione::add_conclusions(c, false);
  relazione::add_code_chapter(c, {{mechanism_name(L, a.kase.mechanism.type), &a}});
  relazione::add_warnings(c);
  relazione::add_legend(c);
  relazione::add_signature(c);
  // The tabulati: the candidates, the dynamic analysis, the comparison, then
  // the readings (the clauses cited above collected them) and the case file.
  t.set_subtitle(d.document().subtitle);
  t.add_contents(msg(L, "doc.contents"), 3);
  relazione::add_tab_intro(x);
  relazione::add_tab_candidates(x);
  relazione::add_tab_dynamic(x);
  if (!a.verdict.rows.empty()) {
    t.add_heading(msg(L, "cmp.heading"), 2, false);
    relazione::add_tab_comparison(x);
  }
  relazione::add_readings_appendix(x);
  relazione::add_case_file(x);
  Relazione r{d.document(), t.document()};
  // A façade's body flows from section to section, the premessa after the
  // contents (issue 36: the church's body at most 15 pages).
  for (DocBlock& b : r.body.blocks)
    if (auto* h = std::get_if<Heading>(&b.value)) h->new_page = false;
  resolve_references({&r.body, &r.tabulati});
  return r;
}

Document facade_summary(const FacadeAssessment& a, const ReportOptions& options) {
  const Lang L = options.lang;
  DocumentBuilder d(msg(L, "sum.title"), to_string(L));
  relazione::Ctx c{a, options, L, d, nullptr};
  d.set_subtitle((a.kase.project.empty() ? "" : a.kase.project + ". ") + msg(L, "front.case_file") + ": " +
                 detail::shown_file(a.kase.file) + ". " + msg(L, "sum.full"));
  relazione::add_verdict_box(c);
  relazione::add_site(c);
  relazione::add_checks(c);
  relazione::add_dynamic_summary(c);
  relazione::add_safety_indices(c);
  relazione::add_interventions(c);
  relazione::add_probabilistic(c);
  relazione::add_evaluation(c);
  relazione::add_conclusions(c, false);
  relazione::add_warnings(c);
  return d.document();
}

void facade_site_section(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d) {
  relazione::Ctx c{a, options, options.lang, d, nullptr};
  relazione::add_site(c);
}

void facade_mechanism_sections(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d,
                               DocumentBuilder* tabulati, std::set<std::string>* readings) {
  relazione::Ctx c{a, options, options.lang, d, readings, tabulati != nullptr, true};
  relazione::add_verdict_box(c);
  relazione::add_mechanism(c);
  relazione::add_checks(c);
  relazione::add_dynamic(c);
  relazione::add_safety_indices(c);
  // The methods compared: in the building's summary (one table for every mechanism), not repeated here.
  relazione::add_interventions(c);
  relazione::add_evaluation(c);
  relazione::add_warnings(c);
  if (!tabulati) return;
  relazione::Ctx x{a, options, options.lang, *tabulati, readings, true, true};
  relazione::add_tab_candidates(x);
  relazione::add_tab_dynamic(x);
  relazione::add_tab_comparison(x);
  relazione::add_tab_choices(x);
  relazione::add_tab_ties(x);
}

}  // namespace assess
