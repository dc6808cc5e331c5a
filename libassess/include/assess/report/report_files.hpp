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

#include <string>
#include <utility>
#include <vector>

namespace assess {

/// The body's files ("" for none); the tabulati are written beside each (tabulati_path).
struct ReportFiles {
  std::string html;
  std::string pdf;
  std::string docx;
  std::string txt;   ///< the relazione as plain text, 120 columns (text_writer.hpp)
};

/// The file of the tabulati beside a file of the body: "r.pdf" -> "r-tabulati.pdf",
/// "dir/casa.html" -> "dir/casa-tabulati.html", "r" -> "r-tabulati".
std::string tabulati_path(const std::string& path);

/// Every file write_report_files writes for `files`, with the option that
/// names it: ("--html", "r.html"), ("--html", "r-tabulati.html"), ... in
/// that order (the run checks each before the analysis).
std::vector<std::pair<std::string, std::string>> report_outputs(const ReportFiles& files);

/// Writes the requested files of both documents. @throws InputError naming the
/// option (--html, --pdf, --docx, --txt), the file and the cause (a missing
/// program names its Debian package).
void write_report_files(const Relazione& r, const ReportFiles& files);

}  // namespace assess
