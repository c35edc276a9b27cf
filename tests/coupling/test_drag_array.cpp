// Drag on a fixed sphere in a periodic simple-cubic array driven by a body force g.
// Reference: Sangani & Acrivos (1982), K(chi = d/L = 0.5) = 2.8420 (REFERENCES.md), with
// F = 6 pi mu a K U, U the superficial velocity, and F = g L^3 in steady state.
// The momentum exchange must also balance the body force on the fluid: F_me = g N_fluid.
#include <gtest/gtest.h>

#include <cstdio>

#include "sphere_cases.h"

using namespace coupling;
using lbm::MovingWallScheme;

namespace {
struct ArrayResult {
  double K = 0.0;              // from the flow: g L^3 / (6 pi mu a U)
  double force_balance = 0.0;  // F_me / (g N_fluid)
  double seconds = 0.0;
  long steps = 0;
};

ArrayResult run_array(int diameter, MovingWallScheme scheme) {
  sphere_cases::Stopwatch watch;
  const int L = 2 * diameter;  // chi = 0.5
  const double a = 0.5 * diameter, nu = 1.0 / 6.0, K_ref = 2.8420;
  const double U_target = 2e-4;  // Re = U d / nu ~ 0.01: Stokes flow
  const double g = U_target * 6.0 * sphere_cases::kPi * nu * a * K_ref / double(L * L * L);
  auto solver = sphere_cases::make_solver({L, L, L}, {true, true, true}, 1.0, {g, 0.0, 0.0});
  ParticleSet particles;
  // Off the lattice symmetry so the links see generic fractions.
  particles.add(1, {0.5 * L + 0.23, 0.5 * L - 0.31, 0.5 * L + 0.17}, {0, 0, 0}, a);
  SphereCouplingOptions options;
  options.wall_scheme = scheme;
  SphereCoupling coupling(*solver, options);
  ArrayResult r;
  double previous = 0.0;
  for (r.steps = 0; r.steps < 8000;) {
    for (int s = 0; s < 100; ++s, ++r.steps) coupling.step(particles.view());
    const double U = sphere_cases::superficial_velocity(*solver, 0);
    if (std::abs(U - previous) < 1e-5 * std::abs(U)) break;
    previous = U;
  }
  const double U = sphere_cases::superficial_velocity(*solver, 0);
  long long fluid = 0;
  sphere_cases::fluid_mass(*solver, &fluid);
  r.K = g * L * L * L / (6.0 * sphere_cases::kPi * nu * a * U);
  r.force_balance = coupling.force(0)[0] / (g * double(fluid));
  r.seconds = watch.seconds();
  return r;
}
}  // namespace

TEST(DragArray, MeiLuoShyyMatchesSangoniAcrivos) {
  const double K_ref = 2.8420;
  double previous_error = 1.0;
  for (int d : {6, 8, 12}) {
    const ArrayResult r = run_array(d, MovingWallScheme::kMeiLuoShyy);
    const double error = r.K / K_ref - 1.0;
    std::printf("SC array chi=0.5 d=%2d Mei-Luo-Shyy: K = %.4f (ref 2.8420, error %+.2f %%), "
                "F_me/(g N_fluid) = %.5f, %ld steps, %.2f s\n",
                d, r.K, 100 * error, r.force_balance, r.steps, r.seconds);
    // Measured -5.0 %, -2.6 %, -1.4 % (d = 6, 8, 12; first- to second-order convergence,
    // the sphere looks slightly small to the flow): bounds with ~30 % margin.
    const double bound = d == 6 ? 0.065 : (d == 8 ? 0.035 : 0.02);
    EXPECT_LT(std::abs(error), bound) << "d = " << d;
    EXPECT_LT(std::abs(error), previous_error) << "the error must shrink with resolution";
    previous_error = std::abs(error);
    EXPECT_NEAR(r.force_balance, 1.0, 1e-3) << "d = " << d;
  }
}

TEST(DragArray, OtherSchemesForComparison) {
  const double K_ref = 2.8420;
  for (MovingWallScheme scheme : {MovingWallScheme::kBouzidi, MovingWallScheme::kBounceBack}) {
    const ArrayResult r = run_array(8, scheme);
    const double error = r.K / K_ref - 1.0;
    std::printf("SC array chi=0.5 d= 8 %s: K = %.4f (error %+.2f %%), F_me/(g N_fluid) = %.5f, %.2f s\n",
                lbm::moving_wall::label(scheme), r.K, 100 * error, r.force_balance, r.seconds);
    EXPECT_NEAR(r.force_balance, 1.0, 1e-3);
    // Measured at d = 8: Bouzidi -2.8 %, bounce-back +2.6 % (its errors do not shrink
    // systematically with resolution, the wall sits mid-link whatever the fraction).
    EXPECT_LT(std::abs(error), 0.04);
  }
}
