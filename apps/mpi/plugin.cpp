// mpi/plugin.cpp: the MPI plugin of `assess` (assess_mpi.so; mpi_plugin.hpp).
// Built as a module linked with Open MPI, loaded by mpi_session.cpp under mpirun only.
#include "plugin.hpp"

#include <mpi.h>

namespace {

int init(int* rank, int* size) {
  if (MPI_Init(nullptr, nullptr) != MPI_SUCCESS) return 1;
  MPI_Comm_rank(MPI_COMM_WORLD, rank);
  MPI_Comm_size(MPI_COMM_WORLD, size);
  return 0;
}

int allreduce_max_int(int value) {
  int out = 0;
  MPI_Allreduce(&value, &out, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  return out;
}

void reduce_sum_u64(const unsigned long long* in, unsigned long long* out, int n) {
  MPI_Reduce(in, out, n, MPI_UNSIGNED_LONG_LONG, MPI_SUM, 0, MPI_COMM_WORLD);
}

double reduce_max_double(double value) {
  double out = 0.0;
  MPI_Reduce(&value, &out, 1, MPI_DOUBLE, MPI_MAX, 0, MPI_COMM_WORLD);
  return out;
}

void finalize() { MPI_Finalize(); }

const AssessMpiApi api{ASSESS_MPI_PLUGIN_VERSION, init, allreduce_max_int, reduce_sum_u64, reduce_max_double, finalize};

}  // namespace

extern "C" __attribute__((visibility("default"))) const AssessMpiApi* assess_mpi_api() { return &api; }
