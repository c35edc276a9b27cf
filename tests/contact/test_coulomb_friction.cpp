#include <gtest/gtest.h>

#include <cmath>

#include "contact/coulomb_friction.h"

using namespace contact;

namespace {
// A block on a flat wall (normal +z) under a tangential load along x, normal force N,
// integrated with velocity Verlet; returns the final x velocity.
double final_speed(double load, double normal_force, int steps) {
  FrictionParams p{0.1, 1.0, 0.25};
  const double m = 1.0, dt = 0.05;
  FrictionInput in;
  in.normal = {0, 0, 1};
  in.normal_force = normal_force;
  in.effective_mass = m;
  in.dt = dt;
  double v = 0.0;
  for (int s = 0; s < steps; ++s) {
    in.relative_velocity = {v, 0, 0};
    const FrictionResult r = coulomb_friction(p, in);
    in.spring = r.spring;
    v += dt * (load + r.force.x) / m;
  }
  return v;
}
}  // namespace

TEST(CoulombFriction, SticksBelowTheLimit) {
  // mu N = 0.1: a load of 0.09 is held, the particle comes to rest (no creep).
  EXPECT_NEAR(final_speed(0.09, 1.0, 20000), 0.0, 1e-10);
}

TEST(CoulombFriction, SlidesAboveTheLimitWithDynamicForce) {
  // Load 0.2 against mu N = 0.1: accelerates at (0.2 - 0.1)/m.
  const int steps = 2000;
  const double v = final_speed(0.2, 1.0, steps);
  EXPECT_NEAR(v, 0.1 * steps * 0.05, 0.02 * 0.1 * steps * 0.05);
}

TEST(CoulombFriction, ForceNeverExceedsMuN) {
  FrictionParams p{0.3, 5.0, 0.25};
  FrictionInput in;
  in.normal = {0, 0, 1};
  in.normal_force = 2.0;
  in.effective_mass = 1.0;
  in.dt = 0.01;
  in.relative_velocity = {3.0, -4.0, 7.0};  // normal part ignored
  for (int s = 0; s < 100; ++s) {
    const FrictionResult r = coulomb_friction(p, in);
    EXPECT_LE(norm(r.force), 0.3 * 2.0 + 1e-12);
    EXPECT_NEAR(r.force.z, 0.0, 1e-15);
    in.spring = r.spring;
  }
}

TEST(CoulombFriction, SpringIsRotatedIntoTheNewTangentPlane) {
  FrictionParams p{10.0, 1.0, 0.0};
  FrictionInput in;
  in.normal = {0, std::sin(0.1), std::cos(0.1)};
  in.spring = {0, 0.5, 0};
  in.normal_force = 1.0;
  in.effective_mass = 1.0;
  in.dt = 0.01;
  const FrictionResult r = coulomb_friction(p, in);
  EXPECT_NEAR(norm(r.spring), 0.5, 1e-14);
  EXPECT_NEAR(dot(r.spring, in.normal), 0.0, 1e-14);
}
