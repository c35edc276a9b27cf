// The fluid step a host runs (coupling/step_policy.h): the pure fluid step without
// particles, the coupled one while a particle or a node it covered is left, and the particle
// reach passed to the coupled step; and the coupling's memory per node
// (coupling/memory_estimate.h).
#include <gtest/gtest.h>

#include "cases/serial_flow.h"
#include "coupling/memory_estimate.h"
#include "coupling/sphere_coupling.h"
#include "coupling/step_policy.h"

using namespace coupling;

TEST(StepPolicy, PureWithoutParticlesCoupledWhileAParticleOrACoveredNodeIsLeft) {
  auto solver = cases::make_solver({12, 12, 12}, {true, true, true});
  SphereCoupling coupling(*solver);
  const lbm::Communicator comm;
  const double ghost_cutoff[3] = {4.0, 4.0, 4.0};
  ParticleSet none;
  EXPECT_EQ(choose_fluid_step(coupling, none.view(), comm), FluidStep::kPure);
  EXPECT_EQ(advance_fluid(coupling, none.view(), ghost_cutoff, 1.0, comm), FluidStep::kPure);
  EXPECT_EQ(solver->time_step(), 1);
  EXPECT_TRUE(coupling.mapping().moving_cells().empty());

  ParticleSet one;
  one.add(1, {6.2, 5.9, 6.1}, {0.0, 0.0, 0.0}, 2.5);
  EXPECT_EQ(advance_fluid(coupling, one.view(), ghost_cutoff, 1.0, comm), FluidStep::kCoupled);
  EXPECT_EQ(solver->time_step(), 2);
  EXPECT_FALSE(coupling.mapping().moving_cells().empty());
  // The particle left (deleted, or out through an open face): its nodes are still covered,
  // so one more coupled step uncovers and refills them; then the pure step again.
  EXPECT_EQ(choose_fluid_step(coupling, none.view(), comm), FluidStep::kCoupled);
  EXPECT_EQ(advance_fluid(coupling, none.view(), ghost_cutoff, 1.0, comm), FluidStep::kCoupled);
  EXPECT_TRUE(coupling.mapping().moving_cells().empty());
  EXPECT_EQ(choose_fluid_step(coupling, none.view(), comm), FluidStep::kPure);
}

TEST(StepPolicy, AGhostOnlyViewTakesThePureStep) {
  // A rank whose view holds only ghosts: their owners' ranks decide (a sum over the ranks);
  // one rank alone with nothing owned and nothing covered takes the pure step.
  auto solver = cases::make_solver({10, 10, 10}, {true, true, true});
  SphereCoupling coupling(*solver);
  ParticleSet ghosts;
  ghosts.add(1, {5.0, 5.0, 5.0}, {0.0, 0.0, 0.0}, 2.0, /*owned=*/false);
  EXPECT_EQ(choose_fluid_step(coupling, ghosts.view(), lbm::Communicator()), FluidStep::kPure);
}

TEST(StepPolicy, TheReachIsTheSmallestGhostCutoffInCellsAgainstTheLargestOwnedRadius) {
  ParticleSet particles;
  particles.add(1, {1.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, 1.5);
  particles.add(2, {5.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, 3.25);
  particles.add(3, {9.0, 1.0, 1.0}, {0.0, 0.0, 0.0}, 7.0, /*owned=*/false);  // a ghost: not counted
  const double ghost_cutoff[3] = {2.0, 1.5, 3.0};
  const ParticleReach reach = particle_reach(particles.view(), ghost_cutoff, 0.25, lbm::Communicator());
  EXPECT_EQ(reach.view_reach, 1.5 / 0.25);
  EXPECT_EQ(reach.radius_bound, 3.25);
  EXPECT_EQ(particle_reach(ParticleSet{}.view(), ghost_cutoff, 0.25, lbm::Communicator()).radius_bound, 0.0);
}

TEST(MemoryEstimate, CouplingBytesPerNodeCountTheMappingOneCacheTablePerThreadAndTheGhosts) {
  // 8 mapping + 36 per thread + 8 ghost density + 32 ghost moments (double build).
  EXPECT_EQ(coupling_bytes_per_node(1), 84.0);
  EXPECT_EQ(coupling_bytes_per_node(4), 84.0 + 3 * 36.0);
  EXPECT_EQ(coupling_bytes_per_node(0), coupling_bytes_per_node(1));
}
