#pragma once
// Plane channel flow driven by a pressure loss (on-site density faces at x = 0 and x = L-1,
// half-way bounce-back walls at y = -1/2 and H - 1/2, periodic in z), measured against the
// incompressible Poiseuille solution with the same pressure loss and the outlet density as
// the reference: G = c_s^2 (rho_in - rho_out) / (L - 1), u(y) = G (y + 1/2)(H - 1/2 - y) /
// (2 rho_out nu), flux per unit depth Q = sum over the nodes of u(y).
// Used by test_compressibility.cpp (the bound of lbm/stability.h) and by the program
// compressibility_table.cpp (the table of doc/stability.md).
#include <algorithm>
#include <cmath>
#include <vector>

#include "lbm/d3q19.h"
#include "lbm/fluid_solver.h"
#include "lbm/macroscopic.h"

namespace pressure_channel {

struct Setup {
  int length = 201;                 // nodes along x, boundary nodes included
  int height = 8;                   // fluid nodes between the walls
  double density_difference = 0.1;  // rho_in - rho_out, rho_out = 1 (= P / P_out)
  double tau = 1.0;
  bool incompressible = false;  // He & Luo's equilibrium (FluidParameters::incompressible)
  long max_steps = 60000;
};

struct Result {
  bool finite = true;                   // every population finite at the end
  long steps = 0;                       // steps to the steady state (or max_steps)
  double mach = 0.0;                    // largest speed / c_s
  double mass_flux_error = 0.0;         // plane_flux / Q - 1 at mid-channel: sum(rho u) / rho0
                                        // (standard), sum(u) (incompressible equilibrium)
  double inlet_velocity_error = 0.0;    // centre-line u / incompressible - 1, next to the inlet
  double middle_velocity_error = 0.0;   // ... at mid-channel
  double outlet_velocity_error = 0.0;   // ... next to the outlet
  double largest_velocity_error = 0.0;  // largest |error| of the centre-line u over x
  double inlet_density = 0.0;           // density at the first node (imposed)
  double middle_density = 0.0;          // mean density of the mid-channel plane
};

inline Result run(const Setup& s) {
  const int L = s.length, H = s.height, depth = 2;
  lbm::VoxelGeometry geometry({L, H, depth});
  lbm::FluidParameters parameters;
  parameters.tau = s.tau;
  parameters.incompressible = s.incompressible;
  parameters.periodic = {false, false, true};
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kPressureLoss;
  drive.axis = 0;
  drive.outlet_density = 1.0;
  drive.pressure_loss = lbm::D3Q19::cs2 * s.density_difference;
  lbm::Box box;
  box.hi = geometry.dims();
  lbm::FluidSolver solver(geometry, parameters, drive,
                          lbm::Decomposition::serial(box, parameters.periodic));

  const double nu = lbm::TrtParameters::viscosity(s.tau);
  const double gradient = drive.pressure_loss / (L - 1);
  auto exact = [&](int y) { return gradient * (y + 0.5) * (H - 0.5 - y) / (2.0 * nu); };
  // The flux of the exact profile summed over the nodes, as plane_flux sums the lattice's
  // (the integral G H^3 / (12 nu) differs from the node sum by 1 / (2 H^2)).
  double exact_flux = 0.0;
  for (int y = 0; y < H; ++y) exact_flux += exact(y);
  // Start near the steady state (linear density; the exact mass flux, or with the
  // incompressible equilibrium the exact velocity): it only shortens the transient.
  solver.initialise_equilibrium([&](int x, int y, int) {
    const double rho = 1.0 + s.density_difference * (1.0 - double(x) / (L - 1));
    const double u = exact(std::clamp(y, 0, H - 1));
    return std::array<double, 4>{rho, s.incompressible ? u : u / rho, 0.0, 0.0};
  });

  const int middle = L / 2;
  auto mass_flux = [&] { return lbm::plane_flux(solver, 0, middle) / depth; };
  double previous = mass_flux();
  Result r;
  while (r.steps < s.max_steps) {
    for (int i = 0; i < 500; ++i) solver.step();
    r.steps += 500;
    const double now = mass_flux();
    if (!std::isfinite(now)) break;
    const double imbalance =
        std::abs(lbm::plane_flux(solver, 0, 1) - lbm::plane_flux(solver, 0, L - 2)) / depth;
    if (std::abs(now - previous) < 1e-9 * std::abs(now) && imbalance < 1e-6 * std::abs(now)) break;
    previous = now;
  }
  for (double v : solver.populations().raw()) r.finite = r.finite && std::isfinite(v);

  const auto& layout = solver.layout();
  // Centre line: the mean of the two middle nodes of an even H.
  auto centre_velocity = [&](int x) {
    double sum = 0.0;
    for (int y = (H - 1) / 2; y <= H / 2; ++y) sum += solver.velocity(layout.cell(x, y, 0))[0];
    return sum / (1 + H / 2 - (H - 1) / 2);
  };
  const double exact_centre = 0.5 * (exact((H - 1) / 2) + exact(H / 2));
  for (int x = 0; x < L; ++x) {
    const double error = centre_velocity(x) / exact_centre - 1.0;
    r.largest_velocity_error = std::max(r.largest_velocity_error, std::abs(error));
    for (int y = 0; y < H; ++y) {
      const auto u = solver.velocity(layout.cell(x, y, 0));
      r.mach = std::max(
          r.mach, std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]) / std::sqrt(lbm::D3Q19::cs2));
    }
  }
  r.mass_flux_error = mass_flux() / exact_flux - 1.0;
  r.inlet_velocity_error = centre_velocity(1) / exact_centre - 1.0;
  r.middle_velocity_error = centre_velocity(middle) / exact_centre - 1.0;
  r.outlet_velocity_error = centre_velocity(L - 2) / exact_centre - 1.0;
  r.inlet_density = solver.density(layout.cell(0, H / 2, 0));
  r.middle_density = lbm::plane_mean_pressure(solver, 0, middle) / lbm::D3Q19::cs2;
  return r;
}

}  // namespace pressure_channel
