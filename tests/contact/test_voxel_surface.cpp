#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "contact/voxel_surface.h"
#include "contact/wall_contact.h"

using namespace contact;

namespace {
// A floor of solid voxels k <= floor_top in a box of n^3 voxels.
lbm::VoxelGeometry floor_geometry(int n, int floor_top, double spacing,
                                  std::array<double, 3> origin) {
  lbm::VoxelGeometry g({n, n, n}, spacing, origin);
  for (int k = 0; k <= floor_top; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) g.set_solid(i, j, k, true);
  return g;
}

Vec3 total_wall_force(const lbm::VoxelGeometry& g, Vec3 centre, double radius, Vec3 velocity) {
  WallContactParams params;
  params.adhesion.k_a = 0.1;
  std::vector<SurfacePoint> points;
  find_surface_points(g, centre, wall_contact_reach(params, radius), points);
  Vec3 total;
  for (const SurfacePoint& p : points) {
    WallContactInput in;
    in.normal = p.normal;
    in.gap = p.distance - radius;
    in.radius = radius;
    in.mass = 1.0;
    in.velocity = velocity;
    in.dt = 0.01;
    total += wall_contact_force(params, in).force;
  }
  return total;
}
}  // namespace

TEST(VoxelSurface, FlatWallGivesOneContactEverywhere) {
  const double h = 0.7;
  const auto g = floor_geometry(16, 3, h, {0.1, -0.2, 0.3});
  const double top = 0.3 + 3.5 * h;  // top face of the floor
  const double radius = 1.6;
  std::vector<SurfacePoint> points;
  for (int s = 0; s < 100; ++s) {
    const double x = 0.1 + 4.0 * h + 5.0 * h * s / 99.0;  // across 5 voxels, faces included
    const Vec3 centre{x, -0.2 + 7.3 * h, top + radius - 0.01};
    find_surface_points(g, centre, radius + 0.1, points);
    ASSERT_EQ(points.size(), 1u) << "x = " << x;
    EXPECT_NEAR(points[0].distance, radius - 0.01, 1e-12);
    EXPECT_NEAR(points[0].normal.z, 1.0, 1e-15);
  }
}

TEST(VoxelSurface, SlidingAlongAFlatWallFeelsASmoothForce) {
  const double h = 1.0;
  const auto g = floor_geometry(20, 4, h, {0, 0, 0});
  const double radius = 3.5, top = 4.5;
  for (double gap : {-0.05, 0.02}) {  // overlapping (repulsion + friction), adhering
    const Vec3 reference = total_wall_force(g, {8.0, 10.0, top + radius + gap}, radius, {0.1, 0, 0});
    for (int s = 0; s < 100; ++s) {
      const Vec3 c{8.0 + 4.0 * s / 99.0 + 1e-3, 10.0 + 0.5 * s / 99.0, top + radius + gap};
      const Vec3 f = total_wall_force(g, c, radius, {0.1, 0, 0});
      EXPECT_LE(norm(f - reference), 1e-9 * norm(reference)) << "s " << s << " gap " << gap;
    }
  }
}

TEST(VoxelSurface, InnerCornerGivesTwoContacts) {
  // Floor (k <= 3) and a side wall (i >= 12): a sphere in the concave edge touches both.
  lbm::VoxelGeometry g = floor_geometry(16, 3, 1.0, {0, 0, 0});
  for (int k = 0; k < 16; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 12; i < 16; ++i) g.set_solid(i, j, k, true);
  const double radius = 2.0;
  std::vector<SurfacePoint> points;
  find_surface_points(g, {11.5 - radius + 0.01, 7.3, 3.5 + radius - 0.01}, radius + 0.1, points);
  ASSERT_EQ(points.size(), 2u);
  int floor_hits = 0, wall_hits = 0;
  for (const auto& p : points) {
    EXPECT_NEAR(p.distance, radius - 0.01, 1e-12);
    if (std::abs(p.normal.z - 1.0) < 1e-12) ++floor_hits;
    if (std::abs(p.normal.x + 1.0) < 1e-12) ++wall_hits;
  }
  EXPECT_EQ(floor_hits, 1);
  EXPECT_EQ(wall_hits, 1);
}

TEST(VoxelSurface, BoxCornerGivesThreeContacts) {
  lbm::VoxelGeometry g({10, 10, 10}, 1.0);
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i)
        if (i == 0 || j == 0 || k == 0) g.set_solid(i, j, k, true);
  std::vector<SurfacePoint> points;
  find_surface_points(g, {0.5 + 1.0, 0.5 + 1.0, 0.5 + 1.0}, 1.05, points);
  EXPECT_EQ(points.size(), 3u);
}

TEST(VoxelSurface, OuterEdgeNormalPointsFromTheEdge) {
  // A step: solid for k <= 3 and i <= 7. The sphere sits diagonally beyond the top edge.
  lbm::VoxelGeometry g({16, 16, 16}, 1.0);
  for (int k = 0; k <= 3; ++k)
    for (int j = 0; j < 16; ++j)
      for (int i = 0; i <= 7; ++i) g.set_solid(i, j, k, true);
  const Vec3 edge{7.5, 8.2, 3.5};
  const Vec3 centre = edge + Vec3{1.0, 0.0, 1.0};
  std::vector<SurfacePoint> points;
  find_surface_points(g, centre, 1.6, points);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].distance, std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(points[0].normal.x, 1.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(points[0].normal.z, 1.0 / std::sqrt(2.0), 1e-12);
  EXPECT_NEAR(points[0].point.x, 7.5, 1e-12);
  EXPECT_NEAR(points[0].point.z, 3.5, 1e-12);
}

TEST(VoxelSurface, CentreInsideASolidVoxelIsPushedOutOfTheNearestExposedFace) {
  const auto g = floor_geometry(10, 3, 1.0, {0, 0, 0});
  std::vector<SurfacePoint> points;
  find_surface_points(g, {5.0, 5.0, 3.3}, 1.0, points);
  ASSERT_EQ(points.size(), 1u);
  EXPECT_NEAR(points[0].distance, -0.2, 1e-12);
  EXPECT_NEAR(points[0].normal.z, 1.0, 1e-15);
}

TEST(VoxelSurface, NothingOutOfReach) {
  const auto g = floor_geometry(10, 3, 1.0, {0, 0, 0});
  std::vector<SurfacePoint> points;
  find_surface_points(g, {5.0, 5.0, 6.0}, 2.4, points);
  EXPECT_TRUE(points.empty());
}

// The pore scene of the paper: a block with a cylindrical hole, voxels of 0.5.
lbm::VoxelGeometry pore_block_geometry() {
  lbm::VoxelGeometry g({30, 21, 21}, 0.5, {-1.0, 0.2, 0.0});
  for (int k = 0; k < 21; ++k)
    for (int j = 0; j < 21; ++j)
      for (int i = 10; i < 20; ++i) {
        const double dy = j - 10.0, dz = k - 10.0;
        if (dy * dy + dz * dz >= 36.0) g.set_solid(i, j, k, true);
      }
  return g;
}

TEST(VoxelSurface, AcceleratedQueryEqualsFullScan) {
  // The pore scene of the paper, probed on a grid of centres.
  const lbm::VoxelGeometry g = pore_block_geometry();
  const VoxelSurface surface(g);
  std::vector<SurfacePoint> full, fast;
  int compared = 0, with_contacts = 0;
  for (double x = -1.2; x < 14.0; x += 0.37)
    for (double y = 0.0; y < 10.5; y += 0.41)
      for (double z = 0.0; z < 10.5; z += 0.53) {
        find_surface_points(g, {x, y, z}, 1.1, full);
        surface.find({x, y, z}, 1.1, fast);
        ASSERT_EQ(full.size(), fast.size());
        double sum_full = 0.0, sum_fast = 0.0;
        for (const auto& p : full) sum_full += p.distance + 3.0 * p.normal.x + 7.0 * p.normal.z;
        for (const auto& p : fast) sum_fast += p.distance + 3.0 * p.normal.x + 7.0 * p.normal.z;
        EXPECT_NEAR(sum_full, sum_fast, 1e-12);
        ++compared;
        if (!full.empty()) ++with_contacts;
      }
  EXPECT_GT(with_contacts, compared / 10);
}

// A particle's candidate list (contact/wall_candidates.h) gives the points of the scan, in
// the same order and to the last bit, while it is reused and each time it is rebuilt: a
// centre walking through the pore scene, 0.01 voxel per step.
TEST(VoxelSurface, CandidateListGivesThePointsOfTheScan) {
  const lbm::VoxelGeometry g = pore_block_geometry();
  const VoxelSurface surface(g);
  WallCandidates candidates;
  std::vector<SurfacePoint> scanned, listed;
  int with_contacts = 0;
  for (int step = 0; step < 3000; ++step) {
    const double t = 0.005 * step;
    const Vec3 centre{2.0 + t * 0.4, 5.2 + 2.3 * std::cos(t), 5.0 + 2.3 * std::sin(t)};
    surface.find(centre, 1.1, scanned);
    surface.find(centre, 1.1, listed, candidates);
    ASSERT_EQ(scanned.size(), listed.size()) << "step " << step;
    for (std::size_t p = 0; p < scanned.size(); ++p) {
      ASSERT_EQ(scanned[p].distance, listed[p].distance);
      for (int a = 0; a < 3; ++a) {
        ASSERT_EQ(scanned[p].point[a], listed[p].point[a]);
        ASSERT_EQ(scanned[p].normal[a], listed[p].normal[a]);
      }
    }
    if (!scanned.empty()) ++with_contacts;
  }
  EXPECT_GT(with_contacts, 300);
}
