#pragma once
// Small flows for the parallel tests: a channel between walls (y) with a few solid voxels,
// some on the cut planes of the 2-rank splits, started from a non-uniform state so every
// direction of the halo matters.
#include <array>
#include <cmath>

#include "cases/serial_flow.h"
#include "lbm/fluid_solver.h"
#include "lbm/voxel_geometry.h"

namespace lbm_parallel_test {

struct FlowCase {
  lbm::VoxelGeometry geometry;
  lbm::FluidParameters parameters;
  lbm::FlowDrive drive;
};

inline lbm::VoxelGeometry channel_geometry() {
  lbm::VoxelGeometry g({12, 10, 6}, 0.1, {1.0, -2.0, 0.5});
  for (int i = 4; i <= 5; ++i)
    for (int j = 3; j <= 4; ++j)
      for (int k = 2; k <= 3; ++k) g.set_solid(i, j, k, true);
  g.set_solid(9, 7, 1, true);
  g.set_solid(0, 5, 3, true);   // on the periodic x face
  g.set_solid(6, 2, 2, true);   // on the x cut of a 2-rank split
  g.set_solid(3, 5, 5, true);   // on the y cut and the periodic z face
  g.set_solid(11, 4, 0, true);  // periodic corner region
  return g;
}

// Body force along x, periodic x and z.
inline FlowCase body_force_channel() {
  FlowCase c;
  c.geometry = channel_geometry();
  c.parameters.tau = 0.8;
  c.parameters.body_force = {1e-4, 2e-5, -1e-5};
  c.parameters.periodic = {true, false, true};
  return c;
}

// Pressure loss along x (inlet/outlet faces on different ranks in an x split).
inline FlowCase pressure_driven_channel() {
  FlowCase c;
  c.geometry = channel_geometry();
  c.parameters.tau = 0.9;
  c.parameters.periodic = {false, false, true};
  c.drive.kind = lbm::FlowDrive::kPressureLoss;
  c.drive.axis = 0;
  c.drive.pressure_loss = 1e-3;
  return c;
}

// rho and u varying in all three directions.
inline std::array<double, 4> initial_state(int i, int j, int k) {
  return {1.0 + 0.01 * std::sin(0.7 * i + 0.3 * j) * std::cos(0.5 * k),
          0.01 * std::cos(0.4 * j + 0.2 * k), 0.005 * std::sin(0.6 * i + 0.9 * k),
          0.004 * std::cos(0.8 * i - 0.5 * j)};
}

// The whole lattice of the case on one rank: the serial run the parallel ones must equal.
inline lbm::Decomposition serial_decomposition(const FlowCase& c) {
  return cases::serial_decomposition(c.geometry, c.parameters.periodic);
}

inline void start(lbm::FluidSolver& solver) { solver.initialise_equilibrium(initial_state); }

}  // namespace lbm_parallel_test
