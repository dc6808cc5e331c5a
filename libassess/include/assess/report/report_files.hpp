// report_files.hpp: a relazione written to its files (issue 28, items 7, 10,
// 11; issue 36): the body and, beside each of its files, the tabulati di
// calcolo as NAME-tabulati.EXT. The HTML pages (their cross-references link
// the two pages), the PDFs printed from them by headless Chromium (A4, PDF
// bookmarks from the headings, the contents with the page of each section:
// pdf.hpp), the Word documents (docx_writer.hpp) and plain text
// (text_writer.hpp). Every file is written to a temporary file in its folder
// and renamed, so a file is never left cut.
#pragma once

#include "assess/report/relazione.hpp"
#include "assess/report/document.hpp"
#include "assess/report/pdf.hpp"
#include "assess/support/output_file.hpp"

#include <string>
#include <utility>
#include <vector>

namespace assess {

/// The file of the tabulati beside a file of the body: "r.pdf" -> "r-tabulati.pdf",
/// "dir/casa.html" -> "dir/casa-tabulati.html", "r" -> "r-tabulati".
std::string tabulati_path(const std::string& path);

/// The body's files ("" for none); the tabulati are written beside each (tabulati_path).
struct ReportFiles {
  std::string html;
  std::string pdf;
  std::string docx;
  std::string txt;   ///< the relazione as plain text, 120 columns (text_writer.hpp)

  /// Every file write_report_files writes, each with the option that names it
  /// in errors, for check_output_files (support/output_file.hpp): a file added
  /// here is checked against the run's other outputs and inputs (issue 39);
  /// each body file with its tabulati beside it (issue 36: "r.html",
  /// "r-tabulati.html", ...).
  std::vector<OutputTarget> outputs() const {
    std::vector<OutputTarget> out;
    for (const auto& [path, what] : {std::pair<const std::string*, const char*>{&html, "--html"}, {&pdf, "--pdf"},
                                     {&docx, "--docx"}, {&txt, "--txt"}})
      if (!path->empty()) {
        out.push_back({*path, what, ""});
        out.push_back({tabulati_path(*path), what, ""});
      }
    return out;
  }
};

/// Writes the requested files of both documents; the PDFs with `printer`
/// (one the caller started early, pdf.hpp) or a printer of their own.
/// @throws InputError naming the option (--html, --pdf, --docx, --txt), the
/// file and the cause (a missing program names its Debian package).
void write_report_files(const Relazione& r, const ReportFiles& files, PdfPrinter* printer = nullptr);

}  // namespace assess
