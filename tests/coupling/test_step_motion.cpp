// The velocity the fluid sees a particle move with (coupling/boundary/step_motion.h): its
// velocity without a step behind it, the displacement over one fluid step after the first,
// the mean of the last two steps' displacements after that, through periodic wraps.
#include <gtest/gtest.h>

#include "coupling/boundary/step_motion.h"

using coupling::StepMotion;
using coupling::Vec3;

namespace {
const auto kNoWrap = [](double*) {};
}

TEST(StepMotion, WithoutAStepBehindItTheFluidSeesTheVelocity) {
  StepMotion m;
  const double x[3] = {1.0, 2.0, 3.0}, v[3] = {0.1, -0.2, 0.3};
  EXPECT_EQ(m.step(x, v, 2.0, /*advance=*/true, kNoWrap), (Vec3{0.1, -0.2, 0.3}));  // just inserted
  EXPECT_TRUE(m.has_position);
  EXPECT_FALSE(m.has_last_velocity);
  const double x1[3] = {5.0, 2.0, 3.0};
  EXPECT_EQ(m.step(x1, v, 2.0, /*advance=*/false, kNoWrap), (Vec3{0.1, -0.2, 0.3}));  // a run's start
  EXPECT_EQ(m.position, (Vec3{5.0, 2.0, 3.0}));
}

TEST(StepMotion, TheMeanOfTheLastTwoStepsDisplacements) {
  StepMotion m;
  const double v[3] = {9.0, 9.0, 9.0};  // never seen once a step lies behind
  const double x0[3] = {0.0, 0.0, 0.0}, x1[3] = {1.0, 0.5, 0.0}, x2[3] = {4.0, 0.5, -1.0};
  m.step(x0, v, 2.0, true, kNoWrap);
  EXPECT_EQ(m.step(x1, v, 2.0, true, kNoWrap), (Vec3{0.5, 0.25, 0.0}));  // one step: its own
  EXPECT_EQ(m.last_velocity, (Vec3{0.5, 0.25, 0.0}));
  EXPECT_EQ(m.step(x2, v, 2.0, true, kNoWrap), (Vec3{0.5 * (1.5 + 0.5), 0.5 * (0.0 + 0.25), 0.5 * (-0.5 + 0.0)}));
  EXPECT_EQ(m.last_velocity, (Vec3{1.5, 0.0, -0.5}));
}

TEST(StepMotion, ADisplacementThroughAPeriodicFaceIsWrapped) {
  StepMotion m;
  const double v[3] = {0.0, 0.0, 0.0};
  const double before[3] = {9.75, 1.0, 1.0}, after[3] = {0.25, 1.0, 1.0};  // box length 10 along x
  const auto wrap = [](double* d) {
    if (d[0] < -5.0) d[0] += 10.0;
  };
  m.step(before, v, 1.0, true, wrap);
  EXPECT_EQ(m.step(after, v, 1.0, true, wrap), (Vec3{0.5, 0.0, 0.0}));
}
