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
#include "assess/report/relazione.hpp"

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

/// The relazione of the assessment (issues 28, 36) as its two documents.
/// The body: frontespizio, verdict box and contents; premessa (with the
/// tabulati it comes with), normativa, description of the building, survey
/// and knowledge level (its source checked), masonry, criteria; the seismic
/// action; the modelling choices with their alternatives computed (and the
/// defaults the case did not give); the formulas with their clauses; the
/// candidate whose check decides the conclusion developed (bodies, drawing,
/// virtual work, kinematic quantities with their numbers, ADRS) and every
/// candidate examined with where it is developed; the checks; the dynamic
/// analysis; safety indices; the methods compared; interventions; the
/// probabilistic result when given; the evaluation and the judgement;
/// conclusions; the NTC 2018 §10.2 chapter; warnings, legend and signature.
/// The tabulati di calcolo ("T" sections): every candidate's virtual work,
/// capacity curve and checks; the dynamic analysis in full (model, records,
/// histories, every candidate); every row of the comparison; the readings
/// adopted; the case file. Each refers to the other by section number.
/// Render them with to_html (html_writer.hpp), write_docx (docx_writer.hpp)
/// or the report files (report_files.hpp).
Relazione facade_relazione(const FacadeAssessment& a, const ReportOptions& options = {});

/// The summary of the assessment (issue 41): what `assess run` prints in the
/// terminal, in the language of the options, built from the relazione's own
/// sections (the verdict box, the seismic action, the checks, the dynamic
/// results, the safety indices, the interventions, the probabilistic result,
/// the evaluation, the conclusions, the warnings): one result, one wording.
Document facade_summary(const FacadeAssessment& a, const ReportOptions& options = {});

/// The seismic-action section (site, limit states, spectra), added to `d`:
/// the building relazione shows it once (issue 22).
void facade_site_section(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d);

/// One mechanism's sections (verdict box, mechanism, checks, dynamic analysis,
/// safety indices, interventions (the methods compared are in the building's
/// summary), evaluation and judgement, warnings), added to `d`, and its part
/// of the tabulati (candidates, dynamic analysis, comparison, modelling
/// choices) added to `tabulati` (none: no tabulati, no references to them):
/// the building relazione nests them under each mechanism's heading
/// (DocumentBuilder::set_id_prefix and set_heading_shift, the same in both).
/// `readings` collects the readings its clauses rely on.
void facade_mechanism_sections(const FacadeAssessment& a, const ReportOptions& options, DocumentBuilder& d,
                               DocumentBuilder* tabulati, std::set<std::string>* readings);

}  // namespace assess
