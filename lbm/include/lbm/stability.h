#pragma once
#include <array>
#include <string>

#include "lbm/fluid_solver.h"

namespace lbm {

// A fluid node whose state is not finite or whose speed exceeds a limit, found by
// check_fluid_state(); `found` is false when every owned fluid node is fine.
struct FluidStateProblem {
  bool found = false;
  std::array<int, 3> node{0, 0, 0};  // global lattice indices
  double density = 0.0;
  double speed = 0.0;
  std::string describe() const;  // "node (i,j,k): density ..., speed ... (lattice units)"
};

// Scans this rank's owned fluid nodes for NaN/inf populations, non-positive density or a
// speed above max_speed (lattice units; the scheme is only accurate well below the lattice
// speed of sound 0.577, and unstable near it). Local to the rank: the host reduces.
FluidStateProblem check_fluid_state(const FluidSolver& solver, double max_speed);

// Largest speed over the owned fluid nodes of all ranks (the lattice Mach number times c_s).
double max_speed(const FluidSolver& solver);

}  // namespace lbm
