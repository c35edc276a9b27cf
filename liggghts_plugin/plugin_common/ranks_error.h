#pragma once
// An error that some ranks may meet alone (each rank reads its own fluid checkpoint file)
// made collective: error->all on one rank hangs the others in their next collective call,
// error->one aborts MPI and Open MPI's abort notices follow the message. Agreeing first
// lets every rank stop together through error->all, which prints once on rank 0 and ends
// with MPI_Finalize.
#include <mpi.h>

#include <string>

#include "lbm/input_error.h"

namespace lbm_pore {

// Collective. `local_error` is this rank's message, empty when it has none. Returns, on every
// rank, the message of the lowest rank that has one ("rank N: ..." when N > 0), or "".
std::string first_error_of_ranks(MPI_Comm world, const std::string& local_error);

// Collective: runs `work` on every rank and returns, as above, the message of the lowest
// rank where it threw lbm::InputError (each rank reading its own file, say), or "".
template <class Work>
std::string try_on_every_rank(MPI_Comm world, Work&& work) {
  std::string local_error;
  try {
    work();
  } catch (const lbm::InputError& e) {
    local_error = e.what();
  }
  return first_error_of_ranks(world, local_error);
}

}  // namespace lbm_pore
