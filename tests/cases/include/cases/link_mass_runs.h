#pragma once
// Long runs that measure the fluid mass the interpolated moving-wall links create
// (tests/faults/test_link_mass.cpp, doc/stability.md "Mass conservation at interpolated
// walls"): a fixed sphere in a dense periodic simple-cubic array driven by a body force,
// and a sphere spinning in place in a closed box (moving walls, no node covered or uncovered).
#include <cmath>

#include "cases/serial_flow.h"
#include "coupling/sphere_coupling.h"

namespace cases {

struct LinkMassRun {
  double mass_drift = 0.0;       // (M(end) - M(0)) / M(0) over fluid nodes
  double link_defect = 0.0;      // mass the links created, summed over the run, / M(0)
  double force_balance = 0.0;    // F_me / (g N_fluid), mean of the last 1000 steps (array only)
  double force_last_step = 0.0;  // the same in the last step alone
  // Relative change over the last 1000 steps of U averaged over two consecutive steps (array
  // only): Mei-Luo-Shyy in gaps narrower than a cell (phi 0.45) carries a slowly growing
  // oscillation of period two steps that a single step would sample.
  double velocity_change = 0.0;
  long steps = 0;
};

inline coupling::SphereCouplingOptions link_mass_options(lbm::MovingWallScheme scheme,
                                                         bool conserve) {
  coupling::SphereCouplingOptions options;
  options.wall_scheme = scheme;
  options.conserve_link_mass = conserve;
  return options;
}

// Period L cells, sphere radius from the solid fraction phi = (4/3) pi a^3 / L^3, body force
// for a superficial velocity of about 2e-4 (Re ~ 0.01) at the drag test's K.
inline LinkMassRun dense_array_run(double solid_fraction, int L, lbm::MovingWallScheme scheme,
                                   bool conserve, long steps) {
  const double a = L * std::cbrt(3.0 * solid_fraction / (4.0 * kPi)), nu = 1.0 / 6.0;
  const double g = 2e-4 * 6.0 * kPi * nu * a * 2.842 / double(L) / L / L;
  auto solver = make_solver({L, L, L}, {true, true, true}, 1.0, {g, 0.0, 0.0});
  coupling::ParticleSet particles;
  // Off the lattice symmetry so the links see generic fractions.
  particles.add(1, {0.5 * L + 0.23, 0.5 * L - 0.31, 0.5 * L + 0.17}, {0, 0, 0}, a);
  coupling::SphereCoupling coupling(*solver, link_mass_options(scheme, conserve));
  coupling.map_and_refill(particles.view());
  LinkMassRun r;
  const double m0 = fluid_mass(*solver);
  double U_before = 0.0, U_after = 0.0, force_sum = 0.0;
  for (r.steps = 0; r.steps < steps; ++r.steps) {
    if (r.steps == steps - 1002 || r.steps == steps - 1001)
      U_before += 0.5 * superficial_velocity(*solver, 0);
    if (r.steps == steps - 1) U_after += 0.5 * superficial_velocity(*solver, 0);
    coupling.step(particles.view());
    r.link_defect += coupling.last_link_defect().net;
    if (r.steps >= steps - 1000) force_sum += coupling.force(0)[0];
  }
  long long fluid = 0;
  U_after += 0.5 * superficial_velocity(*solver, 0, &fluid);
  r.mass_drift = (fluid_mass(*solver) - m0) / m0;
  r.link_defect /= m0;
  r.force_balance = force_sum / 1000.0 / (g * double(fluid));
  r.force_last_step = coupling.force(0)[0] / (g * double(fluid));
  r.velocity_change = std::abs(U_after - U_before) / std::abs(U_after);
  return r;
}

// A sphere of radius 3.6 spinning about a tilted axis (surface speed ~ 0.01) off-centre in a
// closed box of 12^3 cells (half-way bounce-back walls), fluid at rest at first.
inline LinkMassRun spinning_sphere_run(lbm::MovingWallScheme scheme, bool conserve, long steps) {
  auto solver = make_solver({12, 12, 12}, {false, false, false});
  coupling::ParticleSet particles;
  particles.add(1, {6.23, 5.81, 6.37}, {0, 0, 0}, 3.6);
  particles.angular_velocity = {0.0015, -0.001, 0.002};
  coupling::SphereCoupling coupling(*solver, link_mass_options(scheme, conserve));
  coupling.map_and_refill(particles.view(true));
  LinkMassRun r;
  const double m0 = fluid_mass(*solver);
  for (r.steps = 0; r.steps < steps; ++r.steps) {
    coupling.step(particles.view(true));
    r.link_defect += coupling.last_link_defect().net;
  }
  r.mass_drift = (fluid_mass(*solver) - m0) / m0;
  r.link_defect /= m0;
  return r;
}

}  // namespace cases
