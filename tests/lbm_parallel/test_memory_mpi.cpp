// The collective memory check (lbm/memory_estimate.h) on 2 ranks: the bytes of the ranks on one
// machine add up, and every rank throws when any is short, so a host's error->all cannot hang.
#include <gtest/gtest.h>
#include <mpi.h>

#include <string>

#include "lbm/input_error.h"
#include "lbm/memory_estimate.h"

TEST(MemoryMpi, TheRanksOfAMachineAddUpAndAllThrowTogether) {
  const lbm::Communicator comm(MPI_COMM_WORLD);
  EXPECT_NO_THROW(lbm::check_fits_in_memory_on_every_machine(1e6, "small", "", comm));
  // Only rank 0 asks for too much; every rank must throw, naming the machine's total.
  const double mine = comm.rank() == 0 ? 1e15 : 1e6;
  try {
    lbm::check_fits_in_memory_on_every_machine(mine, "the lattice", "raise dx", comm);
    FAIL() << "rank " << comm.rank() << " did not throw";
  } catch (const lbm::InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("the lattice, with the 2 ranks on this machine together, needs 909 TiB"),
              std::string::npos)
        << what;
    EXPECT_NE(what.find("; raise dx"), std::string::npos) << what;
  }
}
