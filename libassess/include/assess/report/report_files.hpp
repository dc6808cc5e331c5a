// report_files.hpp: a relazione written to its files (issue 28, items 7, 10,
// 11): the HTML page, the PDF printed from it by headless Chromium (A4, PDF
// bookmarks from the headings, the contents with the page of each section:
// a first print gives the pages, the second prints them; pdf.hpp), and the
// Word document (docx_writer.hpp), and plain text (text_writer.hpp). Every file is written to a temporary file
// in its folder and renamed, so a file is never left cut.
#pragma once

#include "assess/report/document.hpp"
#include "assess/support/output_file.hpp"

#include <string>
#include <utility>
#include <vector>

namespace assess {

struct ReportFiles {
  std::string html;  ///< "" for none
  std::string pdf;
  std::string docx;
  std::string txt;   ///< the relazione as plain text, 120 columns (text_writer.hpp)

  /// The files asked for, each with the option that names it in errors, for
  /// check_output_files (support/output_file.hpp): a file added here is
  /// checked against the run's other outputs and inputs (issue 39).
  std::vector<OutputTarget> outputs() const {
    std::vector<OutputTarget> out;
    for (const auto& [path, what] : {std::pair<const std::string*, const char*>{&html, "--html"}, {&pdf, "--pdf"},
                                     {&docx, "--docx"}, {&txt, "--txt"}})
      if (!path->empty()) out.push_back({*path, what, ""});
    return out;
  }
};

/// Writes the requested files. @throws InputError naming the option (--html,
/// --pdf, --docx), the file and the cause (a missing program names its Debian package).
void write_report_files(const Document& d, const ReportFiles& files);

}  // namespace assess
