// Velocity inlet and pressure outlet (Hecht-Harting), constant pressure loss mode, and
// flux conservation through the paper's pore constriction.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <memory>

#include "cases/scoped_threads.h"
#include "cases/serial_flow.h"
#include "lbm/d3q19.h"
#include "lbm/macroscopic.h"
#include "lbm/node_type.h"
#include "lbm/pore_scene.h"

namespace {
// The pore scene, periodic across the flow, driven by an inlet velocity (lattice units).
std::unique_ptr<lbm::FluidSolver> velocity_driven_pore(const lbm::PoreSceneSpec& spec, double tau,
                                                       double inlet_velocity) {
  const auto g = lbm::make_pore_scene(spec);
  lbm::FluidParameters p;
  p.tau = tau;
  p.periodic = {false, true, true};
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kInletVelocity;
  drive.inlet_velocity = inlet_velocity;
  return std::make_unique<lbm::FluidSolver>(g, p, drive, cases::serial_decomposition(g, p.periodic));
}
}  // namespace

TEST(OpenBoundary, FluxIsConservedThroughThePoreConstriction) {
  // inlet, free, pore, outlet lengths, width, pore diameter (cells)
  const lbm::PoreSceneSpec spec{6, 6, 8, 8, 16, 10};
  const auto owned = velocity_driven_pore(spec, 1.0, 0.005);
  lbm::FluidSolver& solver = *owned;
  const lbm::FlowDrive& drive = solver.drive();
  cases::run_to_steady(solver, 1e-8, 40000, 200);
  // The inlet imposes u_in on every node: inflow of mass = rho_in u_in A.
  const double rho_in = lbm::plane_mean_pressure(solver, 0, 0) * 3.0;
  const double inflow = rho_in * drive.inlet_velocity * spec.width * spec.width;
  const auto r = lbm::regions_of(spec);
  for (int x : {0, r.free_end - 1, (r.pore_begin + r.pore_end) / 2, r.outlet_end - 1}) {
    const double flux = lbm::plane_flux(solver, 0, x);
    std::printf("plane x=%d: flux %.8f (inflow %.8f)\n", x, flux, inflow);
    // Mass flux is conserved plane to plane at steady state (to the convergence level).
    EXPECT_NEAR(flux / inflow, 1.0, 1e-5) << "plane " << x;
  }
  EXPECT_GT(lbm::pressure_loss(solver), 0.0);
}

// The pressure loss between the open faces is taken from the densities the open boundary
// imposed in the last step (the collision conserves mass): the same as reading the two planes
// after the step, to round-off, in a flow still far from steady; read from the planes where
// the populations changed since (here a reset of the time step, as a checkpoint read does).
TEST(OpenBoundary, ThePressureLossFromTheFacesEqualsThePlanesRead) {
  const lbm::PoreSceneSpec spec{6, 6, 8, 8, 16, 10};
  const auto owned = velocity_driven_pore(spec, 1.0, 0.02);
  lbm::FluidSolver& solver = *owned;
  for (int step = 0; step < 150; ++step) solver.step();
  const int last = solver.decomposition().global.hi[0] - 1;
  const double read = lbm::plane_mean_pressure(solver, 0, 0) - lbm::plane_mean_pressure(solver, 0, last);
  const double from_faces = lbm::pressure_loss(solver);
  std::printf("pressure loss after 150 steps: %.17g from the faces, %.17g read from the planes\n", from_faces, read);
  EXPECT_GT(read, 1e-4);
  EXPECT_NEAR(from_faces, read, 1e-14 * std::abs(read) + 1e-17);
  solver.set_time_step(solver.time_step());  // the faces' densities no longer count
  EXPECT_EQ(lbm::pressure_loss(solver), read);
}

namespace {
// Plane channel of H nodes between walls normal to y, pressure loss along x. Returns the
// flux relative to the analytical Q = G H^3 / (12 mu) per unit depth.
double pressure_driven_channel_flux_ratio(int H) {
  const int nx = 40;
  lbm::VoxelGeometry g({nx, H, 2});
  lbm::FluidParameters p;
  p.tau = 1.0;
  p.periodic = {false, false, true};
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kPressureLoss;
  drive.pressure_loss = 1e-4;
  lbm::FluidSolver solver(g, p, drive, cases::serial_decomposition(g, p.periodic));
  cases::run_to_steady(solver, 1e-10, 100000, 500);
  EXPECT_NEAR(lbm::pressure_loss(solver) / drive.pressure_loss, 1.0, 1e-6);
  // G = dp / (nx - 1): the boundary nodes carry the imposed densities.
  const double mu = lbm::TrtParameters::viscosity(1.0);
  const double expected = drive.pressure_loss / (nx - 1) * H * H * H / (12.0 * mu) * 2;  // depth 2
  return lbm::plane_flux(solver, 0, nx / 2) / expected;
}
}  // namespace

TEST(OpenBoundary, ImposedPressureLossDrivesPoiseuilleFlux) {
  // Unlike a body force, a pressure gradient along a bounce-back wall leaves a slip of
  // O(G) in lattice units, whatever Lambda: a relative flux error O(1/H^2).
  const double r9 = pressure_driven_channel_flux_ratio(9);
  const double r17 = pressure_driven_channel_flux_ratio(17);
  std::printf("pressure-driven channel: flux / analytic H=9 %.5f, H=17 %.5f\n", r9, r17);
  EXPECT_NEAR(r9, 1.0, 0.04);
  EXPECT_NEAR(r17, 1.0, 0.012);
  EXPECT_GT((1.0 - r9) / (1.0 - r17), 3.0);  // second order: (17/9)^2 = 3.6
}

TEST(OpenBoundary, DriveTooStrongIsRefusedWithItsRange) {
  lbm::VoxelGeometry g({8, 4, 4});
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kInletVelocity;
  drive.inlet_velocity = 0.5;
  try {
    lbm::FluidSolver solver(g, lbm::FluidParameters{}, drive,
                            cases::serial_decomposition(g, {false, true, true}));
    FAIL() << "inlet velocity 0.5 accepted";
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inlet velocity"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("(-0.3, 0.3)"), std::string::npos);
  }
}

#include "lbm/d3q19.h"
#include "lbm/stability.h"

TEST(Stability, NanAndRunawayNodesAreReportedWithTheirPlace) {
  lbm::VoxelGeometry g({6, 5, 4});
  lbm::FluidParameters p;
  p.periodic = {true, true, true};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  EXPECT_FALSE(lbm::check_fluid_state(solver, 0.3).found);
  solver.populations().at(1, solver.layout().cell(3, 2, 1)) = std::nan("");
  const auto problem = lbm::check_fluid_state(solver, 0.3);
  ASSERT_TRUE(problem.found);
  EXPECT_EQ(problem.node, (std::array<int, 3>{3, 2, 1}));
  EXPECT_NE(problem.describe().find("node (3,2,1)"), std::string::npos);
  solver.initialise_equilibrium(1.0, {0.4, 0.0, 0.0});
  EXPECT_TRUE(lbm::check_fluid_state(solver, 0.3).found);
  EXPECT_NEAR(lbm::max_speed(solver), 0.4, 1e-12);
}

// The scan accepts most nodes from its one pass over the arrays and judges the rest node by
// node: a speed a hair below the limit passes, a hair above is reported, and so is an
// infinite density, exactly where the node-by-node scan drew the line.
TEST(Stability, TheLimitIsDrawnExactlyAtTheGivenSpeed) {
  lbm::VoxelGeometry g({6, 5, 4});
  lbm::FluidParameters p;
  p.periodic = {true, true, true};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  solver.initialise_equilibrium(1.0, {0.2, 0.0, 0.0});
  const double speed = lbm::max_speed(solver);
  EXPECT_FALSE(lbm::check_fluid_state(solver, speed).found);
  EXPECT_FALSE(lbm::check_fluid_state(solver, std::nextafter(speed, 1.0)).found);
  const auto above = lbm::check_fluid_state(solver, std::nextafter(speed, 0.0));
  ASSERT_TRUE(above.found);
  EXPECT_EQ(above.node, (std::array<int, 3>{0, 0, 0}));
  EXPECT_EQ(above.speed, speed);
  solver.populations().at(0, solver.layout().cell(2, 3, 2)) = HUGE_VAL;
  const auto infinite = lbm::check_fluid_state(solver, 0.3);
  ASSERT_TRUE(infinite.found);
  EXPECT_EQ(infinite.node, (std::array<int, 3>{2, 3, 2}));
}

// The scan is split over the OpenMP threads by planes: with a bad node in the first and in
// the last plane, every thread count reports the first in scan order (k, j, i), as one
// thread does.
TEST(Stability, TheFirstBadNodeInScanOrderIsReportedOnAnyNumberOfThreads) {
  lbm::VoxelGeometry g({6, 5, 8});
  lbm::FluidParameters p;
  p.periodic = {true, true, true};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  solver.populations().at(2, solver.layout().cell(4, 3, 7)) = std::nan("");
  solver.populations().at(5, solver.layout().cell(1, 4, 0)) = -2.0;  // negative density
  solver.populations().at(1, solver.layout().cell(0, 1, 7)) = std::nan("");
  cases::ScopedThreads threads_of_test(1);
  for (int threads = 1; threads <= cases::ScopedThreads::most(4); ++threads) {
    threads_of_test.set(threads);
    const auto problem = lbm::check_fluid_state(solver, 0.3);
    ASSERT_TRUE(problem.found) << threads;
    EXPECT_EQ(problem.node, (std::array<int, 3>{1, 4, 0})) << threads << " threads";
    EXPECT_LT(problem.density, 0.0);
  }
}

// The masses booked through the open faces (FluidSolver::open_face_mass, the populations
// that crossed them) account for every change of the fluid mass, also while the flow starts
// up and the density field changes (where rho u sampled at the end layers is off by about
// half of their mass change), for both drives.
TEST(OpenBoundary, FaceMassesAccountForTheMassChangeExactly) {
  // inlet, free, pore, outlet lengths, width, pore diameter (cells)
  lbm::PoreSceneSpec spec{6, 2, 8, 6, 12, 7};
  const auto g = lbm::make_pore_scene(spec);
  lbm::FluidParameters p;
  p.tau = 0.8;
  p.periodic = {false, true, true};
  for (auto kind : {lbm::FlowDrive::kInletVelocity, lbm::FlowDrive::kPressureLoss}) {
    lbm::FlowDrive drive;
    drive.kind = kind;
    drive.inlet_velocity = 0.01;
    drive.pressure_loss = 0.003;
    lbm::FluidSolver solver(g, p, drive, cases::serial_decomposition(g, p.periodic));
    const double m0 = lbm::total_mass(solver);
    double booked = 0.0, through = 0.0;
    for (int s = 0; s < 500; ++s) {
      solver.step();
      booked += solver.open_face_mass(0) + solver.open_face_mass(1);
      through += solver.open_face_mass(0);
    }
    const double change = lbm::total_mass(solver) - m0;
    std::printf("drive %d: mass in %.6f, change %.6f, booked %.6f\n", int(kind), through, change, booked);
    EXPECT_GT(through, 10.0);
    EXPECT_GT(std::abs(change), 1e-3);  // the start-up changes the mass: a real test
    EXPECT_NEAR(change, booked, 1e-10 * through);
  }
}

namespace {
struct StepOutcome {
  lbm::PopulationField::Storage populations;
  double pressure_loss = 0.0;          // from the open faces' densities
  double read_pressure_loss = 0.0;     // the planes read (the faces' densities disowned)
  double reference_pressure_loss = 0.0;
};

// The mean pressure of global x-plane `x` as the obvious loop gives it: every fluid node in
// plane order (y innermost), one running sum.
double plane_pressure_by_loop(const lbm::FluidSolver& solver, int x) {
  const lbm::BlockLayout& g = solver.layout();
  double sum = 0.0, count = 0.0;
  for (int k = 0; k < g.size(2); ++k)
    for (int j = 0; j < g.size(1); ++j) {
      const std::size_t cell = g.cell(x, j, k);
      if (solver.node_types()[cell] != lbm::kFluid) continue;
      sum += solver.density(cell);
      count += 1.0;
    }
  return lbm::D3Q19::cs2 * sum / count;
}

// Steps of the pore scene, a plane larger than the open faces' and the pressure's split
// threshold (24 x 24 nodes), ghost planes of the periodic axes above the copies' threshold,
// more static wall links than their split threshold, on `threads` OpenMP threads.
StepOutcome pore_steps(int threads) {
  const cases::ScopedThreads threads_of_run(threads);
  const lbm::PoreSceneSpec spec{8, 8, 24, 24, 24, 15};
  const auto solver = velocity_driven_pore(spec, 0.8, 0.02);
  for (int s = 0; s < 30; ++s) solver->step();
  StepOutcome out;
  out.populations = solver->populations().raw();
  out.pressure_loss = lbm::pressure_loss(*solver);
  out.reference_pressure_loss = plane_pressure_by_loop(*solver, 0) -
                                plane_pressure_by_loop(*solver, solver->layout().size(0) - 1);
  solver->set_time_step(solver->time_step());  // as a checkpoint read: the planes are read
  out.read_pressure_loss = lbm::pressure_loss(*solver);
  return out;
}
}  // namespace

// The fluid step's stages split over OpenMP threads (static walls, open faces, periodic ghost
// copies, collide-stream) and the pressure loss (the faces' densities set on the threads,
// summed on one; or the planes read, their densities on the threads, their sum on one) give
// the one-thread result bit for bit; read, the pressure loss is the plain loop's sum, and
// from the faces the same to round-off.
TEST(OpenBoundary, TwoThreadsGiveTheOneThreadStepAndPressureLossBitForBit) {
  const StepOutcome one = pore_steps(1), two = pore_steps(2);
  ASSERT_EQ(one.populations.size(), two.populations.size());
  EXPECT_EQ(0, std::memcmp(one.populations.data(), two.populations.data(),
                           one.populations.size() * sizeof(lbm::Real)));
  EXPECT_GT(one.pressure_loss, 0.0);
  EXPECT_EQ(one.pressure_loss, two.pressure_loss);
  EXPECT_EQ(one.read_pressure_loss, two.read_pressure_loss);
  EXPECT_EQ(one.read_pressure_loss, one.reference_pressure_loss);
  EXPECT_NEAR(one.pressure_loss, one.reference_pressure_loss, 1e-14 * one.reference_pressure_loss);
}
