// Halo exchange on one rank: a periodic axis copies the opposite face of the same block
// (edges and corners included); ghosts beyond non-periodic faces stay untouched.
#include <gtest/gtest.h>

#include "halo_pattern.h"
#include "lbm/halo_exchange.h"
#include "lbm/input_error.h"

namespace {
using namespace lbm_parallel_test;

lbm::Box global_box() {
  lbm::Box b;
  b.lo = {2, 0, 1};  // not at the origin: the exchange must only use the layout
  b.hi = {7, 4, 4};
  return b;
}

class SerialHalo : public ::testing::TestWithParam<int> {
 protected:
  std::array<bool, 3> periodic() const {
    const int bits = GetParam();
    return {(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0};
  }
  // The whole box on this rank, its populations filled with the test pattern (fill()).
  struct Block {
    lbm::Decomposition d;
    lbm::BlockLayout layout;
    lbm::PopulationField f;
    lbm::HaloExchange halo;
    explicit Block(const lbm::Decomposition& decomposition)
        : d(decomposition), layout(d.owned), f(layout), halo(d, layout) {
      fill(f, layout);
    }
  };
  Block block() const { return Block(lbm::Decomposition::serial(global_box(), periodic())); }
};

TEST_P(SerialHalo, GhostsHoldPeriodicImagesOrStayUntouched) {
  Block b = block();
  auto& [d, layout, f, halo] = b;
  EXPECT_EQ(density_mismatches(halo, f, layout), 0);
  halo.exchange(f);
  EXPECT_EQ(mismatches(f, d, layout), 0);
  // A second exchange changes nothing (idempotent).
  halo.exchange(f);
  EXPECT_EQ(mismatches(f, d, layout), 0);

  std::vector<double> s = scalar_field(layout);
  halo.exchange_scalar(s);
  EXPECT_EQ(scalar_mismatches(s, d, layout), 0);
  EXPECT_EQ(interleaved_mismatches(halo, d, layout, 4), 0);
}

// The five crossing populations per face give every owned node the values it pulls with
// all 19 (edges through the x -> y -> z sweeps), and nothing else is sent.
TEST_P(SerialHalo, CrossingPopulationsGiveTheSamePulledValues) {
  Block b = block();
  auto& [d, layout, f, halo] = b;
  EXPECT_EQ(pull_mismatches(halo, f, layout), 0);
  EXPECT_EQ(non_crossing_written(halo, f, layout), 0);
  // All 19 on some axes (the sphere coupling's flags), the five on the others: the ghosts of
  // a flagged axis's faces (not edges) are whole.
  for (int bits = 0; bits < 8; ++bits) {
    lbm::HaloPopulations which{{(bits & 1) != 0, (bits & 2) != 0, (bits & 4) != 0}};
    lbm::PopulationField g = f;
    halo.exchange(g, which);
    long long bad = 0;
    for (int k = -1; k <= layout.size(2); ++k)
      for (int j = -1; j <= layout.size(1); ++j)
        for (int i = -1; i <= layout.size(0); ++i) {
          const std::array<int, 3> c{i, j, k};
          int ghost_axes = 0, axis = -1;
          for (int a = 0; a < 3; ++a)
            if (c[a] < 0 || c[a] >= layout.size(a)) ++ghost_axes, axis = a;
          if (ghost_axes != 1 || !which.all[axis]) continue;
          for (int q = 0; q < lbm::D3Q19::Q; ++q)
            bad += double(g.at(q, layout.cell(i, j, k))) != expected(q, d, layout, i, j, k);
        }
    EXPECT_EQ(bad, 0) << "flags " << bits;
  }
}

// A hand-built decomposition that sets `periodic` but leaves `neighbor` at its default
// (as FluidSolver does when FluidParameters::periodic overrides it) still wraps.
TEST_P(SerialHalo, HandBuiltDecompositionWithDefaultNeighbours) {
  lbm::Decomposition d;
  d.global = global_box();
  d.owned = d.global;
  d.periodic = periodic();
  const lbm::BlockLayout layout(d.owned);
  lbm::PopulationField f(layout);
  fill(f, layout);
  lbm::HaloExchange(d, layout).exchange(f);
  EXPECT_EQ(mismatches(f, d, layout), 0);
}

// The refill's extra exchange is taken only for owned cells next to a ghost the exchange
// fills: face planes of periodic axes here; never interior cells, ghosts, or faces of a
// non-periodic edge (their ghosts are left alone).
TEST_P(SerialHalo, BordersExchangedGhostOnlyOnFacesOfPeriodicAxes) {
  const auto d = lbm::Decomposition::serial(global_box(), periodic());
  const lbm::BlockLayout layout(d.owned);
  const lbm::HaloExchange halo(d, layout);
  const auto p = periodic();
  for (int k = -1; k <= layout.size(2); ++k)
    for (int j = -1; j <= layout.size(1); ++j)
      for (int i = -1; i <= layout.size(0); ++i) {
        const std::array<int, 3> c{i, j, k};
        bool expect = layout.is_owned(i, j, k);
        bool on_face = false;
        for (int a = 0; a < 3; ++a)
          on_face = on_face || (p[a] && (c[a] == 0 || c[a] == layout.size(a) - 1));
        expect = expect && on_face;
        EXPECT_EQ(halo.borders_exchanged_ghost(layout.cell(i, j, k)), expect)
            << "cell " << i << " " << j << " " << k;
      }
}

INSTANTIATE_TEST_SUITE_P(AllPeriodicCombinations, SerialHalo, ::testing::Range(0, 8));

TEST(SerialHaloErrors, RejectsFieldsOfAnotherLayout) {
  const auto d = lbm::Decomposition::serial(global_box(), {true, true, true});
  const lbm::BlockLayout layout(d.owned);
  lbm::HaloExchange halo(d, layout);
  lbm::Box other = d.owned;
  other.hi[0] += 1;
  lbm::PopulationField f(lbm::BlockLayout{other});
  EXPECT_THROW(halo.exchange(f), lbm::InputError);
  std::vector<double> s(3);
  EXPECT_THROW(halo.exchange_scalar(s), lbm::InputError);
}

}  // namespace
