// report_files.cpp: a relazione written to its HTML, PDF, Word and text files
// (issues 28, 36): the body and its tabulati, each file of the body with the
// tabulati's beside it (NAME-tabulati.EXT). Each PDF is printed once with the
// contents' page column empty, untagged; its named destinations give each
// heading's page and the bookmarks are added afterwards; the
// contents' page numbers are then printed alone (the document up to its
// contents, every other mark invisible) and laid over those first pages with
// qpdf (issue 32: one print of the whole document, not two). Without qpdf, a
// second print of the whole document. One browser prints everything (it
// starts once, pdf.hpp), the two PDFs side by side, and the Word documents
// are written meanwhile (issue 36, item 7);
// every file through the guarded writer (support/output_file.hpp).
#include "assess/report/report_files.hpp"

#include "report/external_tool.hpp"
#include "report/pdf_bookmarks.hpp"

#include "assess/report/docx_writer.hpp"
#include "assess/report/html_writer.hpp"
#include "assess/report/pdf.hpp"
#include "assess/report/text_writer.hpp"
#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/output_file.hpp"


#include <cmath>
#include <cstdio>
#include <filesystem>
#include <future>
#include <sys/resource.h>
#include <unistd.h>
#include <map>
#include <sstream>

namespace assess {

namespace {

namespace fs = std::filesystem;

// The page of each heading: its anchor's named destination in the PDF
// printed with HtmlOptions::heading_destinations.
std::map<std::string, int> heading_pages(const Document& d, const std::map<std::string, int>& destinations) {
  std::map<std::string, int> pages;
  for (const DocBlock& b : d.blocks)
    if (const Heading* h = std::get_if<Heading>(&b.value))
      if (const auto at = destinations.find(h->anchor); at != destinations.end()) pages[h->anchor] = at->second;
  return pages;
}

// The words of the first `pages` pages of `pdf` (pdftotext -bbox, poppler-utils):
// per page, each word's left and right ends and its baseline (pt). Empty when pdftotext fails.
struct PdfWord {
  double x_min, x_max, y_max;
};
std::vector<std::vector<PdfWord>> pdf_words(const fs::path& pdf, int pages, const fs::path& dir) {
  std::vector<std::vector<PdfWord>> out;
  const fs::path log = dir / "words.html";
  if (detail::run_program({"pdftotext", "-bbox", "-f", "1", "-l", std::to_string(pages), pdf.string(), log.string()},
                          dir / "pdftotext.log") != 0)
    return out;
  std::istringstream in(detail::read_file(log));
  for (std::string line; std::getline(in, line);) {
    if (line.find("<page ") != std::string::npos) out.emplace_back();
    PdfWord w{};
    const std::size_t at = line.find("<word ");
    if (at != std::string::npos && !out.empty() &&
        std::sscanf(line.c_str() + at, "<word xMin=\"%lf\" yMin=\"%*f\" xMax=\"%lf\" yMax=\"%lf\"", &w.x_min,
                    &w.x_max, &w.y_max) == 3)
      out.back().push_back(w);
  }
  return out;
}

// The page numbers printed alone lie on the contents' rows of the full print:
// each number has a word of the full print on its baseline, to its left.
// Chromium shrinks a whole document whose content is wider than the page (and
// lays it out wider); the overlay, which ends at the contents, would not be
// shrunk with it and its numbers would fall between the lines.
bool numbers_on_rows(const fs::path& full, const fs::path& overlay, int pages, const fs::path& dir) {
  const auto base = pdf_words(full, pages, dir), numbers = pdf_words(overlay, pages, dir);
  if (base.size() < numbers.size()) return false;
  for (std::size_t p = 0; p < numbers.size(); ++p)
    for (const PdfWord& n : numbers[p]) {
      bool row = false;
      for (const PdfWord& w : base[p]) row = row || (std::abs(w.y_max - n.y_max) < 0.5 && w.x_max < n.x_min);
      if (!row) return false;
    }
  return true;
}

// The PDF's bookmarks: the headings with a page, numbered as printed, the
// title's level dropped.
std::vector<detail::Bookmark> bookmarks(const Document& d, const std::map<std::string, int>& pages) {
  std::vector<detail::Bookmark> out;
  const std::vector<std::string> numbers = heading_numbers(d);
  std::size_t k = 0;
  for (const DocBlock& b : d.blocks) {
    const Heading* h = std::get_if<Heading>(&b.value);
    if (!h) continue;
    const std::string& n = numbers[k++];
    if (pages.count(h->anchor)) out.push_back({(n.empty() ? "" : n + " ") + h->text, std::max(1, h->level - 1), h->anchor});
  }
  return out;
}

// `path`'s content replaced by the file `from` (or the text): whole or not at
// all, never over an input of the run (support/output_file.hpp).
void install(const std::string& option, const std::string& path, const fs::path* from, const std::string* text) {
  write_output_file(path, from ? read_input_file(from->string(), input_kinds::own_output) : *text, option);
}


// `base` with the pages of `overlay` laid over its first pages and the
// bookmarks of `update` (a qpdf JSON update), the base's links kept. False
// when qpdf is not installed, or when the overlay's numbers would not lie on
// the base's contents rows (numbers_on_rows): the caller prints the whole
// document with its numbers instead.
bool overlay_first_pages(const fs::path& base, const fs::path& overlay, const fs::path& update, const fs::path& out,
                         const fs::path& dir) {
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
  if (!numbers_on_rows(base, overlay, pages, dir)) return false;
  const std::string range = "1-" + std::to_string(pages);
  const int done = detail::run_program({"qpdf", base.string(), "--update-from-json=" + update.string(), "--overlay",
                                        overlay.string(), "--from=" + range,
                                        "--to=" + range, "--", out.string()},
                                       dir / "qpdf-overlay.log");
  // qpdf exits 3 for warnings with a written file.
  if ((done != 0 && done != 3) || !fs::exists(out))
    throw InputError("--pdf: qpdf could not lay the contents' page numbers over the print (exit " + std::to_string(done) + ")");
  return true;
}

// The PDF of one document: printed once, untagged, with the contents' page
// column empty and a hidden link to every heading; its named destinations
// give each heading's page; the page numbers printed alone are laid over the
// first pages and the bookmarks added, both by qpdf (without qpdf: a second,
// tagged print, its bookmarks Chromium's). Returns the heading pages (for
// the HTML edition) and writes `final`.
std::map<std::string, int> print_pdf(PdfPrinter& printer, const Document& d, const fs::path& dir, const fs::path& final) {
  fs::create_directories(dir);
  HtmlOptions o;
  o.page_column = true;
  const fs::path first = dir / "first.pdf", toc = dir / "contents.pdf", update = dir / "bookmarks.json";
  HtmlOptions marked = o;
  marked.heading_destinations = true;
  printer.print(to_html(d, marked), first.string(), false);
  o.pages = heading_pages(d, detail::pdf_destinations(first, dir));
  HtmlOptions numbers = o;
  numbers.contents_overlay = true;
  printer.print(to_html(d, numbers), toc.string(), false);
  if (!detail::write_bookmarks_update(first, bookmarks(d, o.pages), update, dir) ||
      !overlay_first_pages(first, toc, update, final, dir))
    printer.print(to_html(d, o), final.string());
  return o.pages;
}

std::string file_name(const std::string& path) { return fs::path(path).filename().string(); }

}  // namespace

std::string tabulati_path(const std::string& path) {
  const fs::path p(path);
  const std::string ext = p.extension().string();
  const std::string stem = p.stem().string();
  // "r.pdf" -> "r-tabulati.pdf"; a name without an extension (or ".hidden") gets the suffix at its end.
  if (ext.empty() || stem.empty()) return path + "-tabulati";
  return (p.parent_path() / (stem + "-tabulati" + ext)).string();
}

void write_report_files(const Relazione& r, const ReportFiles& files, PdfPrinter* started) {
  const Document* docs[2] = {&r.body, &r.tabulati};
  auto path_of = [](const std::string& body_path, int k) { return k == 0 ? body_path : tabulati_path(body_path); };
  detail::TempDir dir("assess_report_");
  PdfPrinter own;  // one browser for both documents' prints (none started unless printed)
  PdfPrinter& printer = started ? *started : own;
  // Side by side (issue 36, item 7): the Word documents and the tabulati's
  // PDF while the body's PDF prints.
  std::vector<std::future<void>> jobs;
  std::map<std::string, int> pages[2];
  std::string docx[2];
  auto wait_all = [&] {
    for (auto& j : jobs)
      if (j.valid()) j.wait();
  };
  try {
    // The tabulati's PDF first: the longest print, the run's critical path.
    if (!files.pdf.empty())
      jobs.push_back(std::async(std::launch::async, [&] {
        pages[1] = print_pdf(printer, *docs[1], dir.path() / "pdf-1", dir.path() / "final-1.pdf");
      }));
    for (int k = 0; k < 2 && !files.docx.empty(); ++k)
      jobs.push_back(std::async(std::launch::async, [&, k] {
        // Behind the PDFs (Linux: a thread's own nice value): the tabulati's print is the run's critical path.
        (void)::setpriority(PRIO_PROCESS, ::gettid(), 10);
        docx[k] = docx_bytes(*docs[k], "--docx " + path_of(files.docx, k));
      }));
    if (!files.pdf.empty()) pages[0] = print_pdf(printer, *docs[0], dir.path() / "pdf-0", dir.path() / "final-0.pdf");
    for (auto& j : jobs) j.get();  // rethrows the first failure
  } catch (...) {
    wait_all();
    throw;
  }
  for (int k = 0; k < 2; ++k) {
    if (!files.pdf.empty()) {
      const fs::path final = dir.path() / ("final-" + std::to_string(k) + ".pdf");
      install("--pdf", path_of(files.pdf, k), &final, nullptr);
    }
    if (!files.html.empty()) {
      HtmlOptions o;
      if (!files.pdf.empty()) {
        o.page_column = true;
        o.pages = pages[k];
      }
      // The two pages link each other by file name (they are written side by side).
      o.documents[k == 0 ? tabulati_key : relazione_key] = file_name(path_of(files.html, 1 - k));
      const std::string page = to_html(*docs[k], o);
      install("--html", path_of(files.html, k), nullptr, &page);
    }
    if (!files.txt.empty()) {
      const std::string text = to_text(*docs[k]);
      install("--txt", path_of(files.txt, k), nullptr, &text);
    }
    if (!files.docx.empty()) install("--docx", path_of(files.docx, k), nullptr, &docx[k]);
  }
}

}  // namespace assess
