#pragma once
// The density and |u|^2 of every node of one z-plane of a rank's block, computed from the 19
// population arrays read front to back (one stretch of each array per plane, across the SIMD
// lanes), for the whole-lattice scans: the thermo totals (lattice_totals, macroscopic.cpp)
// and the NaN/runaway guard (check_fluid_state, stability.cpp). Per node the same additions
// in the same order as FluidSolver::density() and velocity(), and |u|^2 as max_speed()
// computes it, so either scan gives what the per-node functions give, bit for bit.
#include <cstddef>

#include "lbm/fluid_solver.h"

namespace lbm::detail {

struct PlaneMoments {
  std::size_t length = 0;        // slots: the plane's owned rows and the padding between them
  const double* rho = nullptr;     // slot i: cell layout.cell(0, 0, k) + i
  const double* speed2 = nullptr;  // |u|^2 (meaningless where the node is not fluid)
};

// Plane k's moments in the calling thread's buffers, valid until its next call.
PlaneMoments plane_moments(const FluidSolver& solver, int k);

}  // namespace lbm::detail
