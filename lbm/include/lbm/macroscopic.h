#pragma once
#include <array>
#include <vector>

#include "lbm/fluid_solver.h"

namespace lbm {

// Fields on this rank's owned nodes, x fastest (size = owned volume). Solid and particle
// nodes report rho = rho0 and u = 0 so the fields are clean for output.
struct MacroscopicFields {
  std::vector<double> density;
  std::vector<double> velocity;  // 3 per node
  std::vector<std::uint8_t> node_type;
};
MacroscopicFields compute_fields(const FluidSolver& solver);

// Reductions over all ranks (every rank gets the result).
// Volumetric flux sum(u_axis) * 1 cell area through the plane `index` normal to `axis`.
double plane_flux(const FluidSolver& solver, int axis, int index);
// Mean pressure p = cs^2 rho over the fluid nodes of a plane.
double plane_mean_pressure(const FluidSolver& solver, int axis, int index);
// Total mass sum(rho) over fluid nodes.
double total_mass(const FluidSolver& solver);
// Pressure loss between the inlet and outlet planes of the drive axis (first and last
// planes): p_in - p_out.
double pressure_loss(const FluidSolver& solver);

}  // namespace lbm
