// external_tool.cpp: temporary directories and external programs of the report writers.
#include "report/external_tool.hpp"

#include "assess/support/error.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <iterator>

namespace assess::detail {

TempDir::TempDir(const std::string& stem) {
  std::string tmpl = (std::filesystem::temp_directory_path() / (stem + "XXXXXX")).string();
  if (!::mkdtemp(tmpl.data())) throw InputError("cannot create a temporary directory in " + tmpl);
  path_ = tmpl;
}

TempDir::~TempDir() {
  std::error_code ec;
  std::filesystem::remove_all(path_, ec);
}

std::string sh_quote(const std::string& s) {
  std::string out = "'";
  for (char c : s) out += (c == '\'') ? std::string("'\\''") : std::string(1, c);
  return out + "'";
}

int run_program(const std::vector<std::string>& argv, const std::filesystem::path& log, int timeout_s) {
  std::string cmd = "timeout " + std::to_string(timeout_s);
  for (const std::string& a : argv) cmd += " " + sh_quote(a);
  cmd += " >" + sh_quote(log.string()) + " 2>&1";
  const int status = std::system(cmd.c_str());
  return (status != -1 && WIFEXITED(status)) ? WEXITSTATUS(status) : 1;
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
