// external_tool.hpp (private to the report layer): the programs the report
// writers run (headless Chromium for the PDF, pdfinfo for its headings' pages,
// qpdf), each in a private temporary directory removed afterwards, without a
// shell, in its own process group, with a time limit; a signal that stops
// `assess` stops them and removes the directory (support/termination.hpp,
// issue 39). The Word writer runs none (docx_writer.hpp).
#pragma once

#include <filesystem>
#include <string>
#include <vector>

namespace assess::detail {

/// A private temporary directory (support/termination.hpp's
/// make_temporary_folder: under TMPDIR, removed on a signal), removed with
/// its content when it goes out of scope.
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

/// Exit status of run_program for a program not found on PATH.
inline constexpr int program_not_found = 127;
/// Exit status of run_program for a program killed at its time limit.
inline constexpr int program_timed_out = 124;

/// Runs `argv` (program and arguments) with `timeout_s` seconds, standard
/// output and error to `log`, TMPDIR the folder of `log` (a TempDir). Returns its exit status: program_not_found,
/// program_timed_out, 128 + N when signal N ended it. A program that cannot
/// be started for another reason is an InputError naming it and the cause.
int run_program(const std::vector<std::string>& argv, const std::filesystem::path& log, int timeout_s = 180);

/// Writes `text` to `path` (binary); InputError naming `what` on failure.
void write_file(const std::filesystem::path& path, const std::string& text, const std::string& what);

/// The text of a file ("" if it cannot be read).
std::string read_file(const std::filesystem::path& path);

}  // namespace assess::detail
