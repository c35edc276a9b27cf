#pragma once
// Drag on a fixed sphere in a periodic simple-cubic array driven by a body force g
// (tests/coupling/test_drag_array.cpp and the drag and moving cases of examples/accuracy).
// Reference: Sangani & Acrivos (1982), K(chi = d/L = 0.5) = 2.8420 (doc/references.md), with
// F = 6 pi mu a K U, U the superficial velocity, and F = g L^3 in steady state; the momentum
// exchange must also balance the body force on the fluid, F_me = g N_fluid.
#include <cmath>

#include "cases/serial_flow.h"
#include "coupling/sphere_coupling.h"

namespace cases {

constexpr double kDragChi = 0.5;      // d / L
constexpr double kDragKRef = 2.8420;  // Sangani & Acrivos (1982) at chi = 0.5

// Body force on the fluid that gives the superficial velocity U in an array of spheres of
// radius a, period L, viscosity nu, if K = K_ref.
inline double drag_array_body_force(double U, double nu, double a, int L) {
  return U * 6.0 * kPi * nu * a * kDragKRef / double(L) / L / L;
}

struct DragArrayRun {
  double K = 0.0;              // from the flow: g L^3 / (6 pi mu a U)
  double force_balance = 0.0;  // F_me / (g N_fluid), 1 in steady state
  long steps = 0;
};

// Runs until U changes by less than 1e-5 relative per 100 steps, or max_steps.
inline DragArrayRun drag_in_sphere_array(int diameter, lbm::MovingWallScheme scheme,
                                         long max_steps) {
  const int L = static_cast<int>(std::lround(diameter / kDragChi));
  const double a = 0.5 * diameter, nu = 1.0 / 6.0;
  const double U_target = 2e-4;  // Re = U d / nu ~ 0.01: Stokes flow
  const double g = drag_array_body_force(U_target, nu, a, L);
  auto solver = make_solver({L, L, L}, {true, true, true}, 1.0, {g, 0.0, 0.0});
  coupling::ParticleSet particles;
  // Off the lattice symmetry so the links see generic fractions.
  particles.add(1, {0.5 * L + 0.23, 0.5 * L - 0.31, 0.5 * L + 0.17}, {0, 0, 0}, a);
  coupling::SphereCouplingOptions options;
  options.wall_scheme = scheme;
  coupling::SphereCoupling coupling(*solver, options);
  DragArrayRun r;
  double previous = 0.0;
  for (r.steps = 0; r.steps < max_steps;) {
    for (int s = 0; s < 100; ++s, ++r.steps) coupling.step(particles.view());
    const double U = superficial_velocity(*solver, 0);
    if (std::abs(U - previous) < 1e-5 * std::abs(U)) break;
    previous = U;
  }
  long long fluid = 0;
  const double U = superficial_velocity(*solver, 0, &fluid);
  r.K = g * L * L * L / (6.0 * kPi * nu * a * U);
  r.force_balance = coupling.force(0)[0] / (g * double(fluid));
  return r;
}

}  // namespace cases
