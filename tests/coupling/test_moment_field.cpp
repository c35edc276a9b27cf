// The moving walls read the moments of the nodes next to the spheres from the field the
// collide-stream kernel keeps (FluidSolver::keep_node_moments) instead of gathering them from
// the populations (lbm::moving_wall::MomentCache): the same populations and loads bit for
// bit, step after step, with spheres moving, covering and uncovering nodes (whose refill
// refreshes their moments), on one and two threads.
#include <gtest/gtest.h>

#ifdef _OPENMP
#include <omp.h>
#endif

#include <cstring>

#include "cases/serial_flow.h"
#include "cases/staged_step.h"
#include "coupling/sphere_coupling.h"

namespace {

coupling::ParticleSet moving_spheres() {
  coupling::ParticleSet set;
  set.add(1, {6.3, 7.1, 8.4}, {0.02, 0.01, -0.015}, {0.0, 0.01, 0.02}, 3.2);
  set.add(2, {15.2, 14.6, 9.7}, {-0.018, 0.012, 0.02}, {0.01, 0.0, -0.01}, 3.6);
  set.add(3, {10.4, 19.3, 18.1}, {0.011, -0.02, 0.009}, 2.9);
  set.add(4, {19.6, 5.2, 17.3}, {-0.01, -0.013, -0.02}, 3.1);
  return set;
}

// Runs `steps` coupled steps; with `from_populations` the kept field is withdrawn before
// each, so that the moving walls gather the moments from the populations.
struct CoupledRun {
  std::unique_ptr<lbm::FluidSolver> solver;
  std::vector<coupling::Vec3> force;
};
CoupledRun run(int steps, bool from_populations) {
  CoupledRun r;
  r.solver = cases::make_solver({24, 24, 24}, {true, true, true}, 0.9, {2e-6, 0.0, 1e-6});
  coupling::ParticleSet particles = moving_spheres();
  coupling::SphereCoupling c(*r.solver);
  for (int s = 0; s < steps; ++s) {
    cases::advance_particles(particles, 8.0);
    if (from_populations) r.solver->invalidate_node_moments();
    c.step(particles.view(true));
  }
  for (std::size_t p = 0; p < particles.size(); ++p) r.force.push_back(c.force(p));
  return r;
}

class MomentField : public ::testing::TestWithParam<int> {};

TEST_P(MomentField, GivesTheSameStepsAsGatheringThemBitForBit) {
#ifdef _OPENMP
  const int before = omp_get_max_threads();
  omp_set_num_threads(GetParam());
#endif
  // (Without OpenMP both parameters run on one thread: the same comparison.)
  const CoupledRun kept = run(40, false), gathered = run(40, true);
  EXPECT_EQ(cases::max_population_difference(*kept.solver, *gathered.solver), 0.0);
  for (std::size_t p = 0; p < kept.force.size(); ++p)
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(std::memcmp(&kept.force[p][a], &gathered.force[p][a], sizeof(double)), 0)
          << "particle " << p << " axis " << a;
  EXPECT_NE(kept.solver->node_moment_field(), nullptr);
#ifdef _OPENMP
  omp_set_num_threads(before);
#endif
}

INSTANTIATE_TEST_SUITE_P(Threads, MomentField, ::testing::Values(1, 2));

}  // namespace
