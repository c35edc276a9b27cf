#include <gtest/gtest.h>

#include <cmath>

#include "contact/pair_contact.h"
#include "contact/stability_limits.h"
#include "contact/wall_contact.h"

using namespace contact;

TEST(StabilityLimits, TimeStepIsATenthOfTheContactTime) {
  DashDotParams p{4.0, 0.0};
  const TimeStepLimit limit = time_step_limit(p, 1.0);
  EXPECT_EQ(limit.contact_time, contact_duration(p, 1.0));
  EXPECT_NEAR(limit.contact_time, M_PI / 2.0, 1e-14);  // pi / omega_0, omega_0 = 2
  EXPECT_DOUBLE_EQ(limit.max_time_step, limit.contact_time / 10.0);
}

TEST(StabilityLimits, PairOfTheLightestParticlesHasHalfTheirMass) {
  PairContactParams p;
  p.normal = {0.3, 0.25};
  EXPECT_EQ(pair_time_step_limit(p, 2.0).contact_time, contact_duration(p.normal, 1.0));
}

TEST(StabilityLimits, StifferWallSpringSetsTheWallLimit) {
  WallContactParams p;
  p.normal = {0.1, 0.25};
  p.friction.k_t = 0.05;  // softer: k_w sets it
  EXPECT_FALSE(wall_tangential_spring_is_stiffer(p));
  EXPECT_EQ(wall_stiffest_spring(p).k_n, 0.1);
  EXPECT_EQ(wall_time_step_limit(p, 3.0).contact_time, contact_duration(p.normal, 3.0));
  p.friction.k_t = 0.4;  // stiffer: k_t sets it, with the normal damping ratio
  EXPECT_TRUE(wall_tangential_spring_is_stiffer(p));
  EXPECT_EQ(wall_stiffest_spring(p).k_n, 0.4);
  EXPECT_EQ(wall_stiffest_spring(p).damping_ratio, 0.25);
  EXPECT_EQ(wall_time_step_limit(p, 3.0).contact_time,
            contact_duration(DashDotParams{0.4, 0.25}, 3.0));
  // Equal springs: the normal one is named.
  p.friction.k_t = 0.1;
  EXPECT_FALSE(wall_tangential_spring_is_stiffer(p));
}

TEST(StabilityLimits, OverlapSeverityThresholds) {
  EXPECT_EQ(overlap_severity(0.0), OverlapSeverity::kResolved);
  EXPECT_EQ(overlap_severity(kWarnOverlapRatio), OverlapSeverity::kResolved);
  EXPECT_EQ(overlap_severity(0.051), OverlapSeverity::kTooSoft);
  EXPECT_EQ(overlap_severity(kStopOverlapRatio), OverlapSeverity::kTooSoft);
  EXPECT_EQ(overlap_severity(0.51), OverlapSeverity::kPassingThrough);
  EXPECT_DOUBLE_EQ(kWarnOverlapRatio, 0.05);
  EXPECT_DOUBLE_EQ(kStopOverlapRatio, 0.5);
}
