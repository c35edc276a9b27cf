// Interpolated links on a moving wall: Couette flow between a resting and a moving wall,
// with the walls at arbitrary fractions q of the link. Bouzidi's scheme with the
// q-dependent wall term reproduces the linear profile to round-off for any q. Then each
// scheme of lbm/moving_wall/ on one hand-computed link.
#include <gtest/gtest.h>

#include <cstdio>
#include <stdexcept>
#include <vector>

#include "cases/serial_flow.h"
#include "lbm/collide_stream.h"
#include "lbm/d3q19.h"
#include "lbm/input_error.h"
#include "lbm/moving_wall/link_boundary.h"
#include "lbm/macroscopic.h"
#include "lbm/moving_wall/bounce_back.h"
#include "lbm/moving_wall/bouzidi.h"
#include "lbm/moving_wall/mei_luo_shyy.h"
#include "lbm/node_type.h"

namespace {
double couette_error(double q_bottom, double q_top, lbm::MovingWallScheme scheme) {
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
    const double e = couette_error(qf, 1.0 - 0.5 * qf, lbm::MovingWallScheme::kBouzidi);
    std::printf("Couette Bouzidi q=%.2f: L2 error %.2e\n", qf, e);
    EXPECT_LT(e, 1e-9) << "fraction " << qf;
  }
}

TEST(LinkBoundary, BounceBackCouetteIsExactOnlyHalfWay) {
  EXPECT_LT(couette_error(0.5, 0.5, lbm::MovingWallScheme::kBounceBack), 1e-9);
  // Off half-way, plain bounce-back still places the wall mid-link: an O(1/H) error.
  EXPECT_GT(couette_error(0.2, 0.9, lbm::MovingWallScheme::kBounceBack), 1e-3);
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
    lbm::apply_links(bottom, lbm::MovingWallScheme::kBounceBack, 1.0, L, solver.node_types(),
                     solver.populations(), &momentum);
    lbm::apply_links(top, lbm::MovingWallScheme::kBounceBack, 1.0, L, solver.node_types(),
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

// Each moving-wall scheme on one hand-computed link: fluid node x = (1,0,0) sends q = +x into
// the wall node (2,0,0); x - c_q = (0,0,0) is the second node. The wall moves at
// u_w = (0.01, 0.02, 0), so the wall term is 6 w_q rho0 c_q.u_w = 6/18 * 0.01 = 0.06/18.
namespace {
struct OneLink {
  lbm::BlockLayout layout{lbm::Box{{0, 0, 0}, {3, 1, 1}}};
  lbm::PopulationField f{layout};
  std::vector<std::uint8_t> node_type = std::vector<std::uint8_t>(layout.num_cells(), lbm::kSolid);
  std::size_t x = layout.cell(1, 0, 0), second = layout.cell(0, 0, 0), wall = layout.cell(2, 0, 0);
  std::ptrdiff_t offset = layout.offset(1, 0, 0);
  lbm::BoundaryLink link(double fraction) const { return {x, 1, fraction, {0.01, 0.02, 0.0}}; }
  // Populations at rest (f_q = w_q, rho = 1) at a node, or the equilibrium at velocity u.
  void equilibrium_at(std::size_t cell, std::array<double, 3> u) {
    for (int q = 0; q < lbm::D3Q19::Q; ++q) f.at(q, cell) = lbm::equilibrium(q, 1.0, u);
  }
};
constexpr double kWallTerm = 0.06 / 18.0;
}  // namespace

TEST(MovingWallScheme, NamesParseBackAndOthersAreRejected) {
  using lbm::MovingWallScheme;
  for (MovingWallScheme s :
       {MovingWallScheme::kBounceBack, MovingWallScheme::kBouzidi, MovingWallScheme::kMeiLuoShyy})
    EXPECT_EQ(lbm::moving_wall::parse(lbm::moving_wall::name(s)), s);
  EXPECT_STREQ(lbm::moving_wall::name(MovingWallScheme::kMeiLuoShyy), "mls");
  EXPECT_STREQ(lbm::moving_wall::label(MovingWallScheme::kMeiLuoShyy), "Mei-Luo-Shyy");
  EXPECT_THROW(lbm::moving_wall::parse("bounce-back"), lbm::InputError);
}

TEST(MovingWallScheme, BounceBackReturnsOutgoingMinusWallTerm) {
  OneLink c;
  c.node_type[c.x] = lbm::kFluid;
  c.f.at(1, c.x) = 0.10;
  const lbm::moving_wall::BounceBack bb{1.0};
  // The fraction is ignored: f_{-q} = 0.10 - 0.06/18.
  EXPECT_NEAR(bb.returning_population(c.link(0.2), c.offset, c.f), 0.10 - kWallTerm, 1e-15);
  // apply writes it into the wall node's slot and reports c_q (f*_q + f_{-q}).
  std::vector<std::array<double, 3>> momentum;
  lbm::moving_wall::apply({c.link(0.2)}, bb, c.layout, c.f, &momentum);
  EXPECT_NEAR(c.f.at(2, c.wall), 0.10 - kWallTerm, 1e-15);
  ASSERT_EQ(momentum.size(), 1u);
  EXPECT_NEAR(momentum[0][0], 0.20 - kWallTerm, 1e-15);
  EXPECT_EQ(momentum[0][1], 0.0);
}

TEST(MovingWallScheme, BouzidiInterpolatesOnEitherSideOfHalfWay) {
  OneLink c;
  c.node_type[c.x] = c.node_type[c.second] = lbm::kFluid;
  c.f.at(1, c.x) = 0.10;       // f*_q(x)
  c.f.at(2, c.x) = 0.06;       // f*_{-q}(x)
  c.f.at(1, c.second) = 0.08;  // f*_q(x - c_q)
  const lbm::moving_wall::Bouzidi bz{1.0, &c.node_type};
  // s = 1/4: 2 s 0.10 + (1 - 2 s) 0.08 - wall = 0.05 + 0.04 - 0.06/18.
  EXPECT_NEAR(bz.returning_population(c.link(0.25), c.offset, c.f), 0.09 - kWallTerm, 1e-15);
  // s = 3/4: (0.10 + (2 s - 1) 0.06 - wall) / (2 s) = (0.13 - 0.06/18) / 1.5.
  EXPECT_NEAR(bz.returning_population(c.link(0.75), c.offset, c.f), (0.13 - kWallTerm) / 1.5,
              1e-15);
  // s < 1/2 with x - c_q not fluid: bounce-back.
  c.node_type[c.second] = lbm::kSolid;
  EXPECT_NEAR(bz.returning_population(c.link(0.25), c.offset, c.f), 0.10 - kWallTerm, 1e-15);
}

TEST(MovingWallScheme, MeiLuoShyyMixesOutgoingWithFictitiousEquilibrium) {
  // x at rest (f_q = w_q: rho_f = 1, u_f = 0), tau = 1, so f*_q(x) = f^eq_q(1, 0) = 1/18.
  OneLink c;
  c.node_type[c.x] = c.node_type[c.second] = lbm::kFluid;
  c.equilibrium_at(c.x, {0.0, 0.0, 0.0});
  c.equilibrium_at(c.second, {0.03, 0.0, 0.0});
  lbm::moving_wall::MomentCache cache;
  cache.begin(c.layout.num_cells());
  const lbm::moving_wall::MeiLuoShyy mls{1.0, 1.0, {0.0, 0.0, 0.0}, &c.node_type, &cache};
  // Delta = 3/4: u_bf = (1 - 2) u_f + 2 u_w, c_q.u_bf = 0.02, chi = 0.5 / 1.5 = 1/3;
  // f^(*) = (1 + 3 * 0.02) / 18; back = (2/3 + 1.06/3 - 0.06) / 18 = 0.96 / 18.
  EXPECT_NEAR(mls.returning_population(c.link(0.75), c.offset, c.f), 0.96 / 18.0, 1e-14);
  // Delta = 1/4: u_bf = u(x - c_q) = (0.03, 0, 0), chi = -0.5 / -1 = 1/2;
  // f^(*) = (1 + 3 * 0.03) / 18; back = (0.5 + 0.545 - 0.06) / 18 = 0.985 / 18.
  EXPECT_NEAR(mls.returning_population(c.link(0.25), c.offset, c.f), 0.985 / 18.0, 1e-14);
  // Delta = 1/4 with x - c_q not fluid: u_bf = u_f, f^(*) = 1/18; back = 0.94 / 18.
  c.node_type[c.second] = lbm::kSolid;
  EXPECT_NEAR(mls.returning_population(c.link(0.25), c.offset, c.f), 0.94 / 18.0, 1e-14);
}

TEST(MovingWallScheme, NodeMomentsRemoveHalfTheBodyForce) {
  OneLink c;
  c.equilibrium_at(c.x, {0.0, 0.0, 0.0});
  const lbm::NodeMoments m = lbm::node_moments(c.f, c.x, {0.002, 0.0, -0.004});
  EXPECT_NEAR(m.rho, 1.0, 1e-15);
  EXPECT_NEAR(m.u[0], -0.001, 1e-15);
  EXPECT_NEAR(m.u[1], 0.0, 1e-15);
  EXPECT_NEAR(m.u[2], 0.002, 1e-15);
}

TEST(MovingWallScheme, BareArrayEntryRejectsMeiLuoShyy) {
  OneLink c;
  EXPECT_THROW(lbm::apply_links({c.link(0.5)}, lbm::MovingWallScheme::kMeiLuoShyy, 1.0, c.layout,
                                c.node_type, c.f),
               std::invalid_argument);
}
