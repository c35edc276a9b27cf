// The link mass correction taken in the collide-stream kernel's pass
// (SphereCouplingOptions::correct_mass_in_kernel) against the one the moving walls' sweep
// writes: spheres moving fast through a periodic box, covering and uncovering nodes. The
// same operations on the same slots in another pass: populations and loads the same bits
// step after step, the fluid's mass booked to round-off, and the same bits on one and two
// threads.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>

#include "cases/scoped_threads.h"
#include "cases/serial_flow.h"
#include "cases/staged_step.h"
#include "coupling/sphere_coupling.h"

namespace {

struct CoupledRun {
  std::unique_ptr<lbm::FluidSolver> solver;
  std::vector<coupling::Vec3> force;
  double mass_change = 0.0, booked = 0.0, mass = 0.0;
};

CoupledRun run(int steps, bool in_kernel, int threads) {
  const cases::ScopedThreads scope(cases::ScopedThreads::most(threads));
  CoupledRun r;
  r.solver = cases::make_solver({24, 24, 24}, {true, true, true}, 0.9, {2e-6, 0.0, 1e-6});
  coupling::ParticleSet particles;
  particles.add(1, {6.3, 7.1, 8.4}, {0.02, 0.01, -0.015}, {0.0, 0.01, 0.02}, 3.2);
  particles.add(2, {15.2, 14.6, 9.7}, {-0.018, 0.012, 0.02}, {0.01, 0.0, -0.01}, 3.6);
  particles.add(3, {10.4, 19.3, 18.1}, {0.011, -0.02, 0.009}, 2.9);
  coupling::SphereCouplingOptions options;
  options.correct_mass_in_kernel = in_kernel;
  coupling::SphereCoupling c(*r.solver, options);
  c.map_and_refill(particles.view(true));
  const double m0 = cases::fluid_mass(*r.solver);
  for (int s = 0; s < steps; ++s) {
    cases::advance_particles(particles, 8.0);
    c.step(particles.view(true));
    r.booked += c.last_surface_mass() + c.last_mass_change().refilled - c.last_mass_change().covered;
  }
  r.mass = cases::fluid_mass(*r.solver);
  r.mass_change = r.mass - m0;
  for (std::size_t p = 0; p < particles.size(); ++p) r.force.push_back(c.force(p));
  return r;
}

}  // namespace

TEST(KernelMassCorrection, SameBitsAsTheSweep) {
  const CoupledRun sweep = run(60, false, 1), kernel = run(60, true, 1);
  EXPECT_EQ(cases::max_population_difference(*sweep.solver, *kernel.solver), 0.0);
  for (std::size_t p = 0; p < sweep.force.size(); ++p)
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(std::memcmp(&kernel.force[p][a], &sweep.force[p][a], sizeof(double)), 0)
          << "particle " << p << " axis " << a;
  // The fluid's mass changes by what the coupling books (the surfaces' wall terms, refilled
  // less covered nodes), as with the sweep's correction.
  EXPECT_LT(std::abs(kernel.mass_change - kernel.booked), 1e-10 * kernel.mass);
  EXPECT_LT(std::abs(sweep.mass_change - sweep.booked), 1e-10 * sweep.mass);
}

TEST(KernelMassCorrection, SameBitsOnOneAndTwoThreads) {
  const CoupledRun one = run(30, true, 1), two = run(30, true, 2);
  EXPECT_EQ(cases::max_population_difference(*one.solver, *two.solver), 0.0);
  for (std::size_t p = 0; p < one.force.size(); ++p)
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(std::memcmp(&one.force[p][a], &two.force[p][a], sizeof(double)), 0)
          << "particle " << p << " axis " << a;
}
