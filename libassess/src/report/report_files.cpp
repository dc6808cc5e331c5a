// report_files.cpp: a document written to its HTML, PDF and Word files
// (issue 28): the PDF printed once with the contents' page column empty; its
// bookmarks give each heading's page; the contents' page numbers are then
// printed alone (the document up to its contents, every other mark
// invisible) and laid over those first pages with qpdf (issue 32: one print
// of the whole document, not two). Without qpdf, a second print of the whole
// document. The Word document is written beside it while Chromium prints;
// every file through the guarded writer (support/output_file.hpp).
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


// `base` with the pages of `overlay` laid over its first pages (qpdf keeps
// the base's bookmarks and links). False when qpdf is not installed.
bool overlay_first_pages(const fs::path& base, const fs::path& overlay, const fs::path& out, const fs::path& dir) {
  const fs::path log = dir / "qpdf.log";
  const int code = detail::run_program({"qpdf", "--show-npages", overlay.string()}, log);
  if (code == detail::program_not_found) return false;
  const std::string n = detail::read_file(log);
  int pages = 0;
  for (char ch : n) {
    if (ch < '0' || ch > '9') break;
    pages = pages * 10 + (ch - '0');
  }
  if (code != 0 || pages < 1) throw InputError("--pdf: qpdf could not read the contents' page numbers (exit " + std::to_string(code) + ")");
  const std::string range = "1-" + std::to_string(pages);
  const int done = detail::run_program({"qpdf", base.string(), "--overlay", overlay.string(), "--from=" + range,
                                        "--to=" + range, "--", out.string()},
                                       dir / "qpdf-overlay.log");
  // qpdf exits 3 for warnings with a written file.
  if ((done != 0 && done != 3) || !fs::exists(out))
    throw InputError("--pdf: qpdf could not lay the contents' page numbers over the print (exit " + std::to_string(done) + ")");
  return true;
}

}  // namespace

void write_report_files(const Document& d, const ReportFiles& files) {
  // The Word document is written by pandoc while Chromium prints.
  std::future<void> docx;
  detail::TempDir dir("assess_report_");
  const fs::path docx_tmp = dir.path() / "report.docx";
  if (!files.docx.empty())
    docx = std::async(std::launch::async, [&] { write_docx(d, docx_tmp.string(), "--docx " + files.docx); });
  try {
    if (!files.pdf.empty()) {
      HtmlOptions o;
      o.page_column = true;
      const fs::path first = dir.path() / "first.pdf", toc = dir.path() / "contents.pdf", final = dir.path() / "final.pdf";
      // One print of the whole document, the contents' page column empty.
      html_to_pdf(to_html(d, o), first.string());
      o.pages = heading_pages(d, pdf_outline(first.string()));
      const std::string page = to_html(d, o);
      HtmlOptions numbers = o;
      numbers.contents_overlay = true;
      html_to_pdf(to_html(d, numbers), toc.string());
      if (overlay_first_pages(first, toc, final, dir.path())) {
        install("--pdf", files.pdf, &final, nullptr);
      } else {
        html_to_pdf(page, final.string());  // no qpdf: the whole document printed again with its numbers
        install("--pdf", files.pdf, &final, nullptr);
      }
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
