// The halo exchange's per-axis flag (coupling::whole_ghost_axes): raised exactly when a
// sphere covers a node on the second plane from a face the exchange fills, with
// Mei-Luo-Shyy; and the coupled step, which then sends the ghost nodes' moments besides the
// crossing five (SphereCoupling::exchange_halo), equals, bit for bit, the step with all 19
// populations exchanged, while the crossing five alone would differ. Serial, periodic
// axes (a rank alone on a periodic axis exchanges with itself); the 2-rank case is in
// tests/lbm_parallel/test_sphere_halo_mpi.cpp.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "cases/serial_flow.h"
#include "cases/staged_step.h"
#include "coupling/boundary/ghost_moment_cells.h"
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
// face plane x = 0 have fractions below 1/2 (Mei-Luo-Shyy reads the ghost x = -1), with the
// ghost moments on the whole planes and only near the spheres (set_particle_reach). The
// crossing five alone change the result: the case does read a whole ghost node.
class WholeGhostAxesMoments : public ::testing::TestWithParam<bool> {};

TEST_P(WholeGhostAxesMoments, CoupledStepEqualsTheExchangeOfAll19) {
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
  if (GetParam()) c_run.set_particle_reach(1e9, 2.2);  // the view holds every particle
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

INSTANTIATE_TEST_SUITE_P(WholePlanesAndNearSpheres, WholeGhostAxesMoments, ::testing::Bool());

// The cells near the spheres: of the planes the sweeps send and fill along a marked axis,
// exactly those within R + kGhostMomentMargin of a sphere's centre (minimum image), against
// a test of every cell of those planes.
TEST(GhostMomentCells, AreTheCellsOfTheExchangedPlanesNearASphere) {
  const auto solver = cases::make_solver({16, 12, 10}, {true, true, false});
  ParticleSet particles;
  particles.add(1, {1.2, 6.3, 4.7}, {0.0, 0.0, 0.0}, 2.2);   // near x = 0
  particles.add(2, {14.9, 0.4, 6.1}, {0.0, 0.0, 0.0}, 1.7);  // near x = 15 and y = 0, 11
  particles.add(3, {8.0, 6.0, 5.0}, {0.0, 0.0, 0.0}, 2.0);   // near no face plane
  SphereMapping mapping(solver->layout(), PeriodicBox::from(solver->decomposition()));
  mapping.update(particles.view(), solver->node_types());
  GhostMomentCells cells;
  ghost_moment_cells(mapping, particles.view(), *solver, {true, true, false}, cells);
  const lbm::BlockLayout& layout = solver->layout();
  std::vector<std::size_t> want_sent, want_received;
  for (int a = 0; a < 2; ++a)
    for (int side = 0; side < 2; ++side) {
      const int planes[2] = {side == 0 ? 0 : layout.size(a) - 1, side == 0 ? -1 : layout.size(a)};
      for (int which = 0; which < 2; ++which) {
        const int b = a == 0 ? 1 : 0, c = a == 2 ? 1 : 2;
        int ijk[3];
        ijk[a] = planes[which];
        for (int v = -1; v <= layout.size(c); ++v)
          for (int u = -1; u <= layout.size(b); ++u) {
            ijk[b] = u;
            ijk[c] = v;
            const std::size_t cell = layout.cell(ijk[0], ijk[1], ijk[2]);
            bool near = false;
            for (std::size_t p = 0; p < particles.size(); ++p) {
              const Vec3 d = mapping.box().displacement(particles.view().x(p), mapping.node_position(cell));
              near = near || std::sqrt(dot(d, d)) <= particles.view().r(p) + kGhostMomentMargin;
            }
            if (near) (which == 0 ? want_sent : want_received).push_back(cell);
          }
      }
    }
  auto unique = [](std::vector<std::size_t> v) {
    std::sort(v.begin(), v.end());
    v.erase(std::unique(v.begin(), v.end()), v.end());
    return v;
  };
  EXPECT_EQ(unique(cells.sent), unique(want_sent));
  EXPECT_EQ(unique(cells.received), unique(want_received));
  EXPECT_GT(unique(cells.sent).size(), 20u);
  EXPECT_LT(unique(cells.sent).size(), 2u * (14u * 12u + 18u * 12u));  // fewer than the whole planes
}
