// The pore monitor (coupling/diagnostics/pore_monitor.h) and its building blocks: bonds, the
// guards' particle probes, values in host units, restore.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "coupling/diagnostics/bonds.h"
#include "coupling/diagnostics/particle_probes.h"
#include "coupling/diagnostics/pore_monitor.h"
#include "lbm/decomposition.h"
#include "lbm/fluid_solver.h"
#include "lbm/pore_scene.h"

using namespace coupling;

TEST(Bonds, CohesiveBondWithinThreePercentOfTheRadiiSum) {
  ParticleSet set;
  set.add(1, {0.0, 0.0, 0.0}, {0, 0, 0}, 1.0);
  set.add(2, {2.05, 0.0, 0.0}, {0, 0, 0}, 1.0);  // gap 0.05 <= 0.06: bonded
  set.add(3, {0.0, 2.07, 0.0}, {0, 0, 0}, 1.0);  // gap 0.07 > 0.06
  std::vector<char> bonded(3, 0);
  mark_cohesive_bonds(set.view(), {{0, 2}}, bonded);
  EXPECT_EQ(bonded, (std::vector<char>{0, 0, 0}));
  mark_cohesive_bonds(set.view(), {{0, 1}, {0, 2}}, bonded);
  EXPECT_EQ(bonded, (std::vector<char>{1, 1, 0}));
  EXPECT_TRUE(within_adhesion_range(2.06, 2.0));
  EXPECT_FALSE(within_adhesion_range(2.07, 2.0));
}

TEST(ParticleProbes, FastestCountsNaNAsInfiniteAndNearestSurfaceWrapsPeriodically) {
  ParticleSet set;
  set.add(7, {1.0, 1.0, 1.0}, {0.1, 0.0, 0.0}, 1.0);
  set.add(8, {9.0, 1.0, 1.0}, {0.0, 0.2, 0.0}, 2.0);
  EXPECT_EQ(fastest_particle(set.view()).id, 8);
  EXPECT_NEAR(fastest_particle(set.view()).value, 0.2, 1e-15);
  set.set_velocity(0, {std::nan(""), 0.0, 0.0});
  EXPECT_EQ(fastest_particle(set.view()).id, 7);
  EXPECT_TRUE(std::isinf(fastest_particle(set.view()).value));
  PeriodicBox box;
  box.length = {10.0, 10.0, 10.0};
  box.periodic = {true, false, false};
  // Node at x = 0.2: particle 8 is 1.2 away through the periodic face, its surface -0.8.
  const ParticleProbe nearest = nearest_particle_surface(set.view(), box, {0.2, 1.0, 1.0});
  EXPECT_EQ(nearest.id, 8);
  EXPECT_NEAR(nearest.value, -0.8, 1e-12);
  EXPECT_NE(instability_cause(nearest).find("gap of less than a cell"), std::string::npos);
}

TEST(PoreMonitor, DepositsAndCrossingsInHostUnits) {
  // inlet, free, pore, outlet lengths, width, pore diameter (cells)
  lbm::PoreSceneSpec spec{4, 4, 6, 4, 12, 8.0};
  PoreMonitorSetup setup = pore_scene_monitor(spec);
  EXPECT_DOUBLE_EQ(setup.inlet_plane, 3.5);
  EXPECT_DOUBLE_EQ(setup.outlet_plane, 13.5);
  EXPECT_EQ(setup.flow_length, 18);
  EXPECT_DOUBLE_EQ(setup.pore.start, 3.5);  // from the end of the inlet region, by default
  EXPECT_DOUBLE_EQ(pore_scene_monitor(spec, DepositRegion::kPore).pore.start, 7.5);  // the pore alone
  EXPECT_DOUBLE_EQ(pore_scene_monitor(spec, DepositRegion::kPore).pore.end, setup.pore.end);
  UnitInputs in;
  in.dx = 2.0;  // volumes scale with 8, lengths with 2
  in.dt_dem = 0.01;
  in.n_dem = 100;
  in.nu = 1.0 / 6.0 * 4.0;  // tau = 1 at dt_lbm = 1, dx = 2
  const UnitConversion units(in);
  PoreMonitor monitor(setup, units);
  ParticleSet set;
  set.add(1, {3.0, 5.5, 5.5}, {0, 0, 0}, 1.0);   // upstream of the inlet plane
  set.add(2, {10.0, 5.5, 5.5}, {0, 0, 0}, 1.5);  // in the pore, at rest
  const lbm::Communicator serial;
  // Particle 2 (deposited) touches the wall; the wall holds them with -0.5 along the flow,
  // of which -0.375 on particle 2; the fluid pushes particle 1 with 0.25 and 2 with 0.5;
  // every force on them sums to 0.0625 and 0.03125.
  const PoreMonitor::ParticleLoads loads{0.75, -0.5, {0.25, 0.5}, {-0.125, -0.375}, {0.0625, 0.03125}};
  monitor.record_particles(set.view(), {1, 1}, {0, 1}, loads, serial);
  const double V = 4.0 / 3.0 * M_PI * 1.5 * 1.5 * 1.5;
  EXPECT_NEAR(monitor.values()[PoreMonitor::kDepositedVolume], V * 8.0, 1e-12);
  EXPECT_EQ(monitor.values()[PoreMonitor::kDepositedCount], 1.0);
  EXPECT_NEAR(monitor.values()[PoreMonitor::kDepositedLength], V / (M_PI * 16.0) * 2.0, 1e-12);
  EXPECT_EQ(monitor.values()[PoreMonitor::kHydroForceX], 0.75);
  EXPECT_EQ(monitor.values()[PoreMonitor::kWallForceX], -0.5);
  EXPECT_EQ(monitor.values()[PoreMonitor::kDepositedOnWall], 1.0);
  // The deposit's own loads: particle 2's alone, not the totals over both.
  EXPECT_EQ(monitor.values()[PoreMonitor::kDepositFluidForceX], 0.5);
  EXPECT_EQ(monitor.values()[PoreMonitor::kDepositWallForceX], -0.375);
  EXPECT_EQ(monitor.values()[PoreMonitor::kDepositTotalForceX], 0.03125);
  // The count under the scaled speed thresholds: particle 2 is at rest, under all of them.
  for (std::size_t i = 0; i < kDepositSpeedLadder.size(); ++i)
    EXPECT_EQ(monitor.values()[PoreMonitor::kDepositedCountScaledSpeed + i], 1.0);
  set.set_position(0, {4.0, 5.5, 5.5});  // crosses the inlet plane downstream
  monitor.record_particles(set.view(), {1, 1}, {0, 0}, {}, serial);
  EXPECT_EQ(monitor.values()[PoreMonitor::kParticlesIn], 1.0);
  EXPECT_EQ(monitor.values()[PoreMonitor::kDepositWallForceX], 0.0);  // no per-particle loads given
  EXPECT_NEAR(monitor.values()[PoreMonitor::kParticlesInVolume], 4.0 / 3.0 * M_PI * 8.0, 1e-12);

  // No burst yet: every entry of the burst table reads 0, inside the rows or not.
  EXPECT_EQ(monitor.burst_value(0, 0), 0.0);
  EXPECT_EQ(monitor.burst_value(-1, 3), 0.0);
  EXPECT_EQ(monitor.burst_value(2, BurstRecord::kColumns), 0.0);

  monitor.record_particles(set.view(), {1, 1}, {0, 1}, loads, serial);
  PoreMonitor resumed(setup, units);
  resumed.restore(monitor.state());
  EXPECT_EQ(resumed.values(), monitor.values());
  // States written by earlier versions, which recorded only the first kWallForceX values
  // (before the wall's hold), kPressureLossAcrossPore (before the pressure across the pore
  // and the speed ladder), kDepositFluidForceX (before the deposit's own loads) or
  // kDepositTotalForceX (before every force on the deposit), restore with the rest 0.
  for (const int written : {int(PoreMonitor::kWallForceX), int(PoreMonitor::kPressureLossAcrossPore),
                            int(PoreMonitor::kDepositFluidForceX), int(PoreMonitor::kDepositTotalForceX)}) {
    std::vector<double> earlier = monitor.state();
    earlier.erase(earlier.begin() + 1 + written, earlier.begin() + 1 + PoreMonitor::kCount);
    earlier[0] = written;
    PoreMonitor upgraded(setup, units);
    upgraded.restore(earlier);
    std::vector<double> expected = monitor.values();
    ASSERT_NE(expected[PoreMonitor::kDepositTotalForceX], 0.0);
    std::fill(expected.begin() + written, expected.end(), 0.0);
    EXPECT_EQ(upgraded.values(), expected) << written << " values written";
  }
  // A state of another version (its own number of values first) is refused, not misread.
  std::vector<double> foreign = monitor.state();
  foreign[0] = PoreMonitor::kCount - 4;
  EXPECT_THROW(resumed.restore(foreign), std::invalid_argument);
}

// A closed box (velocity 0, solid end layers): the pore is the narrowest section with fluid,
// and a geometry without one gives L_dep = 0, not 0/0.
TEST(PoreMonitor, ClosedBoxGivesAFinitePoreDiameterAndDepositLength) {
  lbm::VoxelGeometry box({6, 4, 4});
  for (int k = 0; k < 4; ++k)
    for (int j = 0; j < 4; ++j) {
      box.set_solid(0, j, k, true);
      box.set_solid(5, j, k, true);
    }
  PoreMonitorSetup setup = voxel_geometry_monitor(box);
  EXPECT_DOUBLE_EQ(setup.pore_diameter, std::sqrt(4.0 * 16.0 / M_PI));  // was 0 (the end layer)
  setup.pore_diameter = 0.0;  // as for a geometry with no open section
  UnitInputs in;
  const UnitConversion units(in);
  PoreMonitor monitor(setup, units);
  ParticleSet set;
  set.add(1, {2.5, 1.5, 1.5}, {0, 0, 0}, 1.0);
  monitor.record_particles(set.view(), {1}, {0}, {}, lbm::Communicator());
  EXPECT_EQ(monitor.values()[PoreMonitor::kDepositedLength], 0.0);
  for (double v : monitor.values()) EXPECT_TRUE(std::isfinite(v));
}

// A fall counts as an erosive burst when a deposit was there to tear off, at the peak or over
// the window before it: a deposit that slid before the peak (counted 0 there) is one, a fall
// with no deposit at all is not (restored from a detector's state, as after a restart).
TEST(PoreMonitor, ABurstWhoseDepositSlidBeforeThePeakIsErosive) {
  const auto monitor_with = [](long long deposit) {
    BurstDetector detector;
    for (long long t = 0; t < 4500; ++t) {
      PressureSample s;
      s.fluid_step = t;
      s.pressure_loss = t <= 3000 ? 0.01 + 1e-5 * t : 0.02;  // a fall of half the peak after 3000
      s.deposited_count = t < 2950 ? deposit : 0;
      detector.add(s);
    }
    EXPECT_EQ(detector.bursts().size(), 1u);
    PoreMonitor monitor(pore_scene_monitor(lbm::PoreSceneSpec{4, 4, 6, 4, 12, 8.0}), UnitConversion(UnitInputs{}));
    std::vector<double> state(1 + PoreMonitor::kCount + 1, 0.0);
    state[0] = PoreMonitor::kCount;
    const auto detector_state = detector.state();
    state.insert(state.end(), detector_state.begin(), detector_state.end());
    monitor.restore(state);
    return monitor.bursts().size();
  };
  EXPECT_EQ(monitor_with(12), 1u);
  EXPECT_EQ(monitor_with(0), 0u);
}

// The paper measures the pressure loss "on both sides of the pore": between the node planes
// next to its ends. In a particle-free pressure-driven flow through the pore scene the wide
// regions before and after the constriction, at a ninth of its speed, lose almost nothing:
// the loss across the pore is that between the open faces within 2 % (a particle queue in
// the free region, which the faces' loss includes, is what tells the two apart).
TEST(PoreMonitor, PressureLossAcrossThePoreIsMostOfTheLossBetweenTheFaces) {
  lbm::PoreSceneSpec spec{4, 4, 8, 4, 12, 6.0};
  const PoreMonitorSetup setup = pore_scene_monitor(spec);
  const lbm::PoreSceneRegions r = lbm::regions_of(spec);
  EXPECT_EQ(setup.upstream_plane, r.pore_begin - 1);
  EXPECT_EQ(setup.downstream_plane, r.pore_end);
  EXPECT_EQ(voxel_geometry_monitor(lbm::make_pore_scene(spec)).upstream_plane, -1);  // no planes known
  const lbm::VoxelGeometry geometry = lbm::make_pore_scene(spec);
  lbm::FluidParameters parameters;
  parameters.periodic = {false, true, true};
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kPressureLoss;
  drive.pressure_loss = 0.003;
  lbm::Box box;
  box.hi = geometry.dims();
  lbm::FluidSolver solver(geometry, parameters, drive, lbm::Decomposition::serial(box, parameters.periodic));
  UnitInputs in;
  in.dx = 1.0;
  in.dt_dem = 0.01;
  in.n_dem = 100;
  in.nu = 1.0 / 6.0;
  const UnitConversion units(in);
  PoreMonitor monitor(setup, units);
  EXPECT_EQ(monitor.value(PoreMonitor::kPressureLossAcrossPore, solver, 0), 0.0);  // fluid at rest
  for (int step = 0; step < 400; ++step) solver.step();
  monitor.fluid_changed();
  const double across = monitor.value(PoreMonitor::kPressureLossAcrossPore, solver, 400);
  const double faces = pressure_loss_in_outlet_units(solver);
  EXPECT_NEAR(faces, 0.003 / (1.0 / 3.0), 1e-9);
  EXPECT_NEAR(across, faces, 0.02 * faces);
}
