// external_tool.hpp (private to the report layer): the programs the report
// writers run (headless Chromium for the PDF, pdftohtml for its outline,
// pandoc for the Word document, rsvg-convert through pandoc), each in a
// private temporary directory removed afterwards, with shell-quoted arguments
// and a time limit.
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace assess::detail {

/// A private temporary directory (mkdtemp), removed with its content.
class TempDir {
 public:
  explicit TempDir(const std::string& stem);
  ~TempDir();
  TempDir(const TempDir&) = delete;
  TempDir& operator=(const TempDir&) = delete;
  const std::filesystem::path& path() const { return path_; }

 private:
  std::filesystem::path path_;
};

/// POSIX shell single-quoting.
std::string sh_quote(const std::string& s);

/// Runs `argv` (program and arguments, quoted here) with `timeout` seconds,
/// standard output and error to `log`. Returns the exit status (127: not found).
int run_program(const std::vector<std::string>& argv, const std::filesystem::path& log, int timeout_s = 180);

/// Writes `text` to `path` (binary); InputError naming `what` on failure.
void write_file(const std::filesystem::path& path, const std::string& text, const std::string& what);

/// The text of a file ("" if it cannot be read).
std::string read_file(const std::filesystem::path& path);

}  // namespace assess::detail
