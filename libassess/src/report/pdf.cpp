// pdf.cpp: HTML -> PDF through headless Chromium. Each page is written to a
// private temporary directory and printed by the run's one browser through
// its DevTools pipe (report/devtools_browser.hpp), or, when the browser does
// not speak it, by `chromium --print-to-pdf` (no header and footer lines;
// PDF bookmarks from the headings); the PDF is checked to start with "%PDF".
// The pages of the headings are read back by report_files.cpp
// (report/pdf_bookmarks.hpp).
#include "assess/report/pdf.hpp"

#include "report/devtools_browser.hpp"
#include "report/external_tool.hpp"

#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/output_file.hpp"

#include <cstdlib>
#include <filesystem>
#include <future>
#include <mutex>

namespace assess {

namespace {

std::string browser_program() {
  const char* env = std::getenv("CHROMIUM");
  return env && *env ? env : "chromium";
}

// One print by its own browser process (`--print-to-pdf`): the PDF's bytes.
std::string print_alone(const std::string& browser, const std::filesystem::path& page, const std::filesystem::path& dir) {
  namespace fs = std::filesystem;
  const fs::path out = dir / "report.pdf", log = dir / "chromium.log";
  const int code = detail::run_program(
      {browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
       "--disable-component-update", "--disable-sync", "--user-data-dir=" + (dir / "profile").string(),
       "--no-pdf-header-footer", "--print-to-pdf-no-header", "--generate-pdf-document-outline",
       "--print-to-pdf=" + out.string(), detail::file_url(page)},
      log);
  if (code == detail::program_not_found)
    throw InputError("--pdf: " + browser + " was not found on PATH: install it (Debian: apt-get install chromium)");
  if (code == detail::program_timed_out)
    throw InputError("--pdf: " + browser + " did not finish printing within its time limit (180 s)");
  if (code != 0 || !fs::exists(out))
    throw InputError("--pdf: " + browser + " could not print the report (exit " + std::to_string(code) + ")");
  return read_input_file(out.string(), input_kinds::own_output);
}

}  // namespace

struct PdfPrinter::Impl {
  std::string browser = browser_program();
  std::unique_ptr<detail::TempDir> dir;
  std::unique_ptr<detail::DevtoolsBrowser> session;
  bool alone = false;  // the browser does not speak DevTools: one process per print
  std::mutex mutex;    // guards what follows
  bool launched = false;
  std::future<void> launching;  // last: destroyed (waited for) first

  void launch() {
    dir = std::make_unique<detail::TempDir>("assess_browser_");
    try {
      session = std::make_unique<detail::DevtoolsBrowser>(browser, dir->path());
    } catch (const detail::DevtoolsUnavailable&) {
      alone = true;
    }
  }
  void start() {
    std::lock_guard<std::mutex> lock(mutex);
    if (launched) return;
    launched = true;
    launching = std::async(std::launch::async, [this] { launch(); });
  }
  // The run's browser, started (or its start waited for); nullptr: print alone.
  detail::DevtoolsBrowser* started() {
    start();
    std::lock_guard<std::mutex> lock(mutex);
    if (launching.valid()) launching.get();  // its error, once (then each print alone says it again)
    return session.get();
  }
};

PdfPrinter::PdfPrinter() : impl_(std::make_unique<Impl>()) {}
PdfPrinter::~PdfPrinter() = default;

void PdfPrinter::start() { impl_->start(); }

void PdfPrinter::print(const std::string& html, const std::string& pdf_path, bool bookmarks) {
  detail::TempDir dir("assess_pdf_");
  const std::filesystem::path page = dir.path() / "report.html";
  detail::write_file(page, html, "--pdf");
  detail::DevtoolsBrowser* session = impl_->started();
  const std::string pdf = session ? session->print(page, bookmarks) : print_alone(impl_->browser, page, dir.path());
  if (pdf.compare(0, 4, "%PDF") != 0)
    throw InputError("--pdf: " + impl_->browser + " could not print the report (what it wrote is not a PDF)");
  // Whole or not at all, never over an input of the run (output_file.hpp).
  write_output_file(pdf_path, pdf, "--pdf");
}

}  // namespace assess
