// The pair style and the wall fix share one normal law: pair_normal_force is dash_dot_force
// in an overlap and cohesion across a gap, as wall_contact_force is the same dash_dot_force
// and adhesion (test_wall_contact.cpp). Exact equality, and exactly the formulas the pair
// style computed inline before, so its results stay bit-identical.
#include <gtest/gtest.h>

#include <cmath>

#include "contact/coulomb_friction.h"
#include "contact/pair_contact.h"

using namespace contact;

TEST(SharedNormalLaw, PairOverlapIsDashDot) {
  PairContactParams p;
  p.normal = {0.37, 0.21};
  const PairContactInput in{-0.013, -0.07, 1.1, 0.9, pair_effective_mass(2.0, 3.0)};
  EXPECT_EQ(pair_normal_force(p, in), dash_dot_force(p.normal, {0.013, 0.07, in.effective_mass}));
  // The formula the pair style computed before it called dash_dot_force (bit-identical).
  const double k_d = 2.0 * p.normal.damping_ratio * std::sqrt(p.normal.k_n * in.effective_mass);
  EXPECT_EQ(pair_normal_force(p, in), p.normal.k_n * (-in.gap) + k_d * (-in.gap_rate));
}

TEST(SharedNormalLaw, PairGapIsCohesion) {
  PairContactParams p;
  p.cohesion.k_c = 0.7;
  const double ri = 1.1, rj = 0.9;
  for (double gap : {0.0, 0.001, 0.017, 0.06, 0.0601}) {
    const PairContactInput in{gap, 0.03, ri, rj, 1.0};
    EXPECT_EQ(pair_normal_force(p, in), -cohesion_force(p.cohesion, gap, ri, rj)) << gap;
  }
  // Within range: the formula the pair style computed before (bit-identical).
  const PairContactInput in{0.017, 0.0, ri, rj, 1.0};
  EXPECT_EQ(pair_normal_force(p, in), -in.gap * p.cohesion.k_c * (ri * rj / (ri + rj)));
}

TEST(SharedNormalLaw, PairEffectiveMassIsTheReducedMass) {
  EXPECT_DOUBLE_EQ(pair_effective_mass(2.0, 3.0), 6.0 / 5.0);
  EXPECT_DOUBLE_EQ(pair_effective_mass(1.0, 1.0), 0.5);
}

TEST(SharedNormalLaw, DefaultTangentialStiffnessIsTwoSeventhsOfTheNormal) {
  EXPECT_DOUBLE_EQ(default_tangential_stiffness(0.7), 0.2);
  EXPECT_EQ(FrictionParams{}.k_t, default_tangential_stiffness(DashDotParams{}.k_n));
}
