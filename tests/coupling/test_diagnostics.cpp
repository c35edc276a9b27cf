// Pore diagnostics: deposited volume and length, particle plane crossings.
#include <gtest/gtest.h>

#include "cases/serial_flow.h"
#include "coupling/diagnostics/pore_diagnostics.h"
#include "coupling/sphere_coupling.h"

using namespace coupling;

TEST(Diagnostics, DepositedVolumeCountsBondedSlowParticlesInThePore) {
  ParticleSet p;
  p.add(1, {10, 5, 5}, {0, 0, 0}, 2.0);      // deposited
  p.add(2, {10, 5, 5}, {0.01, 0, 0}, 2.0);   // too fast
  p.add(3, {10, 9.5, 5}, {0, 0, 0}, 2.0);    // outside the pore radius
  p.add(4, {30, 5, 5}, {0, 0, 0}, 2.0);      // beyond the pore's end
  p.add(5, {12, 6, 4}, {0, 0, 0}, 2.0);      // not bonded
  const std::vector<char> bonded{1, 1, 1, 1, 0};
  PoreRegion pore;
  pore.axis = 0;
  pore.start = 5;
  pore.end = 20;
  pore.centre = {5, 5};
  pore.diameter = 8;
  const Deposition d = deposited(p.view(), bonded, pore, DepositionCriteria{}, lbm::Communicator{});
  const double v = 4.0 / 3.0 * cases::kPi * 8.0;
  EXPECT_EQ(d.count, 1);
  EXPECT_NEAR(d.volume, v, 1e-12);
  EXPECT_NEAR(d.length, v / (cases::kPi * 16.0), 1e-12);
  EXPECT_EQ(d.on_wall, 0);  // no wall flags given
  // Of the deposited particles, those flagged as touching the wall; the others' flags
  // (too fast, outside, unbonded) do not count.
  p.add(6, {8, 5, 5}, {0, 0, 0}, 2.0);  // deposited too, not on the wall
  const std::vector<char> bonded6{1, 1, 1, 1, 0, 1}, on_wall{1, 1, 1, 1, 1, 0};
  const Deposition w = deposited(p.view(), bonded6, pore, DepositionCriteria{}, lbm::Communicator{}, &on_wall);
  EXPECT_EQ(w.count, 2);
  EXPECT_EQ(w.on_wall, 1);
  EXPECT_EQ(w.fluid_force, 0.0);  // no forces given
  // The loads on the deposited particles (1 and 6) alone, not on the others.
  const std::vector<double> fluid{1.0, 2.0, 4.0, 8.0, 16.0, 32.0}, wall{-0.5, -1.0, -2.0, -4.0, -8.0, -0.25},
      total{0.125, 3.0, 5.0, 7.0, 9.0, -0.0625};
  const Deposition f = deposited(p.view(), bonded6, pore, DepositionCriteria{}, lbm::Communicator{}, &on_wall,
                                 {&fluid, &wall, &total});
  EXPECT_EQ(f.fluid_force, 33.0);
  EXPECT_EQ(f.wall_force, -0.75);
  EXPECT_EQ(f.total_force, 0.0625);
  EXPECT_EQ(w.total_force, 0.0);
  EXPECT_EQ(f.count, w.count);
}

TEST(Diagnostics, PlaneCrossingsAreCountedWithDirection) {
  ParticleSet p;
  p.add(1, {9.5, 0, 0}, {0, 0, 0}, 1.0);
  p.add(2, {10.5, 0, 0}, {0, 0, 0}, 1.0);
  p.add(3, {3.0, 0, 0}, {0, 0, 0}, 1.0);
  PlaneCrossingCounter counter(0, 10.0);
  EXPECT_EQ(counter.update(p.view(), 40.0, lbm::Communicator{}).count, 0);  // records only
  p.set_position(0, {10.2, 0, 0});  // forward
  p.set_position(2, {39.0, 0, 0});  // periodic wrap, ignored
  auto c = counter.update(p.view(), 40.0, lbm::Communicator{});
  EXPECT_EQ(c.count, 1);
  EXPECT_NEAR(c.volume, 4.0 / 3.0 * cases::kPi, 1e-12);
  p.set_position(0, {9.0, 0, 0});   // back
  p.set_position(1, {9.9, 0, 0});   // back
  EXPECT_EQ(counter.update(p.view(), 40.0, lbm::Communicator{}).count, -2);
}

// The paper's pressure unit: after one step the on-site faces hold their imposed densities
// exactly, so P / P_out = (rho_in - rho_out) / rho_out, here with rho_out = 1.2 to tell a
// division by rho_out from one by rho0 = 1.
TEST(Diagnostics, PressureLossInUnitsOfTheOutletPressure) {
  lbm::VoxelGeometry geometry({12, 4, 4});
  lbm::FluidParameters parameters;
  parameters.periodic = {false, true, true};
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kPressureLoss;
  drive.pressure_loss = 0.05;
  drive.outlet_density = 1.2;
  lbm::Box box;
  box.hi = geometry.dims();
  lbm::FluidSolver solver(geometry, parameters, drive,
                          lbm::Decomposition::serial(box, parameters.periodic));
  solver.step();
  EXPECT_NEAR(outlet_pressure(solver), 1.2 / 3.0, 1e-15);
  EXPECT_NEAR(coupling::pressure_loss(solver), 0.05, 1e-12);
  EXPECT_NEAR(pressure_loss_in_outlet_units(solver), 0.05 / 0.4, 1e-12);  // = 3 dp / rho_out
}
