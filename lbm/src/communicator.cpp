#include "lbm/communicator.h"

#include <algorithm>
#include <stdexcept>

namespace lbm {

namespace {
// One rank: a message to oneself is a copy; -1 means no partner.
void serial_sendrecv(const double* send, int send_count, int dest, double* recv, int recv_count,
                     int source) {
  if (dest > 0 || source > 0) throw std::logic_error("serial communicator: only rank 0 exists");
  if (dest < 0 || source < 0) return;
  if (send_count != recv_count)
    throw std::logic_error("serial communicator: send and receive counts differ");
  std::copy(send, send + send_count, recv);
}
}  // namespace

#ifdef LBM_PORE_HAVE_MPI

// Thin wrappers over the host's communicator. A rank of -1 (no neighbour at a non-periodic
// edge) maps to MPI_PROC_NULL, so a halo sweep needs no special case at domain edges.
// Before MPI_Init (or after MPI_Finalize) the communicator acts as one serial rank, so
// serial tools and tests of an MPI build work without initialising MPI.
namespace {
int peer(int rank) { return rank < 0 ? MPI_PROC_NULL : rank; }
bool mpi_active() {
  int initialised = 0, finalised = 0;
  MPI_Initialized(&initialised);
  MPI_Finalized(&finalised);
  return initialised && !finalised;
}
}  // namespace

int Communicator::rank() const {
  int r = 0;
  if (mpi_active()) MPI_Comm_rank(comm_, &r);
  return r;
}

int Communicator::size() const {
  int s = 1;
  if (mpi_active()) MPI_Comm_size(comm_, &s);
  return s;
}

void Communicator::sum(double* values, int count) const {
  if (mpi_active()) MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_SUM, comm_);
}

void Communicator::sum(long long* values, int count) const {
  if (mpi_active()) MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_LONG_LONG, MPI_SUM, comm_);
}

void Communicator::max(double* values, int count) const {
  if (mpi_active()) MPI_Allreduce(MPI_IN_PLACE, values, count, MPI_DOUBLE, MPI_MAX, comm_);
}

Communicator::Location Communicator::max_location(double value) const {
  Location local{value, rank()}, global = local;
  if (mpi_active()) MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, comm_);
  return global;
}

void Communicator::sendrecv(const double* send, int send_count, int dest, double* recv,
                            int recv_count, int source, int tag) const {
  if (!mpi_active()) return serial_sendrecv(send, send_count, dest, recv, recv_count, source);
  MPI_Sendrecv(send, send_count, MPI_DOUBLE, peer(dest), tag, recv, recv_count, MPI_DOUBLE,
               peer(source), tag, comm_, MPI_STATUS_IGNORE);
}

void Communicator::barrier() const {
  if (mpi_active()) MPI_Barrier(comm_);
}

#else

// One rank: reductions are identities.
int Communicator::rank() const { return 0; }
int Communicator::size() const { return 1; }
void Communicator::sum(double*, int) const {}
void Communicator::sum(long long*, int) const {}
void Communicator::max(double*, int) const {}
Communicator::Location Communicator::max_location(double value) const { return {value, 0}; }

void Communicator::sendrecv(const double* send, int send_count, int dest, double* recv,
                            int recv_count, int source, int /*tag*/) const {
  serial_sendrecv(send, send_count, dest, recv, recv_count, source);
}

void Communicator::barrier() const {}

#endif

}  // namespace lbm
