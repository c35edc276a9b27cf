// FluidSolver::keep_node_moments: the moments the collide-stream kernel writes while it holds
// each node's output are lbm::node_moments of the stored populations, bit for bit, on every
// owned fluid node, for the four kernel variants (body force or not, standard or He & Luo's
// incompressible equilibrium), on one and two threads; the field is withdrawn when the
// populations are rewritten wholesale and refreshed node by node.
#include <gtest/gtest.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <cmath>
#include <cstring>

#include "cases/serial_flow.h"
#include "lbm/macroscopic.h"
#include "lbm/node_type.h"

namespace {

bool same_bits(double a, double b) { return std::memcmp(&a, &b, sizeof a) == 0; }

// A sheared, disturbed flow on a block with a few solid cells, stepped a few times.
std::unique_ptr<lbm::FluidSolver> stirred_solver(bool forced, bool incompressible) {
  lbm::VoxelGeometry g({13, 9, 7});
  g.set_solid(5, 4, 3, true);
  g.set_solid(6, 4, 3, true);
  lbm::FluidParameters p;
  p.tau = 0.8;
  p.periodic = {true, true, true};
  p.incompressible = incompressible;
  if (forced) p.body_force = {1e-5, -2e-6, 3e-6};
  auto solver = std::make_unique<lbm::FluidSolver>(g, p, lbm::FlowDrive{},
                                                   cases::serial_decomposition(g, p.periodic));
  solver->initialise_equilibrium([](int i, int j, int k) {
    return std::array<double, 4>{1.0 + 0.01 * std::sin(0.7 * i + 0.3 * k), 0.02 * std::cos(0.5 * j),
                                 -0.01 * std::sin(0.9 * k), 0.015 * std::cos(0.4 * i)};
  });
  return solver;
}

void expect_field_is_node_moments(const lbm::FluidSolver& solver) {
  const auto* field = solver.node_moment_field();
  ASSERT_NE(field, nullptr);
  const lbm::BlockLayout& g = solver.layout();
  int checked = 0;
  for (int k = 0; k < g.size(2); ++k)
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i) {
        const std::size_t cell = g.cell(i, j, k);
        if (solver.node_types()[cell] != lbm::kFluid) continue;
        const lbm::NodeMoments m = lbm::node_moments(solver.populations(), cell, solver.parameters().body_force);
        ASSERT_TRUE(same_bits(field->at(cell)[0], m.rho)) << "rho at " << i << " " << j << " " << k;
        for (int a = 0; a < 3; ++a)
          ASSERT_TRUE(same_bits(field->at(cell)[1 + a], m.u[std::size_t(a)]))
              << "u_" << a << " at " << i << " " << j << " " << k;
        ++checked;
      }
  EXPECT_GT(checked, 800);
}

class KeptNodeMoments : public ::testing::TestWithParam<std::tuple<bool, bool, int>> {};

TEST_P(KeptNodeMoments, AreNodeMomentsOfTheStoredPopulationsBitForBit) {
  const auto [forced, incompressible, threads] = GetParam();
#ifdef _OPENMP
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
#else
  (void)threads;  // without OpenMP every variant runs on one thread: the same checks
#endif
  auto solver = stirred_solver(forced, incompressible);
  solver->keep_node_moments();
  EXPECT_EQ(solver->node_moment_field(), nullptr) << "no kernel has run since it was asked for";
  for (int step = 0; step < 3; ++step) {
    solver->step();  // both placements of the in-place field
    expect_field_is_node_moments(*solver);
  }
#ifdef _OPENMP
  omp_set_num_threads(before);
#endif
}

INSTANTIATE_TEST_SUITE_P(Variants, KeptNodeMoments,
                         ::testing::Combine(::testing::Bool(), ::testing::Bool(), ::testing::Values(1, 2)));

TEST(KeptNodeMoments, WithdrawnWhenThePopulationsAreRewrittenAndRefreshedNodeByNode) {
  auto solver = stirred_solver(true, false);
  solver->keep_node_moments();
  solver->step();
  ASSERT_NE(solver->node_moment_field(), nullptr);
  solver->initialise_equilibrium(1.0, {0.0, 0.0, 0.0});
  EXPECT_EQ(solver->node_moment_field(), nullptr);
  solver->step();
  ASSERT_NE(solver->node_moment_field(), nullptr);
  solver->set_time_step(solver->time_step());  // as a checkpoint read does
  EXPECT_EQ(solver->node_moment_field(), nullptr);
  solver->step();
  // A host rewrites one node (the refill of an uncovered node) and refreshes it.
  const std::size_t cell = solver->layout().cell(2, 3, 4);
  for (int q = 0; q < lbm::D3Q19::Q; ++q)
    solver->populations().at(q, cell) = static_cast<lbm::Real>(lbm::equilibrium(q, 1.02, {0.01, 0.0, -0.02}));
  solver->refresh_node_moments(cell);
  expect_field_is_node_moments(*solver);
}

TEST(KeptNodeMoments, OffUnlessAskedFor) {
  auto solver = stirred_solver(false, false);
  solver->step();
  EXPECT_EQ(solver->node_moment_field(), nullptr);
}

}  // namespace
