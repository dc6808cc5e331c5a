// mpi_session.hpp: the MPI ranks of `assess campaign` and `assess fragility`.
//
// Under mpirun (Open MPI sets OMPI_COMM_WORLD_SIZE, other launchers PMI_SIZE)
// the session loads the MPI plugin (mpi/plugin.hpp) with dlopen(), starts MPI
// and finalizes it when destroyed; otherwise it is one rank and never touches
// MPI. No other command loads MPI (issue 32: start-up of every command).
#pragma once

#include <string>

extern "C" struct AssessMpiApi;  // mpi/plugin.hpp

namespace assess::cli {

class MpiSession {
 public:
  /// One rank, or MPI started through the plugin when launched by mpirun.
  /// SystemError when mpirun started us but the plugin is missing or fails.
  MpiSession();
  ~MpiSession();
  MpiSession(const MpiSession&) = delete;
  MpiSession& operator=(const MpiSession&) = delete;

  bool active() const { return api_ != nullptr; }
  int rank() const { return rank_; }
  int size() const { return size_; }
  /// The largest `value` over the ranks (every rank gets it).
  int max_over_ranks(int value) const;
  /// Sums `n` counts over the ranks into `out` on rank 0.
  void sum_to_root(const unsigned long long* in, unsigned long long* out, int n) const;
  /// The largest `value` over the ranks, on rank 0.
  double max_to_root(double value) const;

  /// Launched by an MPI launcher (environment of mpirun).
  static bool launched_by_mpirun();
  /// Where the plugin is looked for, first found wins (for messages and tests).
  static std::string plugin_search_path();

 private:
  const ::AssessMpiApi* api_ = nullptr;
  int rank_ = 0, size_ = 1;
};

}  // namespace assess::cli
