// Mass conservation with moving spheres: two spheres moving through a periodic box for many
// steps, crossing cells in all directions; the fluid mass drifts only by the refill/cover
// imbalance and the moving-wall terms.
#include <gtest/gtest.h>

#include <cstdio>

#include "cases/serial_flow.h"
#include "coupling/sphere_coupling.h"

using namespace coupling;

TEST(MassConservation, MovingSpheresDriftIsSmall) {
  cases::Stopwatch watch;
  auto solver = cases::make_solver({24, 24, 24}, {true, true, true});
  ParticleSet particles;
  const Vec3 x0{6.3, 7.1, 8.4}, x1{17.2, 16.6, 15.3};
  const Vec3 v0{0.02, 0.01, -0.005}, v1{-0.015, 0.005, 0.012};
  particles.add(1, x0, v0, 3.5);
  particles.add(2, x1, v1, 3.0);
  SphereCoupling coupling(*solver);
  coupling.map_and_refill(particles.view());
  const double m0 = cases::fluid_mass(*solver);
  const int steps = 1000;
  double covered = 0.0, refilled = 0.0, max_step_change = 0.0;
  for (int t = 0; t < steps; ++t) {
    for (int a = 0; a < 3; ++a) {
      particles.position[a] = x0[a] + v0[a] * t;
      particles.position[3 + a] = x1[a] + v1[a] * t;
    }
    coupling.step(particles.view());
    covered += coupling.last_mass_change().covered;
    refilled += coupling.last_mass_change().refilled;
    max_step_change = std::max(max_step_change, std::abs(coupling.last_mass_change().net()));
  }
  const double m1 = cases::fluid_mass(*solver);
  const double drift = (m1 - m0) / m0 / steps;
  std::printf("mass: %d steps, relative drift %.2e per step (total %+.3e of %.1f); covered %.2f, "
              "refilled %.2f (mean per step %.3f / %.3f), largest net change in one step %.3f; %.2f s\n",
              steps, drift, m1 - m0, m0, covered, refilled, covered / steps, refilled / steps,
              max_step_change, watch.seconds());
  // Measured -1.4e-6 per step (MLS, averaged-density refill, link mass correction on;
  // -1.7e-6 without it): what remains is the bounce-back moving-wall terms (-0.024 per step)
  // and covering/refilling, which balance on average (1.420 vs 1.425 per step). Bound 3e-6
  // per step.
  EXPECT_LT(std::abs(drift), 3e-6);
}
