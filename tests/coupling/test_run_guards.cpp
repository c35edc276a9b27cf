// The run-time guards (coupling/diagnostics/run_guards.h) on one rank: a particle faster
// than half a cell per fluid step stops the run with its message here, a NaN node likewise
// with the node and the nearest particle; a wall followed or searched (bonds.h).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "cases/serial_flow.h"
#include "coupling/diagnostics/bonds.h"
#include "coupling/diagnostics/run_guards.h"
#include "lbm/stability.h"

using namespace coupling;

TEST(RunGuards, AParticleFasterThanHalfACellPerStepStopsTheRun) {
  ParticleSet particles;
  particles.add(4, {2.0, 2.0, 2.0}, {0.3, 0.0, 0.0}, 1.0);
  GuardVerdict verdict = particle_speed_guard(particles.view(), 700, lbm::Communicator());
  EXPECT_FALSE(verdict.stop);
  EXPECT_DOUBLE_EQ(verdict.value, 0.3);
  particles.set_velocity(0, {0.0, 0.6, 0.0});
  verdict = particle_speed_guard(particles.view(), 700, lbm::Communicator());
  EXPECT_TRUE(verdict.stop);
  EXPECT_TRUE(verdict.found_here);
  EXPECT_DOUBLE_EQ(verdict.value, 0.6);
  EXPECT_EQ(verdict.message.find("particle 4 moves 0.6 cells per fluid step at DEM step 700"), 0u)
      << verdict.message;
}

TEST(RunGuards, ANanNodeStopsTheRunNamingTheStepsTheNodeAndTheNearestParticle) {
  auto solver = cases::make_solver({8, 8, 8}, {true, true, true});
  ParticleSet particles;
  particles.add(9, {2.0, 2.0, 2.0}, {0.0, 0.0, 0.0}, 1.0);
  EXPECT_FALSE(fluid_state_guard(*solver, particles.view(), 100, 1).stop);
  solver->populations().at(1, solver->layout().cell(3, 2, 2)) = std::nan("");
  const GuardVerdict verdict = fluid_state_guard(*solver, particles.view(), 300, 3);
  EXPECT_TRUE(verdict.stop);
  EXPECT_TRUE(verdict.found_here);
  EXPECT_EQ(verdict.message.find("fluid became unstable at DEM step 300 (fluid step 3), node (3,2,2)"), 0u)
      << verdict.message;
  EXPECT_NE(verdict.message.find("nearest particle 9"), std::string::npos) << verdict.message;
}

TEST(Bonds, AParticleTouchesTheWallFromItsFollowedNearestWallOrBySearch) {
  lbm::VoxelGeometry g({8, 8, 8});
  for (int j = 0; j < 8; ++j)
    for (int k = 0; k < 8; ++k) g.set_solid(0, j, k, true);  // the plane x = 0
  const contact::VoxelSurface surface(g);
  std::vector<contact::SurfacePoint> scratch;
  NearestWall followed;
  followed.known = true;
  followed.distance = 1.02;  // within 1.03 R of a particle of radius 1
  EXPECT_TRUE(touches_wall(&followed, surface, {6.0, 4.0, 4.0}, 1.0, scratch));  // the followed one decides
  followed.known = false;
  EXPECT_FALSE(touches_wall(&followed, surface, {1.5, 4.0, 4.0}, 1.0, scratch));
  EXPECT_TRUE(touches_wall(nullptr, surface, {1.0, 4.0, 4.0}, 1.0, scratch));  // searched
  EXPECT_FALSE(touches_wall(nullptr, surface, {6.0, 4.0, 4.0}, 1.0, scratch));
}

// A flow beyond the lattice's accuracy is named with its Mach number, step and place and what
// lowers it; at or below the bound nothing is said (a NaN, which the fluid guard reports, neither).
TEST(RunGuards, FastFlowWarningAboveTheAccurateMachNumber) {
  FastFlowSite site;
  site.node = {70, 12, 30};
  site.speed = 0.57;
  site.wall_links = 5;
  site.nearest = {ParticleProbe{93, 0.02}, ParticleProbe{12, 0.61}};
  EXPECT_EQ(coupling::fast_flow_warning(0.29, 10, site), "");
  EXPECT_EQ(coupling::fast_flow_warning(coupling::kAccurateLatticeMach, 10, site), "");
  EXPECT_EQ(coupling::fast_flow_warning(std::nan(""), 10, site), "");
  const std::string warning = coupling::fast_flow_warning(0.99, 12345, site);
  for (const char* words : {"Mach number reached 0.99", "fluid step 12345", "node (70,12,30), speed 0.57",
                            "0.02 cells from particle 93, 0.61 cells from particle 12",
                            "5 of its links on the wall", "u_lattice", "finer lattice"})
    EXPECT_NE(warning.find(words), std::string::npos) << words << " in: " << warning;
}

// The fast node is found over the whole lattice, with the two particle surfaces nearest to it
// and its links on the static wall (the plane z = 0 below it).
TEST(RunGuards, TheFastestFlowIsLocatedWithItsNearestSurfaces) {
  lbm::VoxelGeometry g({8, 8, 8});
  for (int i = 0; i < 8; ++i)
    for (int j = 0; j < 8; ++j) g.set_solid(i, j, 0, true);
  lbm::FluidParameters p;
  p.periodic = {true, true, true};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  solver.initialise_equilibrium(1.0, {0.01, 0.0, 0.0});
  solver.populations().at(1, solver.layout().cell(3, 4, 1)) += 0.3;  // c_1 = (1, 0, 0)
  ParticleSet particles;
  particles.add(7, {6.0, 4.0, 1.0}, {0.0, 0.0, 0.0}, 2.0);  // its surface 1.0 from the node
  particles.add(9, {1.0, 4.0, 1.0}, {0.0, 0.0, 0.0}, 1.5);  // 0.5
  particles.add(4, {3.0, 4.0, 6.0}, {0.0, 0.0, 0.0}, 1.0);  // 4.0
  const FastFlowSite site = locate_fastest_flow(solver, particles.view());
  EXPECT_EQ(site.node, (std::array<int, 3>{3, 4, 1}));
  EXPECT_DOUBLE_EQ(site.speed, lbm::max_speed(solver));
  EXPECT_GT(site.speed, 0.2);
  EXPECT_EQ(site.wall_links, 5);  // the five directions with c_z = -1
  EXPECT_EQ(site.nearest[0].id, 9);
  EXPECT_DOUBLE_EQ(site.nearest[0].value, 0.5);
  EXPECT_EQ(site.nearest[1].id, 7);
  EXPECT_DOUBLE_EQ(site.nearest[1].value, 1.0);
}
