// Velocity inlet and pressure outlet (Hecht-Harting), constant pressure loss mode, and
// flux conservation through the paper's pore constriction.
#include <gtest/gtest.h>

#include <cstdio>

#include "flow_cases.h"
#include "lbm/pore_scene.h"

TEST(OpenBoundary, FluxIsConservedThroughThePoreConstriction) {
  lbm::PoreSceneSpec spec;
  spec.inlet_length = 6;
  spec.free_length = 6;
  spec.pore_length = 8;
  spec.outlet_length = 8;
  spec.width = 16;
  spec.pore_diameter = 10;
  const auto g = lbm::make_pore_scene(spec);
  lbm::FluidParameters p;
  p.tau = 1.0;
  p.periodic = {false, true, true};
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kInletVelocity;
  drive.inlet_velocity = 0.01;
  lbm::FluidSolver solver(g, p, drive, flow_cases::serial(g, p.periodic));
  flow_cases::run_to_steady(solver, 1e-9, 40000, 200);
  const double inflow = drive.inlet_velocity * spec.width * spec.width;
  const auto r = lbm::regions_of(spec);
  for (int x : {0, r.free_end - 1, (r.pore_begin + r.pore_end) / 2, r.outlet_end - 1}) {
    const double flux = lbm::plane_flux(solver, 0, x);
    std::printf("plane x=%d: volumetric flux %.6f (inflow %.6f)\n", x, flux, inflow);
    // Volumetric flux differs from the conserved mass flux by the density variation (~Ma^2).
    EXPECT_NEAR(flux / inflow, 1.0, 5e-3) << "plane " << x;
  }
  EXPECT_GT(lbm::pressure_loss(solver), 0.0);
}

TEST(OpenBoundary, ImposedPressureLossDrivesPoiseuilleFlux) {
  // Plane channel between walls normal to y, pressure loss along x.
  const int nx = 40, H = 9;
  lbm::VoxelGeometry g({nx, H, 2});
  lbm::FluidParameters p;
  p.tau = 1.0;
  p.periodic = {false, false, true};
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kPressureLoss;
  drive.pressure_loss = 1e-4;
  lbm::FluidSolver solver(g, p, drive, flow_cases::serial(g, p.periodic));
  flow_cases::run_to_steady(solver, 1e-10, 100000, 500);
  EXPECT_NEAR(lbm::pressure_loss(solver) / drive.pressure_loss, 1.0, 1e-6);
  // Q per unit depth = G H^3 / (12 mu), G = dp / (nx - 1) between the boundary node planes.
  const double mu = lbm::TrtParameters::viscosity(1.0);
  const double expected = drive.pressure_loss / (nx - 1) * H * H * H / (12.0 * mu) * 2;  // depth 2
  const double flux = lbm::plane_flux(solver, 0, nx / 2);
  std::printf("pressure-driven channel: flux %.6e, analytic %.6e\n", flux, expected);
  EXPECT_NEAR(flux / expected, 1.0, 0.02);
}

TEST(OpenBoundary, DriveTooStrongIsRefusedWithItsRange) {
  lbm::VoxelGeometry g({8, 4, 4});
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kInletVelocity;
  drive.inlet_velocity = 0.5;
  try {
    lbm::FluidSolver solver(g, lbm::FluidParameters{}, drive, flow_cases::serial(g, {false, true, true}));
    FAIL() << "inlet velocity 0.5 accepted";
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inlet velocity"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("(-0.3, 0.3)"), std::string::npos);
  }
}
