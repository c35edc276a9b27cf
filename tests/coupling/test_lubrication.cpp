// Lubrication: the correction law itself, and the total force (lattice + lubrication) on a
// sphere approaching a wall (cases/sphere_wall_approach.h, shared with examples/accuracy)
// and on two approaching spheres against Brenner (1961) / the two-sphere values in
// doc/references.md.
#include <gtest/gtest.h>

#include <cstdio>
#include <cstdlib>
#include <vector>

#include "cases/sphere_wall_approach.h"
#include "coupling/lubrication/lubrication.h"

using namespace coupling;

TEST(Lubrication, LawIsZeroAtTheCutoffAndClampedAtTheRoughness) {
  LubricationParameters p;
  LubricationCorrection lub(p);
  const double mu = p.rho * p.nu, R = 4.0, v = 0.01;
  EXPECT_DOUBLE_EQ(lub.magnitude(R, p.cutoff, v, R), 0.0);
  EXPECT_DOUBLE_EQ(lub.magnitude(R, 1.0, v, R), 0.0);
  const double h = 0.2;
  EXPECT_NEAR(lub.magnitude(R, h, v, R), 6 * cases::kPi * mu * R * R * v * (1 / h - 1 / p.cutoff),
              1e-14);
  EXPECT_DOUBLE_EQ(lub.magnitude(R, 1e-5, v, R), lub.magnitude(R, 0.01 * R, v, R));
  // Pair: equal and opposite, repulsive when approaching; a = R/2 for equal spheres.
  const Vec3 Fi = lub.pair_force(R, R, {2 * R + h, 0, 0}, {v, 0, 0}, {-v, 0, 0});
  const Vec3 Fj = lub.pair_force(R, R, {-2 * R - h, 0, 0}, {-v, 0, 0}, {v, 0, 0});
  EXPECT_LT(Fi[0], 0.0);
  EXPECT_NEAR(Fi[0], -Fj[0], 1e-15);
  EXPECT_NEAR(-Fi[0], lub.magnitude(0.5 * R, h, 2 * v, R), 1e-12);
  // Wall: a = R, pushes away from the wall, nothing when receding.
  const auto wall = plane_wall({0, -0.5, 0}, {0, 1, 0});
  EXPECT_GT(lub.wall_force(R, {0, -v, 0}, wall({0, R - 0.5 + h, 0}))[1], 0.0);
  EXPECT_LT(lub.wall_force(R, {0, +v, 0}, wall({0, R - 0.5 + h, 0}))[1], 0.0);
}

TEST(Lubrication, SphereApproachingAWallFollowsBrenner) {
  cases::Stopwatch watch;
  // d = 8: box 24 x 28 x 24, U = 0.004 (cases/sphere_wall_approach.h).
  const std::vector<cases::LambdaSample> history = cases::sphere_approaching_wall(8).corrected;
  const double lambda_ref = cases::lambda_at(history, 1.0);
  for (int i = 0; i < cases::kBrennerPoints; ++i) {
    const double lambda = cases::lambda_at(history, cases::kBrennerDelta[i]);
    const double increase = lambda - lambda_ref;
    const double increase_ref = cases::kBrennerLambda[i] - cases::kBrennerLambda[0];
    std::printf(
        "sphere-wall d=8 delta/a=%.2f: lambda %.3f (Brenner %.3f), increase over delta=a "
        "%.3f (Brenner %.3f)\n",
        cases::kBrennerDelta[i], lambda, cases::kBrennerLambda[i], increase, increase_ref);
    // Measured (d = 8, box 24x28x24, U = 0.004, Re = 0.19): lambda/lambda_Brenner - 1 =
    // +8.6 %, +0.5 %, -10.7 %, -8.8 %, -7.5 %, -4.3 %, -7.8 % for delta/a = 1 ... 0.01
    // (finite box and unsteadiness at large gaps, one-cell gap resolution near h_c):
    // bound 15 %.
    EXPECT_NEAR(lambda / cases::kBrennerLambda[i], 1.0, 0.15)
        << "delta/a = " << cases::kBrennerDelta[i];
  }
  std::printf("sphere-wall: %zu steps, %.2f s\n", history.size(), watch.seconds());
}

TEST(Lubrication, TwoSpheresApproachingFollowTheSqueezeLaw) {
  cases::Stopwatch watch;
  const double R = 4.0, U = 0.004, mu = 1.0 / 6.0;
  auto solver = cases::make_solver({56, 24, 24}, {true, true, true});
  ParticleSet particles;
  const double h0 = 8.2, xc = 28.1;
  particles.add(1, {xc - R - 0.5 * h0, 11.7, 12.2}, {U, 0, 0}, R);
  particles.add(2, {xc + R + 0.5 * h0, 11.7, 12.2}, {-U, 0, 0}, R);
  SphereCoupling coupling(*solver);
  LubricationCorrection lub(LubricationParameters{});
  const PeriodicBox box = PeriodicBox::from(solver->decomposition());
  std::vector<cases::LambdaSample> history;
  for (int t = 0;; ++t) {
    const double h = h0 - 2 * U * t;
    if (h < 2 * 0.005 * R) break;
    particles.set_position(0, {xc - R - 0.5 * h, 11.7, 12.2});
    particles.set_position(1, {xc + R + 0.5 * h, 11.7, 12.2});
    coupling.step(particles.view());
    double F[6] = {0, 0, 0, 0, 0, 0};
    lub.add_forces(particles.view(), box, nullptr, F);
    const double total = -(coupling.force(0)[0] + F[0]);
    history.push_back({0.5 * h / R, total / (6 * cases::kPi * mu * R * U)});
  }
  const double l1 = cases::lambda_at(history, 1.0), l01 = cases::lambda_at(history, 0.1);
  const double l001 = cases::lambda_at(history, 0.01);
  const double increase = l001 - l01, increase_ref = 28.114 - 4.6255;
  std::printf("two spheres d=8: lambda(delta/a=1) %.3f, (0.1) %.3f (ref 4.6255), (0.01) %.3f (ref 28.114); "
              "increase 0.1->0.01 %.3f (ref %.3f); %zu steps, %.2f s\n",
              l1, l01, l001, increase, increase_ref, history.size(), watch.seconds());
  // Measured: -2.3 % at delta/a = 0.1, +1.6 % at 0.01, increase +2.4 %: bound 5 %.
  EXPECT_NEAR(l01 / 4.6255, 1.0, 0.05);
  EXPECT_NEAR(l001 / 28.114, 1.0, 0.05);
  EXPECT_NEAR(increase / increase_ref, 1.0, 0.05);
}
