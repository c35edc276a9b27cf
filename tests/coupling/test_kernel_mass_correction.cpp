// The link mass correction taken in the collide-stream kernel's pass
// (SphereCouplingOptions::correct_mass_in_kernel), and the moving walls with it
// (moving_walls_in_kernel), against the moving walls' sweep that writes both: spheres moving
// fast through a periodic box, covering and uncovering nodes. The same operations on the
// same slots in another pass: populations and loads the same bits step after step, the
// fluid's mass booked to round-off, and the same bits on one and two threads.
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

enum class Pass { kSweep, kCorrectionInKernel, kLinksInKernel };

CoupledRun run(int steps, Pass pass, int threads) {
  const cases::ScopedThreads scope(cases::ScopedThreads::most(threads));
  CoupledRun r;
  r.solver = cases::make_solver({24, 24, 24}, {true, true, true}, 0.9, {2e-6, 0.0, 1e-6});
  coupling::ParticleSet particles;
  particles.add(1, {6.3, 7.1, 8.4}, {0.02, 0.01, -0.015}, {0.0, 0.01, 0.02}, 3.2);
  particles.add(2, {15.2, 14.6, 9.7}, {-0.018, 0.012, 0.02}, {0.01, 0.0, -0.01}, 3.6);
  particles.add(3, {10.4, 19.3, 18.1}, {0.011, -0.02, 0.009}, 2.9);
  coupling::SphereCouplingOptions options;
  options.correct_mass_in_kernel = pass != Pass::kSweep;
  options.moving_walls_in_kernel = pass == Pass::kLinksInKernel;
  coupling::SphereCoupling c(*r.solver, options);
  c.map_and_refill(particles.view(true));
  const double m0 = cases::fluid_mass(*r.solver);
  for (int s = 0; s < steps; ++s) {
    cases::advance_particles(particles, 8.0);
    c.step(particles.view(true));
    r.booked += c.last_surface_mass() + c.last_mass_change().refilled - c.last_mass_change().covered;
  }
  EXPECT_EQ(c.links_in_kernel(), pass == Pass::kLinksInKernel);
  r.mass = cases::fluid_mass(*r.solver);
  r.mass_change = r.mass - m0;
  for (std::size_t p = 0; p < particles.size(); ++p) r.force.push_back(c.force(p));
  return r;
}

}  // namespace

void expect_same_bits(const CoupledRun& a, const CoupledRun& b) {
  EXPECT_EQ(cases::max_population_difference(*a.solver, *b.solver), 0.0);
  for (std::size_t p = 0; p < a.force.size(); ++p)
    for (int k = 0; k < 3; ++k)
      EXPECT_EQ(std::memcmp(&a.force[p][k], &b.force[p][k], sizeof(double)), 0)
          << "particle " << p << " axis " << k;
  EXPECT_EQ(std::memcmp(&a.mass, &b.mass, sizeof(double)), 0);
}

TEST(KernelMassCorrection, SameBitsAsTheSweep) {
  const CoupledRun sweep = run(60, Pass::kSweep, 1);
  for (const Pass pass : {Pass::kCorrectionInKernel, Pass::kLinksInKernel}) {
    SCOPED_TRACE(pass == Pass::kLinksInKernel ? "links in the kernel" : "correction in the kernel");
    const CoupledRun kernel = run(60, pass, 1);
    expect_same_bits(sweep, kernel);
    // The fluid's mass changes by what the coupling books (the surfaces' wall terms,
    // refilled less covered nodes), as with the sweep's correction.
    EXPECT_LT(std::abs(kernel.mass_change - kernel.booked), 1e-10 * kernel.mass);
  }
  EXPECT_LT(std::abs(sweep.mass_change - sweep.booked), 1e-10 * sweep.mass);
}

TEST(KernelMassCorrection, SameBitsOnOneAndTwoThreads) {
  for (const Pass pass : {Pass::kCorrectionInKernel, Pass::kLinksInKernel}) {
    SCOPED_TRACE(pass == Pass::kLinksInKernel ? "links in the kernel" : "correction in the kernel");
    expect_same_bits(run(30, pass, 1), run(30, pass, 2));
  }
}
