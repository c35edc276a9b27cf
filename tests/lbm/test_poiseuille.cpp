// Plane and circular-pipe Poiseuille flow driven by a body force, against the analytical
// profiles u(y) = g y (H - y) / (2 mu) and u(r) = g (R^2 - r^2) / (4 mu), with the walls
// half-way between nodes (plane) or at the exact radius via interpolated links (pipe; the
// set-up is cases/pipe_poiseuille.h, shared with examples/accuracy).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "cases/pipe_poiseuille.h"
#include "cases/serial_flow.h"

namespace {

constexpr double kForce = 1e-6;

struct ChannelResult {
  double l2_error;
  double max_velocity_error;  // relative error of the centre-line velocity
};

// Channel of H nodes between walls normal to y; walls half-way (y = -1/2, H - 1/2).
ChannelResult plane_channel(int H, double tau, double magic) {
  lbm::VoxelGeometry g({2, H, 2});
  lbm::FluidParameters p;
  p.tau = tau;
  p.magic = magic;
  p.body_force = {kForce, 0.0, 0.0};
  p.periodic = {true, false, true};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  cases::run_to_steady(solver, 1e-13, 400000, 500);
  const double mu = lbm::TrtParameters::viscosity(tau);
  auto exact = [&](int, int y, int) { return kForce * (y + 0.5) * (H - 0.5 - y) / (2.0 * mu); };
  ChannelResult r;
  r.l2_error = cases::relative_l2_error(solver, 0, exact);
  // Centre line: the mean of the two middle nodes for even H.
  const auto f = lbm::compute_fields(solver);
  double umax = 0.0, emax = 0.0;
  for (int y = 0; y < H; ++y) {
    umax = std::max(umax, f.velocity[3 * (2 * y) + 0]);
    emax = std::max(emax, exact(0, y, 0));
  }
  r.max_velocity_error = umax / emax - 1.0;
  return r;
}

double order(double coarse_error, double fine_error) {
  return std::log(coarse_error / fine_error) / std::log(2.0);
}

// Mean relative L2 error over the radii around the nominal R (cases::kPipeRadiusFactors);
// checks that every wall link is cut inside its link.
double mean_pipe_error(double R, lbm::MovingWallScheme scheme) {
  double sum = 0.0;
  for (double factor : cases::kPipeRadiusFactors) {
    const cases::PipeRun run = cases::pipe_poiseuille(factor * R, scheme);
    for (const auto& l : run.links) EXPECT_TRUE(l.fraction > 0.0 && l.fraction <= 1.0 + 1e-12);
    sum += run.l2_error;
  }
  return sum / 3.0;
}

}  // namespace

TEST(PlanePoiseuille, MagicThreeSixteenthsIsExactForAnyViscosity) {
  for (double tau : {0.6, 1.0, 2.0}) {
    const auto r = plane_channel(8, tau, 3.0 / 16.0);
    std::printf("plane H=8 tau=%.2f Lambda=3/16: L2 error %.3e\n", tau, r.l2_error);
    EXPECT_LT(r.l2_error, 1e-8) << "tau " << tau;
  }
}

TEST(PlanePoiseuille, OtherMagicGivesViscosityIndependentPredictedError) {
  // H_eff^2 = H^2 + (16 Lambda - 3)/3 (Ginzburg): centre velocity error (16L-3)/(3H^2).
  const double magic = 0.25, H = 8;
  const double predicted = (16 * magic - 3) / (3 * H * H);
  std::vector<double> errors;
  for (double tau : {0.6, 1.0, 2.0}) {
    const auto r = plane_channel(8, tau, magic);
    std::printf("plane H=8 tau=%.2f Lambda=1/4: centre error %.4e (predicted %.4e), L2 %.4e\n",
                tau, r.max_velocity_error, predicted, r.l2_error);
    EXPECT_NEAR(r.max_velocity_error, predicted, 0.02 * predicted);
    errors.push_back(r.l2_error);
  }
  EXPECT_NEAR(errors[0] / errors[2], 1.0, 1e-6);  // independent of tau
}

TEST(PlanePoiseuille, SecondOrderConvergence) {
  const double e8 = plane_channel(8, 1.0, 0.25).l2_error;
  const double e16 = plane_channel(16, 1.0, 0.25).l2_error;
  const double e32 = plane_channel(32, 1.0, 0.25).l2_error;
  std::printf("plane Lambda=1/4 L2 errors H=8,16,32: %.3e %.3e %.3e; orders %.2f %.2f\n", e8, e16,
              e32, order(e8, e16), order(e16, e32));
  EXPECT_LT(e8, 1e-2);
  EXPECT_NEAR(order(e8, e16), 2.0, 0.15);
  EXPECT_NEAR(order(e16, e32), 2.0, 0.15);
}

TEST(PipePoiseuille, BouzidiLinksConvergeAtSecondOrder) {
  const double e4 = mean_pipe_error(4.0, lbm::MovingWallScheme::kBouzidi);
  const double e8 = mean_pipe_error(8.0, lbm::MovingWallScheme::kBouzidi);
  const double e16 = mean_pipe_error(16.0, lbm::MovingWallScheme::kBouzidi);
  std::printf("pipe Bouzidi mean L2 errors R=4,8,16: %.3e %.3e %.3e; orders %.2f %.2f\n", e4, e8,
              e16, order(e4, e8), order(e8, e16));
  EXPECT_LT(e4, 0.03);
  EXPECT_LT(e16, 1.5e-3);
  EXPECT_GT(order(e4, e16) / 2.0, 1.8);  // mean order over the two refinements
}

TEST(PipePoiseuille, StaircaseBounceBackIsLessAccurateThanBouzidi) {
  const double bb = mean_pipe_error(8.0, lbm::MovingWallScheme::kBounceBack);
  const double bz = mean_pipe_error(8.0, lbm::MovingWallScheme::kBouzidi);
  std::printf("pipe R=8: bounce-back mean L2 %.3e, Bouzidi mean L2 %.3e\n", bb, bz);
  EXPECT_LT(bb, 0.1);
  EXPECT_LT(bz, 0.5 * bb);
}
