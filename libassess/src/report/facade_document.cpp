// facade_document.cpp: the relazione of a façade assessment as a document
// (issue 28, item 12): the sections of relazione_*.cpp in the order of a
// relazione di calcolo (relazione.md §2), built once; the writers render it.
#include "assess/report/facade_report.hpp"

#include "report/relazione_context.hpp"
#include "report/report_heading.hpp"

#include "assess/report/html_writer.hpp"

#include <set>

namespace assess {

Document facade_document(const FacadeAssessment& a, const ReportOptions& options) {
  const Lang L = options.lang;
  DocumentBuilder d(msg(L, "doc.title"), to_string(L));
  std::set<std::string> readings;
  relazione::Ctx c{a, options, L, d, &readings};
  relazione::add_front_matter(c);
  relazione::add_premessa(c);
  relazione::add_normativa(c);
  relazione::add_building_description(c);
  relazione::add_site(c);
  relazione::add_formulas(c);
  relazione::add_mechanism(c);
  relazione::add_checks(c);
  relazione::add_dynamic(c);
  relazione::add_safety_indices(c);
  relazione::add_comparison(c);
  relazione::add_interventions(c);
  relazione::add_probabilistic(c);
  relazione::add_evaluation(c);
  relazione::add_conclusions(c);
  // Appendices: the candidates' checks first (they may cite readings), the readings last but one.
  relazione::add_candidates_appendix(c);
  relazione::add_warnings(c);
  relazione::add_legend(c);
  relazione::add_readings_appendix(c);
  relazione::add_case_file(c);
  return d.document();
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

std::string facade_html(const FacadeAssessment& a, const ReportOptions& options) {
  return to_html(facade_document(a, options));
}

void facade_site_section(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d) {
  relazione::Ctx c{a, options, options.lang, d, nullptr};
  relazione::add_site(c);
}

void facade_mechanism_sections(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d,
                               std::set<std::string>* readings) {
  relazione::Ctx c{a, options, options.lang, d, readings};
  relazione::add_verdict_box(c);
  relazione::add_mechanism(c);
  relazione::add_checks(c);
  relazione::add_dynamic(c);
  relazione::add_safety_indices(c);
  // The methods compared: in the building's summary (one table for every mechanism), not repeated here.
  relazione::add_interventions(c);
  relazione::add_evaluation(c);
  relazione::add_conclusions(c, false);
  relazione::add_warnings(c);
}

void facade_candidates_appendix(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d,
                                std::set<std::string>* readings) {
  relazione::Ctx c{a, options, options.lang, d, readings};
  relazione::add_candidates_appendix(c);
}

}  // namespace assess
