// Plane and circular-pipe Poiseuille flow driven by a body force, against the analytical
// profiles u(y) = g y (H - y) / (2 mu) and u(r) = g (R^2 - r^2) / (4 mu), with the walls
// half-way between nodes (plane) or at the exact radius via interpolated links (pipe).
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <vector>

#include "flow_cases.h"
#include "lbm/d3q19.h"
#include "lbm/link_boundary.h"

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
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, flow_cases::serial(g, p.periodic));
  flow_cases::run_to_steady(solver, 1e-13, 400000, 500);
  const double mu = lbm::TrtParameters::viscosity(tau);
  auto exact = [&](int, int y, int) { return kForce * (y + 0.5) * (H - 0.5 - y) / (2.0 * mu); };
  ChannelResult r;
  r.l2_error = flow_cases::relative_l2_error(solver, 0, exact);
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

// Pipe of radius R along x, solid outside r = R; wall links cut at the exact radius.
// Starts from the analytical profile (the steady state does not depend on the start, it is
// only reached sooner) and runs until the velocity changes by less than 1e-9 relative per
// 100 steps.
double pipe(double R, lbm::MovingWallScheme scheme) {
  const int n = static_cast<int>(std::ceil(2 * R)) + 2;
  const double centre = 0.5 * (n - 1);
  lbm::VoxelGeometry g({2, n, n});
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      if (std::hypot(j - centre, k - centre) >= R)
        for (int i = 0; i < 2; ++i) g.set_solid(i, j, k, true);
  lbm::FluidParameters p;
  p.tau = 1.0;
  p.magic = 3.0 / 16.0;
  p.body_force = {kForce, 0.0, 0.0};
  p.periodic = {true, false, false};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, flow_cases::serial(g, p.periodic));
  const double mu = lbm::TrtParameters::viscosity(1.0);
  auto exact = [&](int, int y, int z) {
    const double r2 = std::pow(y - centre, 2) + std::pow(z - centre, 2);
    return kForce * (R * R - r2) / (4.0 * mu);
  };
  solver.initialise_equilibrium(
      [&](int x, int y, int z) { return std::array<double, 4>{1.0, exact(x, y, z), 0.0, 0.0}; });

  std::vector<lbm::BoundaryLink> links;
  const auto& L = solver.layout();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < 2; ++i) {
        const std::size_t x = L.cell(i, j, k);
        if (solver.node_types()[x] != lbm::kFluid) continue;
        for (int q = 1; q < lbm::D3Q19::Q; ++q) {
          const int cy = lbm::D3Q19::c[q][1], cz = lbm::D3Q19::c[q][2];
          if (solver.node_types()[x + L.offset(lbm::D3Q19::c[q][0], cy, cz)] == lbm::kFluid)
            continue;
          // |p + s c| = R on the pipe's cross-section.
          const double py = j - centre, pz = k - centre;
          const double a = cy * cy + cz * cz, b = py * cy + pz * cz, c = py * py + pz * pz - R * R;
          const double s = (-b + std::sqrt(b * b - a * c)) / a;
          links.push_back({x, q, s, {0.0, 0.0, 0.0}});
        }
      }
  for (const auto& l : links) EXPECT_TRUE(l.fraction > 0.0 && l.fraction <= 1.0 + 1e-12);

  auto stages_before_collision = [&] {
    solver.exchange_halo();
    solver.apply_wall_bounce_back();
    lbm::apply_links(links, scheme, 1.0, solver.layout(), solver.node_types(),
                     solver.populations());
  };
  // The step has an extra stage, so step by hand instead of solver.step().
  auto previous = lbm::compute_fields(solver).velocity;
  for (long s = 0; s < 100000; s += 100) {
    for (int t = 0; t < 100; ++t) {
      stages_before_collision();
      solver.collide_stream();
    }
    const auto now = lbm::compute_fields(solver).velocity;
    double change = 0.0, scale = 1e-300;
    for (std::size_t i = 0; i < now.size(); ++i) {
      change = std::max(change, std::abs(now[i] - previous[i]));
      scale = std::max(scale, std::abs(now[i]));
    }
    if (change < 1e-9 * scale) break;
    previous = now;
  }
  return flow_cases::relative_l2_error(solver, 0, exact);
}

// Curved-wall errors oscillate with how the wall cuts the lattice, so each resolution is
// the mean over three radii around the nominal one (R, R +- 7.5 %).
double mean_pipe_error(double R, lbm::MovingWallScheme scheme) {
  return (pipe(0.925 * R, scheme) + pipe(R, scheme) + pipe(1.075 * R, scheme)) / 3.0;
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
