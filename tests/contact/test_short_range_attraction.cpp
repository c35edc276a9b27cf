#include <gtest/gtest.h>

#include "contact/pair_contact.h"
#include "contact/short_range_attraction.h"

using namespace contact;

TEST(Cohesion, LinearInGapWithinRange) {
  CohesionParams p{0.1};
  const double ri = 3.0, rj = 2.0, a_star = ri * rj / (ri + rj);
  EXPECT_DOUBLE_EQ(cohesion_force(p, 0.1, ri, rj), 0.1 * 0.1 * a_star);
  EXPECT_DOUBLE_EQ(cohesion_range(p, ri, rj), 0.03 * 5.0);
  EXPECT_DOUBLE_EQ(cohesion_force(p, 0.15, ri, rj), max_cohesion_force(p, ri, rj));
  EXPECT_DOUBLE_EQ(max_cohesion_force(p, ri, rj), 0.03 * 0.1 * ri * rj);
}

TEST(Cohesion, ZeroInOverlapAndBeyondRange) {
  CohesionParams p{0.1};
  EXPECT_EQ(cohesion_force(p, -0.01, 1.0, 1.0), 0.0);
  EXPECT_EQ(cohesion_force(p, 0.0601, 1.0, 1.0), 0.0);
  EXPECT_EQ(cohesion_force(p, 0.0, 1.0, 1.0), 0.0);
}

TEST(Adhesion, LinearInGapWithinRange) {
  AdhesionParams p{0.2};
  EXPECT_DOUBLE_EQ(adhesion_force(p, 0.05, 2.0), 0.05 * 0.2 * 2.0);
  EXPECT_DOUBLE_EQ(adhesion_range(p, 2.0), 0.06);
  EXPECT_EQ(adhesion_force(p, 0.0601, 2.0), 0.0);
  EXPECT_EQ(adhesion_force(p, -0.001, 2.0), 0.0);
  EXPECT_DOUBLE_EQ(max_adhesion_force(p, 2.0), 0.03 * 0.2 * 4.0);
}

TEST(PairContact, ContinuousThroughContactAndAttractiveInRange) {
  PairContactParams p;
  PairContactInput in{-1e-12, 0.0, 1.0, 1.0, 1.0};
  EXPECT_NEAR(pair_normal_force(p, in), 0.0, 1e-12);
  in.gap = 1e-12;
  EXPECT_NEAR(pair_normal_force(p, in), 0.0, 1e-12);
  in.gap = 0.03;
  EXPECT_LT(pair_normal_force(p, in), 0.0);
  EXPECT_TRUE(pair_bonded(p, 0.06, 1.0, 1.0));
  EXPECT_FALSE(pair_bonded(p, 0.0601, 1.0, 1.0));
  in.gap = 0.0601;
  EXPECT_EQ(pair_normal_force(p, in), 0.0);
}
