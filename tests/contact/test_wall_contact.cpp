#include <gtest/gtest.h>

#include <cmath>

#include "contact/wall_contact.h"

using namespace contact;

TEST(WallContact, OverlapGivesDashDotRepulsion) {
  WallContactParams p;
  WallContactInput in;
  in.normal = {0, 0, 1};
  in.gap = -0.01;
  in.radius = 1.0;
  in.mass = 2.0;
  in.velocity = {0, 0, -0.1};
  in.dt = 0.01;
  const auto r = wall_contact_force(p, in);
  const double k_q = 0.5 * std::sqrt(p.normal.k_n * 2.0);  // paper table, zeta = 0.25
  EXPECT_NEAR(r.force.z, 0.1 * 0.01 + k_q * 0.1, 1e-15);
  EXPECT_TRUE(r.active);
}

TEST(WallContact, AdhesionPullsTowardsTheWallWithinRange) {
  WallContactParams p;
  p.adhesion.k_a = 0.5;
  WallContactInput in;
  in.normal = {1, 0, 0};
  in.gap = 0.02;
  in.radius = 1.0;
  in.mass = 1.0;
  in.dt = 0.01;
  EXPECT_NEAR(wall_contact_force(p, in).force.x, -0.02 * 0.5 * 1.0, 1e-15);
  in.gap = 0.031;
  const auto r = wall_contact_force(p, in);
  EXPECT_EQ(r.force.x, 0.0);
  EXPECT_FALSE(r.active);
}

TEST(WallContact, FrictionOpposesSlidingAndIsCapped) {
  WallContactParams p;
  p.friction.mu = 0.1;
  WallContactInput in;
  in.normal = {0, 0, 1};
  in.gap = -0.1;
  in.radius = 1.0;
  in.mass = 1.0;
  in.velocity = {5.0, 0, 0};
  in.dt = 0.1;
  const auto r = wall_contact_force(p, in);
  EXPECT_NEAR(r.force.x, -0.1 * p.normal.k_n * 0.1, 1e-15);
  EXPECT_TRUE(r.sliding);
}
