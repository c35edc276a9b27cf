// The substep load model (coupling/force/substep_load.h): F - C (v - v_step), buoyancy, and
// the secant estimate of C with its clamps, from hand-set states.
#include <gtest/gtest.h>

#include <cmath>

#include "coupling/force/substep_load.h"

using namespace coupling;

namespace {
SubstepLoadParameters parameters(double dt_fluid = 2.0) {
  SubstepLoadParameters p;
  p.dt_fluid = dt_fluid;
  p.max_coefficient_masses = 4.0;
  return p;
}
}  // namespace

TEST(SubstepLoad, AtTheStepVelocityTheStoredLoadActsUnchanged) {
  SubstepLoadState s;
  s.force = {1.5, -2.0, 0.25};
  s.torque = {0.1, 0.2, 0.3};
  s.coefficient = 7.0;
  s.step_velocity = {0.3, 0.1, -0.2};
  const SubstepLoad load = SubstepLoadModel(parameters()).at_substep(s, s.step_velocity, 1.0);
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(load.hydrodynamic[a], s.force[a]);
    EXPECT_EQ(load.torque[a], s.torque[a]);
    EXPECT_EQ(load.buoyancy[a], 0.0);  // no gravity
  }
}

TEST(SubstepLoad, AVelocityChangeIsResistedWithTheCoefficient) {
  SubstepLoadState s;
  s.force = {1.0, 0.0, 0.0};
  s.coefficient = 3.0;
  s.step_velocity = {0.5, 0.0, 0.0};
  const SubstepLoad load = SubstepLoadModel(parameters()).at_substep(s, {0.75, -0.5, 0.0}, 1.0);
  EXPECT_DOUBLE_EQ(load.hydrodynamic[0], 1.0 - 3.0 * 0.25);
  EXPECT_DOUBLE_EQ(load.hydrodynamic[1], 1.5);
  EXPECT_DOUBLE_EQ(load.hydrodynamic[2], 0.0);
}

// The paper's "a fraction of the hydrodynamic force in each time step" read literally
// (share 1 / N_DEM): the force, its velocity response and the torque scaled by the share,
// buoyancy (not the fluid step's) whole.
TEST(SubstepLoad, AShareOfTheLoadScalesForceResponseAndTorqueButNotBuoyancy) {
  auto p = parameters();
  p.share = 1.0 / 100.0;
  p.buoyancy = true;
  p.fluid_density = 1.0;
  p.gravity = {0.0, 0.0, -1.0};
  SubstepLoadState s;
  s.force = {2.0, -1.0, 0.5};
  s.torque = {0.3, 0.0, -0.6};
  s.coefficient = 4.0;
  s.step_velocity = {0.1, 0.0, 0.0};
  const Vec3 v{0.2, 0.05, 0.0};
  const SubstepLoad held = SubstepLoadModel(parameters()).at_substep(s, v, 0.5);
  const SubstepLoad part = SubstepLoadModel(p).at_substep(s, v, 0.5);
  EXPECT_DOUBLE_EQ(part.hydrodynamic[0], (2.0 - 4.0 * 0.1) / 100.0);
  EXPECT_DOUBLE_EQ(part.hydrodynamic[1], (-1.0 - 4.0 * 0.05) / 100.0);
  for (int a = 0; a < 3; ++a) {
    EXPECT_DOUBLE_EQ(part.hydrodynamic[a], held.hydrodynamic[a] / 100.0);
    EXPECT_DOUBLE_EQ(part.torque[a], s.torque[a] / 100.0);
  }
  EXPECT_NEAR(part.buoyancy[2], 4.0 / 3.0 * M_PI * 0.125, 1e-15);
}

TEST(SubstepLoad, BuoyancyIsMinusFluidDensityTimesVolumeTimesGravity) {
  auto p = parameters();
  p.buoyancy = true;
  p.fluid_density = 1000.0;
  p.gravity = {0.0, 0.0, -9.81};
  const double R = 2e-3;
  const SubstepLoad load = SubstepLoadModel(p).at_substep(SubstepLoadState{}, {0.0, 0.0, 0.0}, R);
  const double volume = 4.0 / 3.0 * M_PI * R * R * R;
  EXPECT_NEAR(load.buoyancy[2], 1000.0 * volume * 9.81, 1e-15);
  EXPECT_EQ(load.buoyancy[0], 0.0);
}

// Two fluid steps of a particle whose force falls linearly with its velocity, F = F0 - c v:
// the secant recovers c exactly when it lies between the link term and the mass bound.
TEST(SubstepLoad, SecantRecoversTheCoefficientFromTwoKnownStates) {
  const double c = 5.0, F0 = 2.0, mass = 10.0;  // c_max = 4 m / dt = 20
  SubstepLoadModel model(parameters(2.0));
  SubstepLoadState s;
  auto fluid_step = [&](const Vec3& v, double link_term) {
    SubstepLoadModel::start_fluid_step(s, true);
    for (int a = 0; a < 3; ++a) s.force[a] = F0 - c * v[a];
    s.coefficient = link_term;
    model.finish_fluid_step(s, v, mass);
  };
  fluid_step({0.1, 0.0, 0.0}, 1.0);
  fluid_step({0.3, -0.2, 0.1}, 1.0);
  EXPECT_NEAR(s.coefficient, c, 1e-12);
  EXPECT_EQ(s.previous_velocity[0], 0.1);
  EXPECT_EQ(s.step_velocity[1], -0.2);
}

TEST(SubstepLoad, TheCoefficientIsClampedBetweenTheLinkTermAndAFewMasses) {
  SubstepLoadModel model(parameters(2.0));
  auto finished = [&](double secant_c, double link_term, double mass, double dv = 0.1) {
    SubstepLoadState s;
    s.previous_velocity = {0.0, 0.0, 0.0};
    s.previous_force = {0.0, 0.0, 0.0};
    s.force = {-secant_c * dv, 0.0, 0.0};
    s.coefficient = link_term;
    model.finish_fluid_step(s, {dv, 0.0, 0.0}, mass);
    return s.coefficient;
  };
  EXPECT_NEAR(finished(100.0, 1.0, 10.0), 20.0, 1e-12);  // above 4 m / dt_fluid
  EXPECT_NEAR(finished(-3.0, 1.0, 10.0), 1.0, 1e-12);    // below the link term
  EXPECT_NEAR(finished(50.0, 30.0, 10.0), 20.0, 1e-12);  // link term above the bound: the bound
  EXPECT_NEAR(finished(5.0, 1.0, 0.0), 1.0, 1e-12);      // mass unknown: the link term
  EXPECT_NEAR(finished(5.0, 1.0, 10.0, 0.0), 1.0, 1e-12);  // no velocity change: the link term
}

TEST(SubstepLoad, StartingAStepKeepsTheOldOneOnlyForOwnedParticles) {
  SubstepLoadState owned, ghost;
  for (SubstepLoadState* s : {&owned, &ghost}) {
    s->force = {1.0, 2.0, 3.0};
    s->step_velocity = {4.0, 5.0, 6.0};
    s->coefficient = 7.0;
    s->torque = {8.0, 9.0, 10.0};
  }
  SubstepLoadModel::start_fluid_step(owned, true);
  SubstepLoadModel::start_fluid_step(ghost, false);
  EXPECT_EQ(owned.previous_force[2], 3.0);
  EXPECT_EQ(owned.previous_velocity[0], 4.0);
  EXPECT_EQ(ghost.previous_force[2], 0.0);
  for (const SubstepLoadState* s : {&owned, &ghost}) {
    EXPECT_EQ(s->force[0], 0.0);
    EXPECT_EQ(s->torque[1], 0.0);
    EXPECT_EQ(s->coefficient, 0.0);
    EXPECT_EQ(s->step_velocity[2], 0.0);
  }
}
