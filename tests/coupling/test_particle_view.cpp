// The owning particle list behind a view (coupling/particle_view.h): owned entries before
// ghosts, angular velocities exposed only for a rotating view, and a list cleared and
// refilled (as a host refills it every fluid step) giving the view a fresh one gives.
#include <gtest/gtest.h>

#include "coupling/particle_view.h"

using namespace coupling;

namespace {
void fill(ParticleSet& set) {
  set.add(7, {1.0, 2.0, 3.0}, {0.1, 0.0, 0.0}, {0.0, 0.0, 0.5}, 2.5);
  set.add(9, {4.0, 5.0, 6.0}, {0.0, 0.2, 0.0}, 1.5, false);
}
}  // namespace

TEST(ParticleSet, ViewShowsOwnedBeforeGhostsAndSpinOnlyWhenRotating) {
  ParticleSet set;
  fill(set);
  const ParticleView still = set.view();
  EXPECT_EQ(still.num_owned, 1u);
  EXPECT_EQ(still.num_total, 2u);
  EXPECT_TRUE(still.is_owned(0));
  EXPECT_FALSE(still.is_owned(1));
  EXPECT_EQ(still.identifier(1), 9);
  EXPECT_EQ(still.x(1), (Vec3{4.0, 5.0, 6.0}));
  EXPECT_EQ(still.r(0), 2.5);
  EXPECT_EQ(still.omega(0), (Vec3{0.0, 0.0, 0.0}));
  const ParticleView spinning = set.view(true);
  EXPECT_EQ(spinning.omega(0), (Vec3{0.0, 0.0, 0.5}));
  EXPECT_EQ(spinning.omega(1), (Vec3{0.0, 0.0, 0.0}));  // added without a spin
  // v + omega x offset at the point one cell along x.
  EXPECT_EQ(spinning.surface_velocity(0, {1.0, 0.0, 0.0}), (Vec3{0.1, 0.5, 0.0}));
}

TEST(ParticleSet, ClearedAndRefilledEqualsAFreshSet) {
  ParticleSet fresh, reused;
  fill(fresh);
  reused.add(1, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0);
  reused.add(2, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0);
  reused.add(3, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.0}, 1.0);
  reused.clear();
  EXPECT_EQ(reused.size(), 0u);
  EXPECT_EQ(reused.view().num_owned, 0u);
  fill(reused);
  EXPECT_EQ(reused.num_owned, fresh.num_owned);
  EXPECT_EQ(reused.id, fresh.id);
  EXPECT_EQ(reused.position, fresh.position);
  EXPECT_EQ(reused.velocity, fresh.velocity);
  EXPECT_EQ(reused.angular_velocity, fresh.angular_velocity);
  EXPECT_EQ(reused.radius, fresh.radius);
}
