// lbm::lattice_totals (lbm/macroscopic.h) gives what total_mass, max_speed and a count of the
// particle nodes give, bit for bit, from its one pass along the rows: on a lattice of random
// populations with walls, particle (kMoving) nodes and a body force, with the standard and
// with the incompressible equilibrium.
#include <gtest/gtest.h>

#include <random>

#include "cases/serial_flow.h"
#include "lbm/d3q19.h"
#include "lbm/macroscopic.h"
#include "lbm/node_type.h"
#include "lbm/stability.h"

namespace {

void expect_totals_as_the_separate_passes(bool incompressible) {
  lbm::VoxelGeometry g({13, 9, 7});
  for (int k = 2; k < 5; ++k)
    for (int j = 1; j < 7; ++j) g.set_solid(5, j, k, true);
  lbm::FluidParameters p;
  p.tau = 0.8;
  p.body_force = {3e-5, -1e-5, 2e-6};
  p.incompressible = incompressible;
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, {true, false, true}));
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> noise(0.5, 1.5);
  for (std::size_t cell = 0; cell < solver.layout().num_cells(); ++cell)
    if (solver.node_types()[cell] == lbm::kFluid)
      for (int q = 0; q < lbm::D3Q19::Q; ++q) solver.populations().at(q, cell) *= noise(rng);
  // A few owned nodes become particle nodes, as a sphere's mapping would mark them.
  long long moving = 0;
  for (int i = 8; i < 11; ++i)
    for (int j = 3; j < 5; ++j) {
      solver.node_types()[solver.layout().cell(i, j, 3)] = lbm::kMoving;
      ++moving;
    }
  const lbm::LatticeTotals totals = lbm::lattice_totals(solver);
  EXPECT_EQ(totals.mass, lbm::total_mass(solver));
  EXPECT_EQ(totals.max_speed, lbm::max_speed(solver));
  EXPECT_EQ(totals.moving_nodes, moving);
  EXPECT_GT(totals.max_speed, 0.01);  // random populations: far from rest
}

}  // namespace

TEST(LatticeTotals, EqualTheSeparatePassesBitForBit) { expect_totals_as_the_separate_passes(false); }

TEST(LatticeTotals, EqualTheSeparatePassesWithTheIncompressibleEquilibrium) {
  expect_totals_as_the_separate_passes(true);
}
