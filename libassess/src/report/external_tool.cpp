// external_tool.cpp: temporary directories and external programs of the report writers.
#include "report/external_tool.hpp"

#include "assess/support/error.hpp"
#include "assess/support/termination.hpp"

#include <cstring>
#include <fstream>
#include <iterator>

namespace assess::detail {

TempDir::TempDir(const std::string& stem) : path_(make_temporary_folder(stem)) {}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
  release_temporary(path_.string());
}

int run_program(const std::vector<std::string>& argv, const std::filesystem::path& log, int timeout_s) {
  // Its TMPDIR is the private temporary directory of its log: what it leaves
  // there (Chromium's org.chromium.* when it is stopped) goes with it.
  const ProgramResult r = assess::run_program(argv, log.string(), timeout_s, log.parent_path().string());
  if (!r.started) {
    if (r.start_error == ENOENT) return program_not_found;
    throw InputError("cannot start " + argv.front() + ": " + std::strerror(r.start_error));
  }
  if (r.timed_out) return program_timed_out;
  return r.signal ? 128 + r.signal : r.exit_status;
}

void write_file(const std::filesystem::path& path, const std::string& text, const std::string& what) {
  std::ofstream f(path, std::ios::binary);
  if (!(f << text) || !f.flush()) throw InputError(what + ": cannot write " + path.string());
}

std::string read_file(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

}  // namespace assess::detail
