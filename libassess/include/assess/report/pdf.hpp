// pdf.hpp: print an HTML report to PDF with Debian's headless Chromium, A4
// as the page's @page rule says (report layer; runs an external program,
// computes nothing). A PdfPrinter starts the browser once for all the PDFs
// of a run and prints them side by side through its DevTools pipe; a
// browser that does not speak it prints with `--print-to-pdf`, one process
// per print.
#pragma once

#include <memory>
#include <string>

namespace assess {

/// The PDFs of one run, printed by one headless browser (started by start()
/// or at the first print, closed with the printer). The browser is `chromium` on
/// PATH, or the program named by the environment variable CHROMIUM.
class PdfPrinter {
 public:
  PdfPrinter();
  ~PdfPrinter();
  PdfPrinter(const PdfPrinter&) = delete;
  PdfPrinter& operator=(const PdfPrinter&) = delete;

  /// Starts the browser in the background (once): its start-up runs beside
  /// the work that comes before the first print. Errors are the first print's.
  void start();

  /// Prints the HTML document `html` (the text of the page) to the PDF file
  /// `pdf_path`; several threads may print at once. With `bookmarks` false,
  /// no outline and no tags: a quarter less work, for a print whose
  /// bookmarks are added afterwards or that is laid over another one. @throws
  /// InputError if the browser is missing (naming the Debian package
  /// chromium), fails, takes more than 180 s or writes no PDF.
  void print(const std::string& html, const std::string& pdf_path, bool bookmarks = true);

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace assess
