#pragma once
#include <cstddef>

#ifdef LBM_PORE_HAVE_MPI
#include <mpi.h>
#endif

namespace lbm {

// The communicator the host hands us (LIGGGHTS's `world`, or MPI_COMM_WORLD in a test).
// lbm/ never calls MPI_Init and never uses MPI_COMM_WORLD itself. Without MPI, a serial
// communicator of one rank.
class Communicator {
 public:
#ifdef LBM_PORE_HAVE_MPI
  explicit Communicator(MPI_Comm comm = MPI_COMM_SELF) : comm_(comm) {}
  MPI_Comm native() const { return comm_; }
#else
  Communicator() = default;
#endif
  int rank() const;
  int size() const;
  // In-place sums / max over all ranks.
  void sum(double* values, int count) const;
  void sum(long long* values, int count) const;
  void max(double* values, int count) const;
  double sum(double value) const { sum(&value, 1); return value; }
  // The largest of the ranks' values and the lowest rank that holds it (MPI_MAXLOC).
  struct Location {
    double value;
    int rank;
  };
  Location max_location(double value) const;
  // Send `send_count` doubles to `dest` and receive `recv_count` from `source` (tag shared).
  // A rank may be its own source/destination (periodic direction on one rank).
  void sendrecv(const double* send, int send_count, int dest, double* recv, int recv_count,
                int source, int tag) const;
  void barrier() const;

 private:
#ifdef LBM_PORE_HAVE_MPI
  MPI_Comm comm_;
#endif
};

}  // namespace lbm
