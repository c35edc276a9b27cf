// The halo exchange's per-axis flag (coupling::whole_ghost_axes): raised exactly when a
// sphere covers a node on the second plane from a face the exchange fills, with
// Mei-Luo-Shyy; and the coupled step, which then sends the ghost nodes' moments besides the
// crossing five (SphereCoupling::exchange_halo), equals, bit for bit, the step with all 19
// populations exchanged, while the crossing five alone would differ. Serial, periodic
// axes (a rank alone on a periodic axis exchanges with itself); the 2-rank case is in
// tests/lbm_parallel/test_sphere_halo_mpi.cpp.
#include <gtest/gtest.h>

#include "cases/serial_flow.h"
#include "cases/staged_step.h"
#include "coupling/boundary/whole_ghost_axes.h"
#include "coupling/sphere_coupling.h"

using namespace coupling;

namespace {

std::array<long long, 3> axes_for(const lbm::FluidSolver& solver, const Vec3& centre, double R,
                                  lbm::MovingWallScheme scheme = lbm::MovingWallScheme::kMeiLuoShyy) {
  ParticleSet particles;
  particles.add(1, centre, {0.0, 0.0, 0.0}, R);
  SphereMapping mapping(solver.layout(), PeriodicBox::from(solver.decomposition()));
  mapping.update(particles.view(), solver.node_types());
  return whole_ghost_axes(mapping, scheme, solver);
}

using Axes = std::array<long long, 3>;

}  // namespace

TEST(WholeGhostAxes, RaisedForACoveredNodeOnTheSecondPlaneOfAnExchangedFace) {
  // 16 x 12 x 10, periodic along x only: the x faces are exchanged, the y and z ones not.
  const auto solver = cases::make_solver({16, 12, 10}, {true, false, false});
  const double R = 2.2;
  // Covers x = 1 (distance 1.9), not x = 0: the second plane from the low x face.
  EXPECT_EQ(axes_for(*solver, {2.9, 6.0, 5.0}, R), (Axes{1, 0, 0}));
  // Covers x = 2 ... 6: nothing on plane 1 or n - 2.
  EXPECT_EQ(axes_for(*solver, {3.9, 6.0, 5.0}, R), (Axes{0, 0, 0}));
  // Covers x = 10 ... 14: plane n - 2 of the high face.
  EXPECT_EQ(axes_for(*solver, {12.1, 6.0, 5.0}, R), (Axes{1, 0, 0}));
  // Covers the ghost x = -1 and x = 0 ... 2 (plane 1 too).
  EXPECT_EQ(axes_for(*solver, {0.5, 6.0, 5.0}, R), (Axes{1, 0, 0}));
  // Covers y = 1, the second plane from a wall face no exchange fills; z = 8 likewise.
  EXPECT_EQ(axes_for(*solver, {8.0, 2.9, 5.0}, R), (Axes{0, 0, 0}));
  EXPECT_EQ(axes_for(*solver, {8.0, 6.0, 6.1}, R), (Axes{0, 0, 0}));
  // Bouzidi and bounce-back read no whole ghost node.
  EXPECT_EQ(axes_for(*solver, {2.9, 6.0, 5.0}, R, lbm::MovingWallScheme::kBouzidi), (Axes{0, 0, 0}));
  EXPECT_EQ(axes_for(*solver, {2.9, 6.0, 5.0}, R, lbm::MovingWallScheme::kBounceBack), (Axes{0, 0, 0}));
}

TEST(WholeGhostAxes, EveryPeriodicAxisOfAnEdgeGhost) {
  // The sphere node (1, 1, k) of a link from (0, 0, k) along (1, 1, 0) reads the edge ghost
  // (-1, -1, k): both x and y are raised; z is not (no covered node on z = 1 or n - 2).
  const auto solver = cases::make_solver({12, 12, 12}, {true, true, true});
  EXPECT_EQ(axes_for(*solver, {2.6, 2.6, 6.0}, 2.2), (Axes{1, 1, 0}));
}

// The coupled step (SphereCoupling::step, the flags of whole_ghost_axes) against the same
// stages with all 19 populations exchanged: bit for bit, for a sphere whose links from the
// face plane x = 0 have fractions below 1/2 (Mei-Luo-Shyy reads the ghost x = -1). The
// crossing five alone change the result: the case does read a whole ghost node.
TEST(WholeGhostAxes, CoupledStepEqualsTheExchangeOfAll19) {
  const std::array<int, 3> dims{16, 12, 10};
  const std::array<bool, 3> periodic{true, true, false};
  const std::array<double, 3> force{2e-5, -1e-5, 0.0};
  auto run = cases::make_solver(dims, periodic, 0.8, force);
  auto all = cases::make_solver(dims, periodic, 0.8, force);
  auto crossing = cases::make_solver(dims, periodic, 0.8, force);
  // A non-uniform start, so that stale ghost values differ from fresh ones.
  auto state = [](int i, int j, int k) -> std::array<double, 4> {
    return {1.0 + 0.01 * std::sin(0.7 * i + 0.3 * j + 0.2 * k), 0.01 * std::cos(0.4 * j + 0.2 * k),
            0.005 * std::sin(0.6 * i + 0.9 * k), 0.004 * std::cos(0.8 * i - 0.5 * j)};
  };
  for (auto* s : {run.get(), all.get(), crossing.get()}) s->initialise_equilibrium(state);
  SphereCoupling c_run(*run), c_all(*all), c_crossing(*crossing);
  ParticleSet particles;
  // Surface at x = 0.2 ... 0.35 over the run: links from x = 0 into x = 1 with delta < 1/2.
  const Vec3 x0{2.4, 6.3, 4.7}, v{0.005, 0.002, -0.003};
  particles.add(1, x0, v, 2.2);
  long long raised = 0;
  for (int t = 0; t < 30; ++t) {
    for (int a = 0; a < 3; ++a) particles.position[a] = x0[a] + v[a] * t;
    c_run.step(particles.view());
    raised += c_run.ghost_moment_axes()[0];
    cases::staged_step(c_all, particles.view(), lbm::HaloPopulations::every());
    cases::staged_step(c_crossing, particles.view(), lbm::HaloPopulations::crossing());
    ASSERT_EQ(cases::max_population_difference(*run, *all), 0.0) << "step " << t;
    for (int a = 0; a < 3; ++a) {
      ASSERT_EQ(c_run.force(0)[a], c_all.force(0)[a]) << "step " << t;
      ASSERT_EQ(c_run.torque(0)[a], c_all.torque(0)[a]) << "step " << t;
    }
  }
  EXPECT_EQ(raised, 30);
  EXPECT_EQ(c_run.halo_counts().moments[2], 0);  // z is not periodic: never raised
  EXPECT_GT(cases::max_population_difference(*crossing, *all), 1e-9);
}
