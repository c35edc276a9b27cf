// Decomposition and halo exchange on 2 ranks (run under mpirun -np 2): grid cuts tile the
// global box with the right neighbours, and after an exchange every ghost holds the
// pattern value of its (wrapped) global coordinates, for cuts along x, y and z, regular
// and uneven hand-made boxes, every combination of periodic axes.
#include <gtest/gtest.h>
#include <mpi.h>

#include <string>

#include "halo_pattern.h"
#include "lbm/halo_exchange.h"
#include "lbm/input_error.h"

namespace {
using namespace lbm_parallel_test;

lbm::Communicator world() { return lbm::Communicator(MPI_COMM_WORLD); }

lbm::Box make_box(std::array<int, 3> lo, std::array<int, 3> hi) {
  lbm::Box b;
  b.lo = lo;
  b.hi = hi;
  return b;
}

std::array<bool, 3> periodic_bits(int bits) {
  return {(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0};
}

void check_exchange(const lbm::Decomposition& d) {
  const lbm::BlockLayout layout(d.owned);
  lbm::PopulationField f(layout);
  fill(f, layout);
  lbm::HaloExchange halo(d, layout);
  EXPECT_EQ(density_mismatches(halo, f, layout), 0) << "rank " << d.comm.rank();
  // The five crossing populations per face: the same pulled values as with all 19.
  EXPECT_EQ(pull_mismatches(halo, f, layout), 0) << "rank " << d.comm.rank();
  EXPECT_EQ(non_crossing_written(halo, f, layout), 0) << "rank " << d.comm.rank();
  halo.exchange(f);
  EXPECT_EQ(mismatches(f, d, layout), 0) << "rank " << d.comm.rank();
  std::vector<double> s = scalar_field(layout);
  halo.exchange_scalar(s);
  EXPECT_EQ(scalar_mismatches(s, d, layout), 0) << "rank " << d.comm.rank();
  EXPECT_EQ(interleaved_mismatches(halo, d, layout, 4), 0) << "rank " << d.comm.rank();
}

TEST(GridOnTwoRanks, CutsTileTheGlobalBoxWithTheRightNeighbours) {
  ASSERT_EQ(world().size(), 2);
  const lbm::Box global = make_box({0, 1, 2}, {11, 8, 7});
  const int rank = world().rank(), other = 1 - rank;
  for (int split = 0; split < 3; ++split)
    for (int bits = 0; bits < 8; ++bits) {
      std::array<int, 3> procs{1, 1, 1};
      procs[split] = 2;
      const auto periodic = periodic_bits(bits);
      const auto d = lbm::Decomposition::grid(global, periodic, procs, world());
      // Cut at floor(n * 1 / 2) from the global lower bound.
      const int cut = global.lo[split] + global.size(split) / 2;
      EXPECT_EQ(d.owned.lo[split], rank == 0 ? global.lo[split] : cut);
      EXPECT_EQ(d.owned.hi[split], rank == 0 ? cut : global.hi[split]);
      // Both boxes together cover the global box exactly.
      long long boxes[12] = {};
      for (int a = 0; a < 3; ++a) {
        boxes[6 * rank + a] = d.owned.lo[a];
        boxes[6 * rank + 3 + a] = d.owned.hi[a];
      }
      world().sum(boxes, 12);
      long long volume = 0;
      for (int r = 0; r < 2; ++r) {
        long long v = 1;
        for (int a = 0; a < 3; ++a) {
          EXPECT_GE(boxes[6 * r + a], global.lo[a]);
          EXPECT_LE(boxes[6 * r + 3 + a], global.hi[a]);
          v *= boxes[6 * r + 3 + a] - boxes[6 * r + a];
        }
        EXPECT_GT(v, 0);
        volume += v;
      }
      EXPECT_EQ(volume, global.volume());
      EXPECT_EQ(boxes[3 + split], boxes[6 + split]);  // rank 0 ends where rank 1 starts
      for (int a = 0; a < 3; ++a) {
        std::array<int, 2> expected;
        if (a != split)
          expected = periodic[a] ? std::array<int, 2>{rank, rank} : std::array<int, 2>{-1, -1};
        else if (periodic[a])
          expected = {other, other};
        else
          expected = rank == 0 ? std::array<int, 2>{-1, 1} : std::array<int, 2>{0, -1};
        EXPECT_EQ(d.neighbor[a], expected)
            << "split " << split << " axis " << a << " bits " << bits;
      }
      check_exchange(d);
    }
}

TEST(GridOnTwoRanks, RejectsAGridOfOneRank) {
  try {
    lbm::Decomposition::grid(make_box({0, 0, 0}, {4, 4, 4}), {}, {1, 1, 1}, world());
    FAIL() << "no exception";
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("the communicator has 2"), std::string::npos) << e.what();
  }
}

// Hand-made boxes as LIGGGHTS would dictate them: an uneven cut at `cut` along `split`,
// optionally with rank 1 holding the lower part; neighbours set like procneigh.
lbm::Decomposition hand_made(const lbm::Box& global, int split, int cut, bool reversed,
                             std::array<bool, 3> periodic) {
  lbm::Decomposition d;
  d.global = global;
  d.periodic = periodic;
  d.comm = world();
  const int rank = d.comm.rank(), other = 1 - rank;
  const bool lower = (rank == 0) != reversed;
  d.owned = global;
  (lower ? d.owned.hi : d.owned.lo)[split] = cut;
  for (int a = 0; a < 3; ++a) {
    if (a != split) {
      d.neighbor[a] = periodic[a] ? std::array<int, 2>{rank, rank} : std::array<int, 2>{-1, -1};
      continue;
    }
    d.neighbor[a][lower ? 1 : 0] = other;
    d.neighbor[a][lower ? 0 : 1] = periodic[a] ? other : -1;
  }
  return d;
}

TEST(HandMadeBoxes, UnevenCutsAlongEveryAxis) {
  const lbm::Box global = make_box({0, 0, 0}, {10, 7, 5});
  const int cuts[3] = {3, 5, 1};
  for (int split = 0; split < 3; ++split)
    for (bool reversed : {false, true})
      for (int bits = 0; bits < 8; ++bits) {
        SCOPED_TRACE("split " + std::to_string(split) + " reversed " + std::to_string(reversed) +
                     " periodic bits " + std::to_string(bits));
        check_exchange(hand_made(global, split, cuts[split], reversed, periodic_bits(bits)));
      }
}

TEST(HandMadeBoxes, NeighboursThatDoNotShareAFaceAreRejected) {
  lbm::Decomposition d =
      hand_made(make_box({0, 0, 0}, {10, 7, 5}), 0, 3, false, {true, false, false});
  if (d.comm.rank() == 1) d.owned.hi[1] = 6;  // rank 1 one node shorter along y
  const lbm::BlockLayout layout(d.owned);
  try {
    lbm::HaloExchange halo(d, layout);
    FAIL() << "no exception on rank " << d.comm.rank();
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("do not share a face"), std::string::npos) << e.what();
  }
}

// Split along a non-periodic x: only the owned plane at the cut borders a ghost that the
// exchange fills (rank 0's top plane, rank 1's bottom one); the outer faces do not.
TEST(GridOnTwoRanks, BordersExchangedGhostOnlyAtTheCut) {
  ASSERT_EQ(world().size(), 2);
  const auto d = lbm::Decomposition::grid(make_box({0, 0, 0}, {8, 5, 4}), {false, false, false},
                                          {2, 1, 1}, world());
  const lbm::BlockLayout layout(d.owned);
  const lbm::HaloExchange halo(d, layout);
  const int cut_plane = world().rank() == 0 ? layout.size(0) - 1 : 0;
  for (int k = 0; k < layout.size(2); ++k)
    for (int j = 0; j < layout.size(1); ++j)
      for (int i = 0; i < layout.size(0); ++i)
        EXPECT_EQ(halo.borders_exchanged_ghost(layout.cell(i, j, k)), i == cut_plane)
            << "rank " << world().rank() << " cell " << i << " " << j << " " << k;
}

}  // namespace
