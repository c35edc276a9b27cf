// Galilean invariance and smoothness of the moving-sphere force. Case A: a sphere moves at
// +U through fluid initially at rest. Case B: the sphere is fixed and the fluid starts at -U.
// In the sphere's frame both are the same problem, so F_A(t) = F_B(t) up to the
// discretisation of the moving boundary (cell crossings, refill, covering).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "cases/serial_flow.h"
#include "coupling/sphere_coupling.h"

using namespace coupling;
using lbm::MovingWallScheme;

namespace {
std::vector<double> force_history(bool moving, MovingWallScheme scheme, MomentumExchange method,
                                  int steps, double U) {
  auto solver = cases::make_solver({32, 16, 16}, {true, true, true});
  solver->initialise_equilibrium(1.0, {moving ? 0.0 : -U, 0.0, 0.0});
  ParticleSet particles;
  const Vec3 start{8.3, 7.8, 8.1};
  particles.add(1, start, {moving ? U : 0.0, 0.0, 0.0}, 4.0);
  SphereCouplingOptions options;
  options.wall_scheme = scheme;
  options.momentum_exchange = method;
  SphereCoupling coupling(*solver, options);
  // Nodes inside the sphere at t = 0 carry no fluid in either case.
  coupling.map_and_refill(particles.view());
  std::vector<double> F;
  for (int t = 0; t < steps; ++t) {
    if (moving) particles.set_position(0, {start[0] + U * t, start[1], start[2]});
    coupling.step(particles.view());
    F.push_back(coupling.force(0)[0]);
  }
  return F;
}

struct Comparison {
  double mean_error = 0.0;   // (mean F_A - mean F_B) / mean F_B over the window
  double fluctuation = 0.0;  // rms(F_A - F_B) / mean F_B
  double mean_B = 0.0;
};

constexpr int kSteps = 400;  // 8 cells travelled at U
constexpr double kU = 0.02;

// F_A (moving sphere) against F_B (fixed sphere, moving fluid) after the first 100 steps.
Comparison compare(const std::vector<double>& A, const std::vector<double>& B) {
  const int first = 100;
  double sa = 0.0, sb = 0.0, s2 = 0.0;
  for (int t = first; t < kSteps; ++t) {
    sa += A[t];
    sb += B[t];
  }
  const int n = kSteps - first;
  sa /= n;
  sb /= n;
  for (int t = first; t < kSteps; ++t) s2 += std::pow(A[t] - B[t] - (sa - sb), 2);
  Comparison c;
  c.mean_B = sb;
  c.mean_error = (sa - sb) / std::abs(sb);
  c.fluctuation = std::sqrt(s2 / n) / std::abs(sb);
  return c;
}

Comparison compare(MovingWallScheme scheme, MomentumExchange method) {
  return compare(force_history(true, scheme, method, kSteps, kU),
                 force_history(false, scheme, method, kSteps, kU));
}
}  // namespace

TEST(GalileanInvariance, MovingSphereFeelsTheSameDragAsFixedSphereInMovingFluid) {
  cases::Stopwatch watch;
  const Comparison c = compare(MovingWallScheme::kMeiLuoShyy, MomentumExchange::kGalileanInvariant);
  std::printf("Galilean (MLS, Wen et al. momentum exchange), d = 8, U = 0.02, 8 cells travelled: "
              "mean drag %.4e, moving vs fixed %+.2f %%, rms fluctuation %.2f %%, %.2f s\n",
              c.mean_B, 100 * c.mean_error, 100 * c.fluctuation, watch.seconds());
  // Measured +0.09 % and 0.30 % rms: bounds 0.5 % and 1 % (the plain momentum exchange and
  // Bouzidi: PlainMomentumExchangeAndBouzidiHoldTheSameBounds).
  EXPECT_LT(std::abs(c.mean_error), 0.005);
  EXPECT_LT(c.fluctuation, 0.01);
}

TEST(GalileanInvariance, PlainMomentumExchangeAndBouzidiHoldTheSameBounds) {
  const auto mls = MovingWallScheme::kMeiLuoShyy;
  const auto plain = MomentumExchange::kPlain, wen = MomentumExchange::kGalileanInvariant;
  const auto moving_plain = force_history(true, mls, plain, kSteps, kU);
  const auto fixed_plain = force_history(false, mls, plain, kSteps, kU);
  const auto moving_wen = force_history(true, mls, wen, kSteps, kU);
  const auto fixed_wen = force_history(false, mls, wen, kSteps, kU);
  // Wen et al.'s term, -u_w (f*_q - f_{-q}) per link, vanishes where the wall rests: the fixed
  // sphere feels the same force from both forms, bit for bit; the moving one does not.
  double fixed_difference = 0.0, moving_difference = 0.0;
  for (int t = 0; t < kSteps; ++t) {
    fixed_difference = std::max(fixed_difference, std::abs(fixed_plain[t] - fixed_wen[t]));
    moving_difference = std::max(moving_difference, std::abs(moving_plain[t] - moving_wen[t]));
  }
  const Comparison c = compare(moving_plain, fixed_plain);
  const Comparison b = compare(MovingWallScheme::kBouzidi, wen);
  std::printf("Galilean (MLS, plain momentum exchange): moving vs fixed %+.2f %%, rms fluctuation "
              "%.2f %%; largest plain - Wen et al. force %.2e (moving sphere), %.2e (fixed)\n",
              100 * c.mean_error, 100 * c.fluctuation, moving_difference, fixed_difference);
  std::printf("Galilean (Bouzidi, Wen et al.): moving vs fixed %+.2f %%, rms fluctuation %.2f %%\n",
              100 * b.mean_error, 100 * b.fluctuation);
  EXPECT_EQ(fixed_difference, 0.0);
  EXPECT_GT(moving_difference, 0.0);
  // At U = 0.02 the term changes the mean drag by 6e-5 of itself (at most 1.4e-4 in a step,
  // against a drag of 0.23): the plain form and Bouzidi keep the bounds of the default
  // (measured +0.10 % and 0.30 % rms, Bouzidi +0.10 % and 0.26 %).
  EXPECT_LT(std::abs(c.mean_error), 0.005);
  EXPECT_LT(c.fluctuation, 0.01);
  EXPECT_LT(std::abs(b.mean_error), 0.005);
  EXPECT_LT(b.fluctuation, 0.01);
}
