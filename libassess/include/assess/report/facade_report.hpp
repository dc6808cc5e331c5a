// facade_report.hpp: the report of a façade assessment, as terminal text,
// JSON and a self-contained printable HTML page with plots (report layer:
// formatting and plotting only; every number comes from FacadeAssessment).
#pragma once

#include "assess/assessment/facade_assessment.hpp"
#include "assess/assessment/tie_intervention.hpp"
#include "assess/report/kinematic_report.hpp"
#include "assess/report/document.hpp"
#include "assess/report/messages.hpp"
#include "assess/report/probabilistic_result.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <set>
#include <string>

namespace assess {


/// The same content as JSON: keys "project", "site", "kinematic" (the keys of
/// `assess kinematic --json`), "checks" (kinematic and "kind": "dynamic" rows),
/// "dynamic" (model, records, selection, analyses, summary per restitution),
/// "comparison" (D/C per approach, seed Fig. 8).
nlohmann::json facade_json(const FacadeAssessment& a);

/// What the HTML relazione needs besides the assessment.
struct ReportOptions {
  Lang lang = Lang::it;     ///< language of the text (--lang)
  std::string date;         ///< date printed in the header; empty: today (UTC, YYYY-MM-DD)
  std::string case_text;    ///< the case file's text, echoed in the appendix; empty: a note
  /// An additional probabilistic result (`assess run --fragility DIR`): shown
  /// in its own box after the verdicts by approach, labelled as not a code check.
  std::optional<ProbabilisticResult> fragility;
  /// Issue 23: the tie rods of the case (assess run with "ties" or "design"):
  /// their section (tie_html.cpp) in the interventions; null: none.
  const TieInterventionResult* ties = nullptr;
  /// A building's mechanism whose records are a set shared with others (issue
  /// 28): the set's name ("S1"); its records are described once in the
  /// building's summary and the mechanism's dynamic section refers to it.
  std::string shared_records;
};

/// The relazione of the assessment as a document (issue 28): frontespizio,
/// verdict box and contents; premessa, normativa, description of the building,
/// survey and knowledge level, masonry, criteria of the mechanisms' choice;
/// seismic action; the formulas with their clauses; each candidate that
/// governs a method developed (bodies, drawing, virtual work, kinematic
/// quantities with their numbers, capacity curve, ADRS); the checks; the
/// dynamic analysis of the candidate that governs it; safety indices; the
/// methods compared; interventions; the probabilistic result when given;
/// the evaluation of the results; conclusions and signature; appendices
/// (other candidates' checks, warnings, legend, the readings adopted, the
/// case file). Render it with to_html (html_writer.hpp), write_docx
/// (docx_writer.hpp) or the report files (report_files.hpp).
Document facade_document(const FacadeAssessment& a, const ReportOptions& options = {});

/// The summary of the assessment (issue 41): what `assess run` prints in the
/// terminal, in the language of the options, built from the relazione's own
/// sections (the verdict box, the seismic action, the checks, the dynamic
/// results, the safety indices, the interventions, the probabilistic result,
/// the evaluation, the conclusions, the warnings): one result, one wording.
Document facade_summary(const FacadeAssessment& a, const ReportOptions& options = {});

/// to_html(facade_document(a, options)).
std::string facade_html(const FacadeAssessment& a, const ReportOptions& options = {});

/// The seismic-action section (site, limit states, spectra), added to `d`:
/// the building relazione shows it once (issue 22).
void facade_site_section(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d);

/// One mechanism's sections (verdict box, mechanism, checks, dynamic analysis,
/// safety indices, interventions (the methods compared are in the building's summary), evaluation, conclusions without
/// signature, warnings), added to `d`: the building relazione nests them
/// under each mechanism's heading (DocumentBuilder::set_id_prefix and
/// set_heading_shift). `readings` collects the readings its clauses rely on.
void facade_mechanism_sections(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d,
                               std::set<std::string>* readings);

/// The appendix of the checks of the candidates the body does not develop.
void facade_candidates_appendix(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d,
                                std::set<std::string>* readings);

}  // namespace assess
