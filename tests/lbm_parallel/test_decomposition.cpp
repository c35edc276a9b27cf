// Decomposition on one rank: serial and grid layouts, and the messages for bad grids.
// Multi-rank cuts and neighbours are checked in test_halo_mpi.cpp under mpirun.
#include <gtest/gtest.h>

#include <string>

#include "lbm/decomposition.h"
#include "lbm/input_error.h"

namespace {

lbm::Box box(std::array<int, 3> lo, std::array<int, 3> hi) {
  lbm::Box b;
  b.lo = lo;
  b.hi = hi;
  return b;
}

std::string grid_error(const lbm::Box& global, std::array<int, 3> procs) {
  try {
    lbm::Decomposition::grid(global, {false, false, false}, procs, lbm::Communicator());
  } catch (const lbm::InputError& e) {
    return e.what();
  }
  return "";
}

TEST(Decomposition, SerialOwnsEverythingAndWrapsPeriodicAxesOntoItself) {
  const lbm::Box global = box({0, 0, 0}, {8, 6, 4});
  const auto d = lbm::Decomposition::serial(global, {true, false, true});
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(d.owned.lo[a], global.lo[a]);
    EXPECT_EQ(d.owned.hi[a], global.hi[a]);
  }
  EXPECT_EQ(d.neighbor[0], (std::array<int, 2>{0, 0}));
  EXPECT_EQ(d.neighbor[1], (std::array<int, 2>{-1, -1}));
  EXPECT_EQ(d.neighbor[2], (std::array<int, 2>{0, 0}));
}

TEST(Decomposition, OneByOneByOneGridEqualsSerial) {
  const lbm::Box global = box({2, 0, 1}, {9, 5, 4});
  const auto d =
      lbm::Decomposition::grid(global, {false, true, false}, {1, 1, 1}, lbm::Communicator());
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(d.owned.lo[a], global.lo[a]);
    EXPECT_EQ(d.owned.hi[a], global.hi[a]);
  }
  EXPECT_EQ(d.neighbor[0], (std::array<int, 2>{-1, -1}));
  EXPECT_EQ(d.neighbor[1], (std::array<int, 2>{0, 0}));
}

TEST(Decomposition, RejectsGridsThatDoNotMatchTheCommunicator) {
  const lbm::Box global = box({0, 0, 0}, {8, 6, 4});
  EXPECT_NE(grid_error(global, {2, 1, 1}).find("the communicator has 1"), std::string::npos)
      << grid_error(global, {2, 1, 1});
  EXPECT_NE(grid_error(global, {1, 0, 1}).find("processors along y = 0, must be >= 1"),
            std::string::npos);
  // More processors than nodes along an axis would leave a rank without nodes.
  EXPECT_NE(grid_error(box({0, 0, 0}, {8, 6, 1}), {1, 1, 2}).find("use fewer processors along z"),
            std::string::npos);
  EXPECT_NE(grid_error(box({0, 0, 0}, {8, 0, 4}), {1, 1, 1}).find("no node along y"),
            std::string::npos);
}

}  // namespace
