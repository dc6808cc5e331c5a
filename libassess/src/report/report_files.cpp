// report_files.cpp: a document written to its HTML, PDF and Word files
// (issue 28): the PDF in two prints (the first, of the page laid out with its
// figures empty, gives each heading's page through the PDF's bookmarks; the
// second prints the contents with them), the
// Word document beside it while Chromium prints; every file written to a
// temporary file in its folder and renamed.
#include "assess/report/report_files.hpp"

#include "report/external_tool.hpp"

#include "assess/report/docx_writer.hpp"
#include "assess/report/html_writer.hpp"
#include "assess/report/pdf.hpp"
#include "assess/report/text_writer.hpp"
#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/output_file.hpp"


#include <cctype>
#include <cstdio>
#include <filesystem>
#include <future>

namespace assess {

namespace {

namespace fs = std::filesystem;

std::string squeeze(const std::string& s) {
  std::string out;
  for (unsigned char c : s)
    if (!std::isspace(c)) out += char(c);
  return out;
}

// The page of each heading: the headings in document order matched with the
// PDF's bookmarks (Chromium makes one per h1-h6, in order) by their text.
std::map<std::string, int> heading_pages(const Document& d, const std::vector<std::pair<int, std::string>>& outline) {
  std::map<std::string, int> pages;
  const std::vector<std::string> numbers = heading_numbers(d);
  std::size_t j = 0, k = 0;
  for (const DocBlock& b : d.blocks) {
    const Heading* h = std::get_if<Heading>(&b.value);
    if (!h) continue;
    const std::string& n = numbers[k++];
    const std::string want = squeeze(n + h->text);
    for (std::size_t i = j; i < outline.size(); ++i)
      if (squeeze(outline[i].second) == want) {
        pages[h->anchor] = outline[i].first;
        j = i + 1;
        break;
      }
  }
  return pages;
}

// `path`'s content replaced by the file `from` (or the text): whole or not at
// all, never over an input of the run (support/output_file.hpp).
void install(const std::string& option, const std::string& path, const fs::path* from, const std::string* text) {
  write_output_file(path, from ? read_input_file(from->string(), input_kinds::own_output) : *text, option);
}

}  // namespace

void write_report_files(const Document& d, const ReportFiles& files) {
  // The Word document is written by pandoc while Chromium prints.
  std::future<void> docx;
  detail::TempDir dir("assess_report_");
  const fs::path docx_tmp = dir.path() / "report.docx";
  if (!files.docx.empty()) docx = std::async(std::launch::async, [&] { write_docx(d, docx_tmp.string()); });
  try {
    if (!files.pdf.empty()) {
      HtmlOptions o;
      o.page_column = true;
      o.layout_only = true;  // the first print only reads where each heading falls
      const fs::path first = dir.path() / "first.pdf", second = dir.path() / "second.pdf";
      html_to_pdf(to_html(d, o), first.string());
      o.pages = heading_pages(d, pdf_outline(first.string()));
      o.layout_only = false;
      const std::string page = to_html(d, o);
      html_to_pdf(page, second.string());
      install("--pdf", files.pdf, &second, nullptr);
      if (!files.html.empty()) install("--html", files.html, nullptr, &page);
    } else if (!files.html.empty()) {
      const std::string page = to_html(d);
      install("--html", files.html, nullptr, &page);
    }
  } catch (...) {
    if (docx.valid()) docx.wait();
    throw;
  }
  if (!files.txt.empty()) {
    const std::string text = to_text(d);
    install("--txt", files.txt, nullptr, &text);
  }
  if (docx.valid()) {
    docx.get();
    install("--docx", files.docx, &docx_tmp, nullptr);
  }
}

}  // namespace assess
