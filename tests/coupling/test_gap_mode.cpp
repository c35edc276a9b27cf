// The gap mode: a fluid node between two spheres closer than a cell along z (every link with
// a z component ends on a sphere) keeps a z momentum that each step reverses and that no
// collision damps. A host that moves the spheres under their hydrodynamic force (a spring
// and a dashpot to their rest positions, as a deposited particle's contacts hold it, with
// N_DEM substeps per fluid step) and shows the fluid their one-step mean velocities feeds
// the mode back through the moving-wall term and pumps it; with the two-step mean of
// coupling::wall_velocity_of_steps it stays at what it was born with. What stopped the long
// clogging runs on the fluid guard (speed 0.5, density 1.6 at such a node).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cases/serial_flow.h"
#include "coupling/boundary/wall_velocity.h"
#include "coupling/sphere_coupling.h"
#include "lbm/d3q19.h"
#include "lbm/node_type.h"

using namespace coupling;

namespace {

struct GapRun {
  double first = 0.0, largest = 0.0, last = 0.0;  // |rho u_z| at the gap node
  double largest_speed = 0.0;
};

// Two spheres of radius 4 above each other along z; the node (8, 8, 10) lies 0.05 cells above
// the lower one and 0.3 below the upper one, and with it the nodes of plane 10 whose z
// neighbours are both covered form the gap. Each gap node is given a z momentum of 0.1
// (mass neutral), then `steps` fluid steps run with the spheres on springs; the run reports
// the node (8, 8, 10).
GapRun run_gap(bool two_step_mean, int steps) {
  using L = lbm::D3Q19;
  auto solver = cases::make_solver({16, 16, 24}, {true, true, true});
  const double R = 4.0;
  const Vec3 rest[2] = {{8.3, 8.2, 5.95}, {8.3, 8.2, 14.3}};
  ParticleSet particles;
  for (int p = 0; p < 2; ++p) particles.add(p + 1, rest[p], {0, 0, 0}, R);
  SphereCoupling coupling(*solver);
  coupling.map_and_refill(particles.view());
  const auto& layout = solver->layout();
  const std::size_t gap = layout.cell(8, 8, 10);
  auto& f = solver->populations();
  const double j0 = 0.1;
  const auto& type = solver->node_types();
  int gap_nodes = 0;
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) {
      const std::size_t cell = layout.cell(i, j, 10);
      if (type[cell] != lbm::kFluid || type[layout.cell(i, j, 9)] == lbm::kFluid ||
          type[layout.cell(i, j, 11)] == lbm::kFluid)
        continue;
      ++gap_nodes;
      for (int q = 0; q < L::Q; ++q)
        f.at(q, cell) = static_cast<lbm::Real>(f.at(q, cell) + 3.0 * L::w[q] * L::c[q][2] * j0);
    }
  EXPECT_GE(gap_nodes, 1);
  // A deposited particle of the paper's table at 7.1 cells per d (d-unit reading): mass
  // 2.3 * 4/3 pi R^3, contact stiffness 0.1 * 7.1^3, damping ratio 0.25; 100 substeps.
  const double mass = 2.3 * 4.0 / 3.0 * M_PI * R * R * R, k = 0.1 * 7.1 * 7.1 * 7.1;
  const double damping = 2.0 * 0.25 * std::sqrt(k * mass);
  const int substeps = 100;
  const double dt = 1.0 / substeps;
  double z[2] = {rest[0][2], rest[1][2]}, v[2] = {0.0, 0.0};
  Vec3 last[2] = {{0, 0, 0}, {0, 0, 0}};
  GapRun run;
  for (int t = 0; t < steps; ++t) {
    coupling.step(particles.view());
    const double jz = solver->density(gap) * solver->velocity(gap)[2];
    if (t == 0) run.first = std::abs(jz);
    run.largest = std::max(run.largest, std::abs(jz));
    run.last = std::abs(jz);
    run.largest_speed = std::max(run.largest_speed, std::abs(solver->velocity(gap)[2]));
    for (int p = 0; p < 2; ++p) {
      const double force = coupling.force(p)[2], start = z[p];
      for (int s = 0; s < substeps; ++s) {
        v[p] += (force - k * (z[p] - rest[p][2]) - damping * v[p]) / mass * dt;
        z[p] += v[p] * dt;
      }
      const Vec3 step_velocity{0.0, 0.0, z[p] - start};
      const Vec3 seen = two_step_mean ? wall_velocity_of_steps(step_velocity, t > 0 ? &last[p] : nullptr)
                                      : step_velocity;
      last[p] = step_velocity;
      particles.set_position(p, {rest[p][0], rest[p][1], z[p]});
      particles.set_velocity(p, seen);
    }
  }
  return run;
}

}  // namespace

TEST(GapMode, OneStepVelocitiesPumpTheModeTwoStepMeansDoNot) {
  const int steps = 1500;
  const GapRun one = run_gap(false, steps), two = run_gap(true, steps);
  std::printf("gap node |rho u_z| over %d steps: one-step velocity %.4f -> largest %.4f (last %.4f, "
              "speed %.3f); two-step mean %.4f -> largest %.4f (last %.4f)\n",
              steps, one.first, one.largest, one.last, one.largest_speed, two.first, two.largest, two.last);
  // The mode is there (born with the seeded 0.1) in both.
  EXPECT_GT(one.first, 0.09);
  EXPECT_GT(two.first, 0.09);
  // With the one-step velocity it grows (measured 0.097 -> 0.114 over 1500 steps, still
  // growing: the mechanism; in the clogged pore, where more surfaces and the lubrication
  // couple in, ten times faster), with the two-step mean it does not (0.097 -> at most
  // 0.099, the neighbouring gap nodes exchanging theirs).
  EXPECT_GT(one.largest, 1.10 * one.first);
  EXPECT_GE(one.last, one.largest);
  EXPECT_LT(two.largest, 1.04 * two.first);
}

TEST(GapMode, WallVelocityOfStepsIsTheTwoStepMean) {
  const Vec3 last{0.3, -0.1, 0.02}, before{-0.3, 0.1, 0.04};
  const Vec3 mean = wall_velocity_of_steps(last, &before);
  EXPECT_DOUBLE_EQ(mean[0], 0.0);  // an alternating displacement does not reach the fluid
  EXPECT_DOUBLE_EQ(mean[1], 0.0);
  EXPECT_DOUBLE_EQ(mean[2], 0.03);
  EXPECT_EQ(wall_velocity_of_steps(last, nullptr), last);  // a particle's first step
}
