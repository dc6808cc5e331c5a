// mpi/plugin.hpp: the interface between `assess` and its MPI plugin
// (assess_mpi.so, apps/mpi/plugin.cpp), the only code linked with Open MPI.
//
// MPI is used by `assess campaign` and `assess fragility` when mpirun starts
// them, and by nothing else; the executable therefore does not link Open MPI
// (its loader work, libmpi with hwloc, libevent, udev, ..., took about three
// quarters of the start-up of every command: issue 32). mpi_session.cpp loads
// the plugin with dlopen() only under mpirun. A plain C table of functions,
// versioned, so a stale plugin is refused rather than called.
#pragma once

extern "C" {

#define ASSESS_MPI_PLUGIN_VERSION 1

struct AssessMpiApi {
  int version;  ///< ASSESS_MPI_PLUGIN_VERSION
  /// MPI_Init, then this process's rank and the number of ranks; 0 on success.
  int (*init)(int* rank, int* size);
  /// MPI_Allreduce(MAX) of one int over every rank.
  int (*allreduce_max_int)(int value);
  /// MPI_Reduce(SUM) of n unsigned 64-bit counts to rank 0 (out: valid on rank 0).
  void (*reduce_sum_u64)(const unsigned long long* in, unsigned long long* out, int n);
  /// MPI_Reduce(MAX) of one double to rank 0.
  double (*reduce_max_double)(double value);
  void (*finalize)();
};

/// The plugin's one exported symbol.
const AssessMpiApi* assess_mpi_api();
typedef const AssessMpiApi* (*AssessMpiApiFn)();
}
