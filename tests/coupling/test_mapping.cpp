// Mapping and links: covered node count, exact link fractions, periodic wrap.
#include <gtest/gtest.h>

#include <cstdio>

#include "cases/serial_flow.h"
#include "coupling/boundary/sphere_links.h"
#include "coupling/mapping/sphere_mapping.h"
#include "coupling/sphere_coupling.h"
#include "lbm/d3q19.h"

using namespace coupling;

TEST(SphereMapping, LinkFractionIsTheExactIntersection) {
  const int c[3] = {1, 1, 0};
  const Vec3 d{-3.0, -3.2, 0.4};  // node relative to centre
  const double R = 3.5;
  const double s = link_fraction(d, c, R);
  const Vec3 y{d[0] + s, d[1] + s, d[2]};
  EXPECT_NEAR(std::sqrt(dot(y, y)), R, 1e-12);
  EXPECT_GT(s, 0.0);
  EXPECT_LE(s, 1.0);
}

TEST(SphereMapping, CoveredNodesAndLinksOfOneSphere) {
  auto solver = cases::make_solver({16, 16, 16}, {true, true, true});
  ParticleSet particles;
  const double R = 4.0;
  particles.add(1, {7.3, 8.1, 7.7}, {0, 0, 0}, R);
  SphereCoupling coupling(*solver);
  coupling.map_and_refill(particles.view());
  const std::size_t covered = coupling.mapping().moving_cells().size();
  const double volume = 4.0 / 3.0 * cases::kPi * R * R * R;
  std::printf("R = 4: %zu covered nodes, sphere volume %.1f\n", covered, volume);
  EXPECT_NEAR(double(covered), volume, 0.06 * volume);
  SphereLinks links;
  build_sphere_links(coupling.mapping(), particles.view(), solver->node_types(), links);
  ASSERT_FALSE(links.links.empty());
  for (std::size_t l = 0; l < links.links.size(); ++l) {
    const auto& link = links.links[l];
    EXPECT_EQ(solver->node_types()[link.fluid_cell], lbm::kFluid);
    EXPECT_GT(link.fraction, 0.0);
    EXPECT_LE(link.fraction, 1.0);
    EXPECT_NEAR(std::sqrt(dot(links.arm[l], links.arm[l])), R, 1e-9);
  }
}

TEST(SphereMapping, PeriodicWrapCoversGhostsAndMovesCleanly) {
  auto solver = cases::make_solver({12, 12, 12}, {true, true, true});
  ParticleSet particles;
  particles.add(1, {0.2, 6.0, 6.0}, {0, 0, 0}, 3.0);
  SphereCoupling coupling(*solver);
  coupling.map_and_refill(particles.view());
  const auto& L = solver->layout();
  // Covered on both sides of the periodic x face, and in the ghost layer.
  EXPECT_EQ(solver->node_types()[L.cell(11, 6, 6)], lbm::kMoving);
  EXPECT_EQ(solver->node_types()[L.cell(2, 6, 6)], lbm::kMoving);
  EXPECT_EQ(solver->node_types()[L.cell(-1, 6, 6)], lbm::kMoving);
  const std::size_t before = coupling.mapping().moving_cells().size();
  // Move by -0.6 cells across the face: node 3 is uncovered, refilled and fluid again.
  particles.set_position(0, {-0.4, 6.0, 6.0});
  coupling.map_and_refill(particles.view());
  EXPECT_EQ(solver->node_types()[L.cell(3, 6, 6)], lbm::kFluid);
  EXPECT_EQ(solver->node_types()[L.cell(9, 6, 6)], lbm::kMoving);
  EXPECT_NEAR(double(coupling.mapping().moving_cells().size()), double(before), 0.1 * before);
  EXPECT_GT(coupling.last_mass_change().num_refilled, 0);
  EXPECT_GT(coupling.last_mass_change().num_covered, 0);
}
