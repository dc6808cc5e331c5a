// pdf.cpp: HTML -> PDF through headless Chromium. The page is written to a
// private temporary directory, printed with --print-to-pdf (no header and
// footer lines), and the PDF is checked to exist and start with "%PDF".
#include "assess/report/pdf.hpp"

#include "assess/support/error.hpp"
#include "assess/support/input_file.hpp"
#include "assess/support/output_file.hpp"

#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>

namespace assess {

namespace {

std::string sh_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

std::string read_head(const std::string& path, std::size_t n) {
  std::ifstream in(path, std::ios::binary);
  std::string s(n, '\0');
  in.read(s.data(), std::streamsize(n));
  s.resize(std::size_t(in.gcount()));
  return s;
}

}  // namespace

void html_to_pdf(const std::string& html, const std::string& pdf_path) {
  namespace fs = std::filesystem;
  const char* env = std::getenv("CHROMIUM");
  const std::string browser = env && *env ? env : "chromium";
  std::string tmpl = (fs::temp_directory_path() / "assess_pdf_XXXXXX").string();
  if (!::mkdtemp(tmpl.data())) throw InputError("--pdf: cannot create a temporary directory in " + tmpl);
  const fs::path dir(tmpl);
  struct Cleanup {
    fs::path d;
    ~Cleanup() {
      std::error_code ec;
      fs::remove_all(d, ec);
    }
  } cleanup{dir};
  const fs::path page = dir / "report.html", out = dir / "report.pdf", log = dir / "chromium.log";
  {
    std::ofstream f(page, std::ios::binary);
    if (!(f << html)) throw InputError("--pdf: cannot write the temporary page " + page.string());
  }
  const std::string cmd = "timeout 180 " + sh_quote(browser) +
                          " --headless --no-sandbox --disable-gpu --no-first-run --disable-background-networking"
                          " --disable-component-update --disable-sync --user-data-dir=" +
                          sh_quote((dir / "profile").string()) +
                          " --no-pdf-header-footer --print-to-pdf-no-header --print-to-pdf=" +
                          sh_quote(out.string()) + " " + sh_quote("file://" + page.string()) + " >" +
                          sh_quote(log.string()) + " 2>&1";
  const int status = std::system(cmd.c_str());
  const int code = (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : 1;
  if (code == 127)
    throw InputError("--pdf: " + browser + " was not found on PATH: install it (Debian: apt-get install chromium)");
  if (code != 0 || !fs::exists(out) || read_head(out.string(), 4) != "%PDF")
    throw InputError("--pdf: " + browser + " could not print the report (exit " + std::to_string(code) + ")");
  // Whole or not at all, never over an input of the run (output_file.hpp).
  write_output_file(pdf_path, read_input_file(out.string(), input_kinds::own_output), "--pdf");
}

}  // namespace assess
