// lbm::Communicator's reductions on 2 ranks: max_location gives the largest value and the
// lowest rank that holds it, as the run-time guards need it (one rank writes the message).
#include <gtest/gtest.h>
#include <mpi.h>

#include "lbm/communicator.h"

TEST(CommunicatorMpi, MaxLocationGivesTheLargestValueAndTheLowestRankHoldingIt) {
  const lbm::Communicator comm(MPI_COMM_WORLD);
  ASSERT_EQ(comm.size(), 2);
  lbm::Communicator::Location top = comm.max_location(comm.rank() == 1 ? 5.0 : 3.0);
  EXPECT_EQ(top.value, 5.0);
  EXPECT_EQ(top.rank, 1);
  top = comm.max_location(2.5);  // a tie: the lower rank
  EXPECT_EQ(top.value, 2.5);
  EXPECT_EQ(top.rank, 0);
}
