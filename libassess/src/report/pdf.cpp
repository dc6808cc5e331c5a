// pdf.cpp: HTML -> PDF through headless Chromium. The page is written to a
// private temporary directory, printed with --print-to-pdf (no header and
// footer lines; PDF bookmarks from the headings), and the PDF is checked to
// exist and start with "%PDF". The outline is read back with pdftohtml
// (poppler-utils) for the contents' page numbers.
#include "assess/report/pdf.hpp"

#include "report/external_tool.hpp"

#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/output_file.hpp"

#include <cstdlib>
#include <filesystem>

namespace assess {

namespace {

std::string xml_unescape(std::string s) {
  static const std::pair<const char*, const char*> ents[] = {
      {"&lt;", "<"}, {"&gt;", ">"}, {"&quot;", "\""}, {"&#39;", "'"}, {"&apos;", "'"}, {"&amp;", "&"}};
  for (const auto& [from, to] : ents)
    for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) s.replace(at, std::string(from).size(), to);
  return s;
}

}  // namespace

void html_to_pdf(const std::string& html, const std::string& pdf_path) {
  namespace fs = std::filesystem;
  const char* env = std::getenv("CHROMIUM");
  const std::string browser = env && *env ? env : "chromium";
  detail::TempDir dir("assess_pdf_");
  const fs::path page = dir.path() / "report.html", out = dir.path() / "report.pdf", log = dir.path() / "chromium.log";
  detail::write_file(page, html, "--pdf");
  const int code = detail::run_program(
      {browser, "--headless", "--no-sandbox", "--disable-gpu", "--no-first-run", "--disable-background-networking",
       "--disable-component-update", "--disable-sync", "--user-data-dir=" + (dir.path() / "profile").string(),
       "--no-pdf-header-footer", "--print-to-pdf-no-header", "--generate-pdf-document-outline",
       "--print-to-pdf=" + out.string(), "file://" + page.string()},
      log);
  if (code == detail::program_not_found)
    throw InputError("--pdf: " + browser + " was not found on PATH: install it (Debian: apt-get install chromium)");
  if (code == detail::program_timed_out)
    throw InputError("--pdf: " + browser + " did not finish printing within its time limit (180 s)");
  if (code != 0 || !fs::exists(out) || detail::read_file(out).compare(0, 4, "%PDF") != 0)
    throw InputError("--pdf: " + browser + " could not print the report (exit " + std::to_string(code) + ")");
  // Whole or not at all, never over an input of the run (output_file.hpp).
  write_output_file(pdf_path, read_input_file(out.string(), input_kinds::own_output), "--pdf");
}

std::vector<std::pair<int, std::string>> pdf_outline(const std::string& pdf_path) {
  detail::TempDir dir("assess_outline_");
  const std::filesystem::path xml = dir.path() / "outline.xml", log = dir.path() / "log";
  const int code = detail::run_program({"pdftohtml", "-xml", "-i", "-q", "-nodrm", "-f", "1", "-l", "1", pdf_path, (dir.path() / "outline").string()}, log);
  std::vector<std::pair<int, std::string>> out;
  if (code != 0) return out;
  const std::string s = detail::read_file(xml);
  for (std::size_t at = s.find("<item page=\""); at != std::string::npos; at = s.find("<item page=\"", at + 1)) {
    const std::size_t q = s.find('"', at + 12), gt = s.find('>', at), end = s.find("</item>", at);
    if (q == std::string::npos || gt == std::string::npos || end == std::string::npos) break;
    out.push_back({std::atoi(s.substr(at + 12, q - at - 12).c_str()), xml_unescape(s.substr(gt + 1, end - gt - 1))});
  }
  return out;
}

}  // namespace assess
