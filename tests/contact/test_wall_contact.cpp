#include <gtest/gtest.h>

#include <cmath>

#include "contact/wall_contact.h"

using namespace contact;

namespace {
WallContactInput contact_input(Vec3 normal, double gap, double radius, double mass, Vec3 velocity,
                               double dt) {
  WallContactInput in;
  in.normal = normal;
  in.gap = gap;
  in.radius = radius;
  in.mass = mass;
  in.velocity = velocity;
  in.dt = dt;
  return in;
}
}  // namespace

TEST(WallContact, OverlapGivesDashDotRepulsion) {
  WallContactParams p;
  const auto r =
      wall_contact_force(p, contact_input({0, 0, 1}, -0.01, 1.0, 2.0, {0, 0, -0.1}, 0.01));
  const double k_q = 0.5 * std::sqrt(p.normal.k_n * 2.0);  // paper table, zeta = 0.25
  EXPECT_NEAR(r.force.z, 0.1 * 0.01 + k_q * 0.1, 1e-15);
  EXPECT_TRUE(r.active);
}

TEST(WallContact, AdhesionPullsTowardsTheWallWithinRange) {
  WallContactParams p;
  p.adhesion.k_a = 0.5;
  WallContactInput in = contact_input({1, 0, 0}, 0.02, 1.0, 1.0, {}, 0.01);
  EXPECT_NEAR(wall_contact_force(p, in).force.x, -0.02 * 0.5 * 1.0, 1e-15);
  in.gap = 0.031;
  const auto r = wall_contact_force(p, in);
  EXPECT_EQ(r.force.x, 0.0);
  EXPECT_FALSE(r.active);
}

TEST(WallContact, FrictionOpposesSlidingAndIsCapped) {
  WallContactParams p;
  p.friction.mu = 0.1;
  const auto r = wall_contact_force(p, contact_input({0, 0, 1}, -0.1, 1.0, 1.0, {5.0, 0, 0}, 0.1));
  EXPECT_NEAR(r.force.x, -0.1 * p.normal.k_n * 0.1, 1e-15);
  EXPECT_TRUE(r.sliding);
}

// The normal law is the pair contact's (test_shared_normal_law.cpp): exactly dash_dot_force
// in an overlap and exactly minus adhesion_force across a gap.
TEST(WallContact, OverlapIsExactlyTheDashDotForce) {
  WallContactParams p;
  p.normal = {0.37, 0.21};
  p.friction.mu = 0.0;  // the normal part alone
  const auto r =
      wall_contact_force(p, contact_input({0, 0, 1}, -0.013, 1.3, 2.7, {0, 0, -0.07}, 0.01));
  EXPECT_EQ(r.force.z, dash_dot_force(p.normal, {0.013, 0.07, 2.7}));
}

TEST(WallContact, GapIsExactlyTheAdhesionForce) {
  WallContactParams p;
  p.adhesion.k_a = 0.7;
  p.friction.mu = 0.0;
  for (double gap : {0.0, 0.001, 0.017, 0.038}) {
    const auto r =
        wall_contact_force(p, contact_input({0, 0, 1}, gap, 1.3, 2.7, {0, 0, 0.03}, 0.01));
    EXPECT_EQ(r.force.z, -adhesion_force(p.adhesion, gap, 1.3)) << gap;
    EXPECT_TRUE(r.active) << gap;
  }
}

// One call is one contact: its own spring in, the spring to keep out, so a wall model can
// sum any number of contacts, each with its own friction spring.
TEST(WallContact, EachContactCarriesItsOwnSpring) {
  WallContactParams p;
  p.friction.mu = 10.0;  // sticking
  WallContactInput in = contact_input({0, 0, 1}, -0.1, 1.0, 1.0, {0.2, 0, 0}, 0.1);
  const auto first = wall_contact_force(p, in);
  in.spring = first.spring;
  const auto second = wall_contact_force(p, in);
  EXPECT_NEAR(first.spring.x, 0.02, 1e-15);   // dt * slip
  EXPECT_NEAR(second.spring.x, 0.04, 1e-15);  // accumulated
  EXPECT_LT(second.force.x, first.force.x);   // a growing restoring force
  EXPECT_FALSE(second.sliding);
}
