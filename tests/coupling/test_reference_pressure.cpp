// The reference pressure's share of the momentum exchange (coupling/force/momentum_exchange.h):
// a sphere resting on a wall at zero gap in fluid at rest (rho0 everywhere) feels nothing
// with the share removed (every link's populations are the reference ones), and with it kept
// (the paper's Eq. 2 read literally) the reference pressure p0 = rho0/3 on the surface that
// has no links, the part in contact with the wall: it is pressed into the wall. A sphere
// away from walls feels nothing either way (its link set is closed).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cases/serial_flow.h"
#include "coupling/sphere_coupling.h"

using namespace coupling;

namespace {

Vec3 force_at_rest(double centre_z, ReferencePressure reference) {
  lbm::VoxelGeometry g({16, 16, 16});
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) g.set_solid(i, j, 0, true);  // the wall, its face at z = 0.5
  lbm::FluidParameters p;
  p.tau = 1.0;
  p.magic = 3.0 / 16.0;
  p.periodic = {true, true, false};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  ParticleSet particles;
  particles.add(1, {8.2, 8.3, centre_z}, {0, 0, 0}, 4.0);
  SphereCouplingOptions options;
  options.reference_pressure = reference;
  SphereCoupling coupling(solver, options);
  coupling.step(particles.view());
  return coupling.force(0);
}

}  // namespace

TEST(ReferencePressure, RemovedOrKeptOnASphereTouchingAWall) {
  const double touching = 0.5 + 4.0, free = 8.0;
  const Vec3 removed = force_at_rest(touching, ReferencePressure::kRemoved);
  const Vec3 kept = force_at_rest(touching, ReferencePressure::kKept);
  const Vec3 kept_free = force_at_rest(free, ReferencePressure::kKept);
  std::printf("sphere R = 4 on a wall in fluid at rest: force removed (%.3g, %.3g, %.3g), kept (%.4g, %.4g, "
              "%.4g); away from the wall, kept (%.3g, %.3g, %.3g)\n",
              removed[0], removed[1], removed[2], kept[0], kept[1], kept[2], kept_free[0], kept_free[1],
              kept_free[2]);
  for (int a = 0; a < 3; ++a) {
    EXPECT_LT(std::abs(removed[a]), 1e-12);
    EXPECT_LT(std::abs(kept_free[a]), 1e-12);
  }
  // Kept: pressed into the wall (-z) by p0 times the projected area of its unlinked surface,
  // a few cells^2 for R = 4 at zero gap; nothing sideways.
  EXPECT_LT(kept[2], -0.5);
  EXPECT_LT(std::abs(kept[0]), 1e-3 * std::abs(kept[2]));
  EXPECT_LT(std::abs(kept[1]), 1e-3 * std::abs(kept[2]));
}
