// facade_report.hpp: the report of a façade assessment, as terminal text,
// JSON and a self-contained printable HTML page with plots (report layer:
// formatting and plotting only; every number comes from FacadeAssessment).
#pragma once

#include "assess/assessment/facade_assessment.hpp"
#include "assess/assessment/tie_intervention.hpp"
#include "assess/report/kinematic_report.hpp"
#include "assess/report/messages.hpp"
#include "assess/report/probabilistic_result.hpp"

#include <nlohmann/json.hpp>

#include <optional>
#include <string>

namespace assess {

class HtmlReport;

/// Readable report: site block per limit state, kinematic block with every
/// intermediate quantity, the checks table (kinematic and dynamic rows, verdicts
/// in Italian and English), the dynamic table and the D/C of all approaches.
/// Tables within 120 columns unless `width` is TextWidth::wide; the site block once.
std::string facade_text(const FacadeAssessment& a, TextWidth width = TextWidth::columns120);

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
  /// their section (tie_html.cpp) after the comparison; null: none.
  const TieInterventionResult* ties = nullptr;
};

/// The summary row (index in v.rows) that the verdict box of `code` names as
/// governing: a row without a verdict or with a D/C that is not finite first
/// (it cannot be trusted), then a failing row, then the largest D/C; -1 if the
/// code has no row. Formatting only: picks among the assessment's rows.
int governing_verdict_row(const Verdict& v, const std::string& code);

/// The relazione as a self-contained, printable HTML page (A4): verdict box
/// per code, site and spectra, a drawing of the mechanism, the virtual-work
/// and candidates tables, the kinematic quantities and the ADRS plot, the
/// checks, the dynamic analysis (compatibility of the records, theta/theta_u
/// histories, summary), the grouped D/C bars, the additional probabilistic
/// result when given (options.fragility), the legend of the clause tags
/// and the case file. Plots are SVG (render_svg).
std::string facade_html(const FacadeAssessment& a, const ReportOptions& options = {});

/// The site section of the relazione (site, limit states, spectra), appended
/// to `h`: the building relazione shows it once (issue 22).
void facade_html_site_section(const FacadeAssessment& a, const ReportOptions& options, HtmlReport& h);

/// One mechanism's sections of the relazione appended to `h` (verdict box,
/// mechanism, kinematic analysis, checks, dynamic analysis, D/C by approach,
/// the tie rods when options.ties is set, warnings): the building relazione nests them under each mechanism's heading
/// (with HtmlReport::set_id_prefix and set_heading_shift).
void facade_html_mechanism_sections(const FacadeAssessment& a, const ReportOptions& options, HtmlReport& h);

}  // namespace assess
