// mpi_session.cpp: MPI loaded at run time, only under mpirun (mpi_session.hpp).
#include "mpi_session.hpp"

#include "mpi/plugin.hpp"

#include <assess/support/error.hpp>

#include <cstdlib>
#include <string>
#include <vector>

#include <dlfcn.h>
#include <unistd.h>

namespace assess::cli {
namespace {

// The folder of the running executable (/proc/self/exe), "" if unknown.
std::string exe_dir() {
  std::vector<char> buf(4096);
  const ssize_t n = ::readlink("/proc/self/exe", buf.data(), buf.size() - 1);
  if (n <= 0) return "";
  std::string p(buf.data(), static_cast<std::size_t>(n));
  const auto slash = p.find_last_of('/');
  return slash == std::string::npos ? "" : p.substr(0, slash);
}

std::vector<std::string> candidates() {
  std::vector<std::string> out;
  if (const char* e = std::getenv("ASSESS_MPI_PLUGIN"); e && *e) out.push_back(e);
  const std::string dir = exe_dir();
  if (!dir.empty()) {
    out.push_back(dir + "/assess_mpi.so");  // the build tree: beside the executable
#if defined(ASSESS_MPI_PLUGIN_RELDIR)
    out.push_back(dir + "/" ASSESS_MPI_PLUGIN_RELDIR "/assess_mpi.so");  // installed: <libdir>/assess
#endif
  }
  return out;
}

}  // namespace

bool MpiSession::launched_by_mpirun() { return std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE"); }

std::string MpiSession::plugin_search_path() {
  std::string s;
  for (const std::string& c : candidates()) s += (s.empty() ? "" : ", ") + c;
  return s;
}

MpiSession::MpiSession() {
  if (!launched_by_mpirun()) return;
  std::string why;
  for (const std::string& path : candidates()) {
    if (::access(path.c_str(), F_OK) != 0) continue;
    // RTLD_GLOBAL: Open MPI's components (mca_*.so) resolve libmpi's symbols globally.
    void* h = ::dlopen(path.c_str(), RTLD_NOW | RTLD_GLOBAL);
    if (!h) {
      const char* e = ::dlerror();
      why = path + ": " + (e ? e : "cannot be loaded");
      continue;
    }
    const auto fn = reinterpret_cast<AssessMpiApiFn>(::dlsym(h, "assess_mpi_api"));
    const AssessMpiApi* api = fn ? fn() : nullptr;
    if (!api || api->version != ASSESS_MPI_PLUGIN_VERSION) {
      why = path + ": not the MPI plugin of this version of assess";
      continue;
    }
    if (api->init(&rank_, &size_) != 0) throw SystemError("MPI_Init failed (plugin " + path + ")");
    api_ = api;
    return;  // the plugin stays loaded until the process ends (Open MPI cannot be unloaded)
  }
  throw SystemError(
      "assess was started by mpirun, but its MPI plugin assess_mpi.so " +
      (why.empty() ? "is not in " + plugin_search_path() : "cannot be used: " + why) +
      " (build assess with Open MPI, Debian package libopenmpi-dev, or run without mpirun)");
}

MpiSession::~MpiSession() {
  if (api_) api_->finalize();
}

int MpiSession::max_over_ranks(int value) const { return api_ ? api_->allreduce_max_int(value) : value; }

void MpiSession::sum_to_root(const unsigned long long* in, unsigned long long* out, int n) const {
  if (api_) {
    api_->reduce_sum_u64(in, out, n);
    return;
  }
  for (int i = 0; i < n; ++i) out[i] = in[i];
}

double MpiSession::max_to_root(double value) const { return api_ ? api_->reduce_max_double(value) : value; }

}  // namespace assess::cli
