// Mass conservation with moving spheres: two spheres moving through a periodic box for many
// steps, crossing cells in all directions; the fluid mass drifts only by the refill/cover
// imbalance and the moving-wall terms.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "cases/serial_flow.h"
#include "coupling/sphere_coupling.h"
#include "lbm/moving_wall/moving_wall_scheme.h"

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
  double covered = 0.0, refilled = 0.0, max_step_change = 0.0, surfaces = 0.0;
  for (int t = 0; t < steps; ++t) {
    for (int a = 0; a < 3; ++a) {
      particles.position[a] = x0[a] + v0[a] * t;
      particles.position[3 + a] = x1[a] + v1[a] * t;
    }
    coupling.step(particles.view());
    surfaces += coupling.last_surface_mass();
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
  // Nothing unaccounted: the fluid mass changed by what the coupling put in, the moving
  // surfaces' wall terms and the refilled less the covered nodes (the link correction makes
  // the Mei-Luo-Shyy links' mass that of bounce-back), to round-off. The surfaces' part
  // (-24) comes from the end of the run, when the spheres meet (centres 5.1 cells apart at
  // step 950, radii 3.5 + 3.0): where they overlap, neither surface has fluid links (see the
  // next test for a sphere alone).
  const double sources = surfaces + refilled - covered;
  std::printf("mass sources: moving surfaces %+.6e, refilled - covered %+.6e, change %+.6e\n",
              surfaces, refilled - covered, m1 - m0);
  EXPECT_LT(std::abs(m1 - m0 - sources), 1e-10 * m0);
}

// The moving-wall terms of a sphere whose surface is all in the fluid cancel for a
// translation: over the links of any set of covered nodes, sum_l w_q c_q = 0 exactly (each
// covered node's sum over all q is zero, and pairs of covered neighbours cancel). What the
// fluid budget books as the surfaces' mass (PoreMonitor::kParticleSurfaceMass) is therefore
// zero here, step by step, and only a surface that meets no fluid (an open end, a contact)
// makes it nonzero.
TEST(MassConservation, TranslatingSphereSurfaceTermsCancel) {
  auto solver = cases::make_solver({20, 20, 20}, {true, true, true});
  ParticleSet particles;
  const Vec3 x0{6.3, 7.1, 8.4}, v{0.03, -0.02, 0.011};
  particles.add(1, x0, v, 3.5);
  SphereCoupling coupling(*solver);
  double largest = 0.0, moment = 0.0;
  for (int t = 0; t < 200; ++t) {
    for (int a = 0; a < 3; ++a) particles.position[a] = x0[a] + v[a] * t;
    coupling.step(particles.view());
    largest = std::max(largest, std::abs(coupling.last_surface_mass()));
    // The scale: one face's terms, 6 w rho0 |c.u| summed over the links.
    double scale = 0.0;
    for (const auto& link : coupling.links().links)
      scale += std::abs(lbm::moving_wall::wall_term(link.q, 1.0, link.wall_velocity));
    moment = std::max(moment, scale);
  }
  std::printf("translating sphere: largest |surface mass| per step %.3e against %.3e summed over "
              "its links' |wall terms|\n", largest, moment);
  EXPECT_GT(moment, 1.0);
  EXPECT_LT(largest, 1e-12 * moment);
}
