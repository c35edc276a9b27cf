#pragma once
#include <array>
#include <string>

#include "lbm/fluid_solver.h"

namespace lbm {

// Limits of the weakly compressible scheme. Speeds: the scheme is accurate only well below
// the lattice speed of sound c_s = 1/sqrt(3); a drive or a fluid faster than kMaxLatticeSpeed
// is refused (drive) or stops the run (during it). Pressure drive: a density difference
// between inlet and outlet above kMaxDensityDifference is far outside the weakly
// compressible regime (the equation of state p = c_s^2 rho is linearised about rho0 = 1):
// such a drive runs (the paper's clogged pores sit at 0.3-0.6), with a warning that states
// its compressibility error (below); the solver refuses kMaxDensityDifference and above.
constexpr double kSoundSpeed = 0.5773502691896258;
constexpr double kMaxLatticeSpeed = 0.3;
constexpr double kWeaklyCompressibleDensityDifference = 0.1;
constexpr double kMaxDensityDifference = 0.9;

// Empty when the drive is within the limits above; otherwise what exceeds which limit, in
// lattice units ("0.35 in lattice units, above the stable limit 0.30 (lattice Mach 0.61)"),
// for the host to prefix with its keyword and the value in the script's units.
std::string drive_limit_violation(const FlowDrive& drive);

// Empty for a drive within the weakly compressible regime; above it, what the run costs in
// accuracy ("a lattice density difference of 0.6, beyond the weakly compressible 0.1: the
// fluid velocity is up to 38 % slower than incompressible flow at the same pressure loss
// (the mass flux is right within 0.3 %)").
std::string drive_accuracy_warning(const FlowDrive& drive);

// Compressibility error of a pressure drive with density difference rho_in - rho_out
// (rho_out = 1; equal to the pressure loss in units of P_out, P / P_out = 3 Delta p): the
// largest relative deviation of the local velocity from incompressible flow with the same
// pressure loss. The scheme's kinematic viscosity is constant, so in a viscous channel its
// mass flux obeys the incompressible law with rho_out as reference, while the velocity,
// mass flux over local density, is slower where the fluid is denser; at the inlet by
// Delta rho / (1 + Delta rho) (0.09 at 0.1, 0.23 at 0.3, 0.375 at 0.6). Measured on a
// pressure-driven plane channel within 0.003 up to 0.6 (doc/stability.md,
// tests/lbm/test_compressibility.cpp). With He & Luo's incompressible equilibrium
// (FluidParameters::incompressible) the measured error is below 0.001 at 0.6.
double compressibility_error_estimate(double density_difference);

// A fluid node whose state is not finite or whose speed exceeds a limit, found by
// check_fluid_state(); `found` is false when every owned fluid node is fine.
struct FluidStateProblem {
  bool found = false;
  std::array<int, 3> node{0, 0, 0};  // global lattice indices
  double density = 0.0;
  double speed = 0.0;
  int wall_links = 0;  // directions of the node's 18 that end on a static wall (kSolid) node
  std::string describe() const;  // "node (i,j,k): density ..., speed ... (lattice units)"
};

// Scans this rank's owned fluid nodes for NaN/inf populations, non-positive density or a
// speed above max_speed (lattice units; the scheme is only accurate well below the lattice
// speed of sound 0.577, and unstable near it). Local to the rank: the host reduces.
FluidStateProblem check_fluid_state(const FluidSolver& solver, double max_speed);

// This rank's fastest owned fluid node (`found` false when it owns none): where the largest
// lattice Mach number of a thermo row is, for the fast-flow warning. Local to the rank.
FluidStateProblem fastest_node(const FluidSolver& solver);

// Largest speed over the owned fluid nodes of all ranks (the lattice Mach number times c_s).
double max_speed(const FluidSolver& solver);

}  // namespace lbm
