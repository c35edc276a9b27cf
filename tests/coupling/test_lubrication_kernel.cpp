// The lubrication kernel (coupling/lubrication/lubrication_kernel.h) in host units, over a
// pair list and followed nearest walls, against the lattice-unit law it scales.
#include <gtest/gtest.h>

#include <vector>

#include "contact/voxel_surface.h"
#include "coupling/lubrication/lubrication_kernel.h"
#include "lbm/voxel_geometry.h"

using namespace coupling;

namespace {
// Host units: dx = 0.5 length units, dt_fluid = 0.2 time units, a force unit of 3.
const LubricationScales kScales{0.5, 0.2, 3.0};
const double kVelocityToLattice = 0.2 / 0.5;
}  // namespace

TEST(LubricationKernel, PairForceIsTheLatticeLawScaledAndGoesOnlyToOwnedParticles) {
  LubricationParameters p;  // cutoff 2/3 cell
  const LubricationKernel kernel(p, kScales);
  EXPECT_DOUBLE_EQ(kernel.cutoff(), p.cutoff * 0.5);
  ParticleSet set;
  set.add(1, {0.0, 0.0, 0.0}, {0.01, 0.0, 0.0}, 1.0);
  set.add(2, {2.1, 0.0, 0.0}, {-0.01, 0.0, 0.0}, 1.0);  // gap 0.1 < 1/3: lubricated
  set.add(3, {0.0, 2.5, 0.0}, {0.0, -0.02, 0.0}, 1.0, false);  // a ghost, gap 0.5: beyond the cutoff
  set.add(4, {0.0, -2.2, 0.0}, {0.0, 0.0, 0.0}, 1.0, false);   // a ghost, gap 0.2
  set.num_owned = 2;
  std::vector<double> force(3 * set.size(), 0.0);
  kernel.add_pair_forces(set.view(), {{0, 1}, {0, 2}, {0, 3}}, force.data());

  const LubricationCorrection law(p);
  const Vec3 F01 = law.pair_force(2.0, 2.0, {4.2, 0.0, 0.0}, {0.01 * kVelocityToLattice, 0, 0},
                                  {-0.01 * kVelocityToLattice, 0, 0});
  const Vec3 F03 = law.pair_force(2.0, 2.0, {0.0, -4.4, 0.0}, {0.01 * kVelocityToLattice, 0, 0}, {0, 0, 0});
  EXPECT_LT(F01[0], 0.0);  // approaching: pushed apart
  EXPECT_NEAR(force[0], (F01[0] + F03[0]) * 3.0, 1e-15);
  EXPECT_NEAR(force[1], (F01[1] + F03[1]) * 3.0, 1e-15);
  EXPECT_NEAR(force[3], -F01[0] * 3.0, 1e-15);
  for (int k = 6; k < 12; ++k) EXPECT_EQ(force[k], 0.0) << "ghost slot " << k;
}

TEST(LubricationKernel, WallForceFollowsTheNearestWallAlongItsNormal) {
  // A voxel floor: solid for z <= 2 (node spacing 0.5), surface at z = 2.5 * 0.5 = 1.25.
  lbm::VoxelGeometry floor({12, 12, 12}, 0.5);
  for (int k = 0; k <= 2; ++k)
    for (int j = 0; j < 12; ++j)
      for (int i = 0; i < 12; ++i) floor.set_solid(i, j, k, true);
  const contact::VoxelSurface surface(floor);
  std::vector<contact::SurfacePoint> scratch;
  const double R = 1.0;
  const Vec3 searched{3.0, 3.0, 1.25 + R + 0.2};
  const NearestWall wall = find_nearest_wall(surface, searched, R + 1.0, scratch);
  ASSERT_TRUE(wall.known);
  EXPECT_NEAR(wall.distance, R + 0.2, 1e-12);
  EXPECT_NEAR(wall.normal[2], 1.0, 1e-12);
  EXPECT_FALSE(find_nearest_wall(surface, {3.0, 3.0, 5.0}, R + 1.0, scratch).known);

  // Within the fluid step the particle moved 0.1 closer: gap 0.1 (0.2 cells < cutoff 2/3).
  ParticleSet set;
  set.add(1, {3.05, 3.0, searched[2] - 0.1}, {0.0, 0.0, -0.01}, R);
  EXPECT_NEAR(wall.distance_from(set.view().x(0)), R + 0.1, 1e-12);
  LubricationParameters p;
  const LubricationKernel kernel(p, kScales);
  std::vector<double> force(3, 0.0);
  kernel.add_wall_forces(set.view(), [&](std::size_t) -> const NearestWall& { return wall; }, force.data());
  WallDistance lattice_wall;
  lattice_wall.distance = (R + 0.1) / 0.5;
  lattice_wall.normal = {0.0, 0.0, 1.0};
  const Vec3 expected = LubricationCorrection(p).wall_force(R / 0.5, {0.0, 0.0, -0.01 * kVelocityToLattice}, lattice_wall);
  EXPECT_GT(force[2], 0.0);
  EXPECT_NEAR(force[2], expected[2] * 3.0, 1e-12);

  // An unknown wall adds nothing.
  const NearestWall none;
  std::vector<double> nothing(3, 0.0);
  kernel.add_wall_forces(set.view(), [&](std::size_t) -> const NearestWall& { return none; }, nothing.data());
  EXPECT_EQ(nothing[2], 0.0);
}
