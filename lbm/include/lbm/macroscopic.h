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

// Density and velocity at one node from its (post-collision) populations; the velocity has
// Guo's half-force removed, u = (sum_q f_q c_q - F/2) / rho (see collide_stream.cpp).
struct NodeMoments {
  double rho = 0.0;
  std::array<double, 3> u{0.0, 0.0, 0.0};
};
NodeMoments node_moments(const PopulationField& f, std::size_t cell,
                         const std::array<double, 3>& body_force);

// Reductions over all ranks (every rank gets the result).
// Flux through the plane `index` normal to `axis`: sum(rho u_axis) / rho0 over its fluid
// nodes (cell area 1). The mass flux is what the scheme conserves exactly at steady state;
// dividing by the reference density gives the volumetric flux of the incompressible limit
// (sum(u_axis) differs from it by the density variation, O(Ma^2)). With the incompressible
// equilibrium (FluidParameters::incompressible) the conserved momentum is rho0 u: sum(u_axis).
double plane_flux(const FluidSolver& solver, int axis, int index);
// Mean pressure p = cs^2 rho over the fluid nodes of a plane.
double plane_mean_pressure(const FluidSolver& solver, int axis, int index);
// Total mass sum(rho) over fluid nodes.
double total_mass(const FluidSolver& solver);
// total_mass, max_speed (lbm/stability.h) and the count of owned particle (kMoving) nodes, as
// those give them, bit for bit, from one pass over the lattice that reads each population
// array front to back, plane by plane (the diagnostics of every thermo row: the two
// whole-lattice passes it replaces, which gathered 19 arrays per node, cost a fifth of a pure
// fluid step at a row every 10 steps).
struct LatticeTotals {
  double mass = 0.0;
  double max_speed = 0.0;
  long long moving_nodes = 0;
};
LatticeTotals lattice_totals(const FluidSolver& solver);
// Pressure loss between the inlet and outlet planes of the drive axis (first and last
// planes): p_in - p_out.
double pressure_loss(const FluidSolver& solver);

}  // namespace lbm
