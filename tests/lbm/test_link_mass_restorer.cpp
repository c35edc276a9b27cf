// LinkMassRestorer::remove (lbm/moving_wall/link_mass.h) against the plain loop it replaces:
// its fast path tests the 19 sources' types word by word and writes without tests, its
// exact loop moves the shares of open sources onto the rest population. Both must give the
// plain loop's writes, bit for bit, whatever the types around the node.
#include <gtest/gtest.h>

#include <random>

#include "lbm/block_layout.h"
#include "lbm/d3q19.h"
#include "lbm/moving_wall/link_mass.h"
#include "lbm/node_type.h"
#include "lbm/population_field.h"

namespace {
using L = lbm::D3Q19;

// The correction as written before the fast path: one type test per source.
void plain_remove(const lbm::BlockLayout& layout, const std::vector<std::uint8_t>& type,
                  lbm::PopulationField& f, std::size_t x, double d) {
  double at_rest = 0.0;
  for (int p = 0; p < L::Q; ++p) {
    const std::size_t from = x - layout.offset(L::c[p][0], L::c[p][1], L::c[p][2]);
    if (type[from] == lbm::kOpen) {
      at_rest += L::w[p] * d;
      continue;
    }
    f.at(p, from) = static_cast<lbm::Real>(f.at(p, from) - L::w[p] * d);
  }
  if (at_rest != 0.0) f.at(0, x) = static_cast<lbm::Real>(f.at(0, x) - at_rest);
}

struct Block {
  lbm::BlockLayout layout{lbm::Box{{0, 0, 0}, {4, 5, 3}}};
  std::vector<std::uint8_t> type = std::vector<std::uint8_t>(layout.num_cells(), lbm::kFluid);
  lbm::PopulationField f{layout};
  Block() {
    for (std::size_t i = 0; i < f.raw().size(); ++i) f.raw()[i] = lbm::Real(0.01 * (i % 97) + 1.0);
  }
};

// remove() on one copy, the plain loop on another, at every owned node: same populations.
void expect_same_writes(const Block& block, double d) {
  for (int k = 0; k < block.layout.size(2); ++k)
    for (int j = 0; j < block.layout.size(1); ++j)
      for (int i = 0; i < block.layout.size(0); ++i) {
        const std::size_t x = block.layout.cell(i, j, k);
        Block fast = block, plain = block;
        const lbm::moving_wall::LinkMassRestorer restorer(fast.layout, fast.type, fast.f);
        restorer.remove(x, d);
        plain_remove(plain.layout, plain.type, plain.f, x, d);
        ASSERT_EQ(fast.f.raw(), plain.f.raw()) << "node " << i << " " << j << " " << k;
      }
}
}  // namespace

TEST(LinkMassRestorer, OneOpenSourceInEachDirection) {
  // The open cell at every neighbour of a central node in turn (every row and edge word of
  // the fast test), and at the cells the word reads beyond a row.
  Block base;
  const std::size_t centre = base.layout.cell(1, 2, 1);
  for (int dz = -1; dz <= 1; ++dz)
    for (int dy = -1; dy <= 1; ++dy)
      for (int dx = -1; dx <= 2; ++dx) {
        Block block = base;
        block.type[centre + base.layout.offset(dx, dy, dz)] = lbm::kOpen;
        expect_same_writes(block, 0.125);
      }
}

TEST(LinkMassRestorer, RandomTypesAroundTheNodes) {
  std::mt19937 rng(7);
  std::uniform_int_distribution<int> pick(0, 3);
  for (int trial = 0; trial < 20; ++trial) {
    Block block;
    for (auto& t : block.type) t = std::uint8_t(pick(rng) == 3 && trial % 2 ? lbm::kOpen : pick(rng) % 3);
    expect_same_writes(block, -0.3 + 0.05 * trial);
  }
}
