// pdf.hpp: print an HTML report to PDF with Debian's headless Chromium
// (`chromium --headless --print-to-pdf`), A4 as the page's @page rule says
// (report layer; runs an external program, computes nothing).
#pragma once

#include <string>
#include <utility>
#include <vector>

namespace assess {

/// Prints the HTML document `html` (the text of the page) to the PDF file
/// `pdf_path`. The browser is `chromium` on PATH, or the program named by the
/// environment variable CHROMIUM. @throws InputError if the browser is missing
/// (naming the Debian package chromium), fails, or writes no PDF.
void html_to_pdf(const std::string& html, const std::string& pdf_path);

/// The bookmarks of a PDF printed by html_to_pdf, in document order: (page,
/// title) of every heading. Read with pdftohtml (Debian package
/// poppler-utils); empty when it is missing or fails.
std::vector<std::pair<int, std::string>> pdf_outline(const std::string& pdf_path);

}  // namespace assess
