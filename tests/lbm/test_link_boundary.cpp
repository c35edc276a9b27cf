// Interpolated links on a moving wall: Couette flow between a resting and a moving wall,
// with the walls at arbitrary fractions q of the link. Bouzidi's scheme with the
// q-dependent wall term reproduces the linear profile to round-off for any q.
#include <gtest/gtest.h>

#include <cstdio>
#include <vector>

#include "cases/serial_flow.h"
#include "lbm/d3q19.h"
#include "lbm/link_boundary.h"

namespace {
double couette_error(double q_bottom, double q_top, lbm::LinkScheme scheme) {
  const int H = 10;
  const double U = 0.01;
  lbm::VoxelGeometry g({2, H, 2});
  lbm::FluidParameters p;
  p.tau = 0.8;
  p.magic = 0.25;
  p.periodic = {true, false, true};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  const auto& L = solver.layout();
  std::vector<lbm::BoundaryLink> links;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      for (int q = 1; q < lbm::D3Q19::Q; ++q) {
        if (lbm::D3Q19::c[q][1] == -1) links.push_back({L.cell(i, 0, k), q, q_bottom, {0, 0, 0}});
        if (lbm::D3Q19::c[q][1] == +1) links.push_back({L.cell(i, H - 1, k), q, q_top, {U, 0, 0}});
      }
  auto step = [&] {
    solver.exchange_halo();
    lbm::apply_links(links, scheme, 1.0, L, solver.node_types(), solver.populations());
    solver.collide_stream();
  };
  for (int s = 0; s < 30000; ++s) step();
  // Walls at y = -q_bottom and y = H - 1 + q_top.
  const double gap = H - 1 + q_top + q_bottom;
  return cases::relative_l2_error(solver, 0,
                                  [&](int, int y, int) { return U * (y + q_bottom) / gap; });
}
}  // namespace

TEST(LinkBoundary, BouzidiCouetteIsExactForAnyFraction) {
  for (double qf : {0.1, 0.3, 0.5, 0.7, 0.95}) {
    const double e = couette_error(qf, 1.0 - 0.5 * qf, lbm::LinkScheme::kBouzidi);
    std::printf("Couette Bouzidi q=%.2f: L2 error %.2e\n", qf, e);
    EXPECT_LT(e, 1e-9) << "fraction " << qf;
  }
}

TEST(LinkBoundary, BounceBackCouetteIsExactOnlyHalfWay) {
  EXPECT_LT(couette_error(0.5, 0.5, lbm::LinkScheme::kBounceBack), 1e-9);
  // Off half-way, plain bounce-back still places the wall mid-link: an O(1/H) error.
  EXPECT_GT(couette_error(0.2, 0.9, lbm::LinkScheme::kBounceBack), 1e-3);
}

TEST(LinkBoundary, MomentumExchangeOnRestingWallEqualsShearStress) {
  // For the Couette flow, the force on the resting wall per node is mu dU/dy.
  const int H = 10;
  const double U = 0.01;
  lbm::VoxelGeometry g({2, H, 2});
  lbm::FluidParameters p;
  p.tau = 0.8;
  p.periodic = {true, false, true};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  const auto& L = solver.layout();
  std::vector<lbm::BoundaryLink> bottom, top;
  for (int k = 0; k < 2; ++k)
    for (int i = 0; i < 2; ++i)
      for (int q = 1; q < lbm::D3Q19::Q; ++q) {
        if (lbm::D3Q19::c[q][1] == -1) bottom.push_back({L.cell(i, 0, k), q, 0.5, {0, 0, 0}});
        if (lbm::D3Q19::c[q][1] == +1) top.push_back({L.cell(i, H - 1, k), q, 0.5, {U, 0, 0}});
      }
  std::vector<std::array<double, 3>> momentum;
  for (int s = 0; s < 30000; ++s) {
    solver.exchange_halo();
    lbm::apply_links(bottom, lbm::LinkScheme::kBounceBack, 1.0, L, solver.node_types(),
                     solver.populations(), &momentum);
    lbm::apply_links(top, lbm::LinkScheme::kBounceBack, 1.0, L, solver.node_types(),
                     solver.populations());
    solver.collide_stream();
  }
  double fx = 0.0;
  for (const auto& m : momentum) fx += m[0];
  const double per_node = fx / 4.0;  // 2 x 2 wall nodes
  const double stress = lbm::TrtParameters::viscosity(0.8) * U / H;
  std::printf("Couette wall shear: momentum exchange %.6e, analytic %.6e\n", per_node, stress);
  EXPECT_NEAR(per_node / stress, 1.0, 1e-6);
}
