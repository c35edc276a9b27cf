// The coupling stages against slow, obviously-correct references, bit for bit: the mapping
// against a scan of every sphere's whole bounding box, the links against a scan of every
// covered cell in every direction, the stages split over two OpenMP threads against one (with
// more than one thread the moving walls and the link mass correction run one after the other,
// with one as the sweep of lbm/moving_wall/link_sweep.h), and that sweep against the stages.
#include <gtest/gtest.h>

#include <cstring>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "cases/scoped_threads.h"
#include "cases/serial_flow.h"
#include "coupling/boundary/sphere_links.h"
#include "coupling/force/momentum_exchange.h"
#include "coupling/sphere_coupling.h"
#include "lbm/d3q19.h"
#include "lbm/node_type.h"

using namespace coupling;

namespace {
// Spheres that overlap each other, a static wall and the periodic faces.
ParticleSet crowded_spheres() {
  ParticleSet p;
  p.add(1, {3.3, 8.1, 7.7}, {0.01, -0.02, 0.003}, 3.5);
  p.add(2, {9.1, 8.4, 7.2}, {-0.004, 0.01, 0.0}, 3.15);
  p.add(3, {15.6, 1.2, 12.9}, {0.002, 0.0, -0.01}, 2.8);  // across both periodic faces
  p.add(4, {11.0, 12.5, 3.0}, {0.0, 0.003, 0.02}, 4.2);   // cut by the wall at z = 0
  p.add(5, {6.2, 11.9, 9.3}, {0.01, 0.01, 0.01}, 1.2, false);  // a ghost
  for (std::size_t i = 0; i < p.size(); ++i)
    for (int a = 0; a < 3; ++a) p.angular_velocity[3 * i + a] = 0.001 * (a + 1) * (i % 2 ? 1 : -1);
  return p;
}

std::unique_ptr<lbm::FluidSolver> solver_with_a_wall() {
  const std::array<int, 3> dims{17, 16, 16};
  const std::array<bool, 3> periodic{true, true, false};
  lbm::VoxelGeometry g(dims);
  for (int j = 0; j < dims[1]; ++j)
    for (int i = 0; i < dims[0]; ++i) g.set_solid(i, j, 0, true);  // a wall at z = 0
  lbm::FluidParameters params;
  params.magic = 3.0 / 16.0;
  params.periodic = periodic;
  auto solver = std::make_unique<lbm::FluidSolver>(g, params, lbm::FlowDrive{},
                                                   cases::serial_decomposition(g, periodic));
  // Populations away from equilibrium, different at every node, so every link differs.
  auto& f = solver->populations();
  for (int q = 0; q < lbm::D3Q19::Q; ++q)
    for (std::size_t c = 0; c < f.num_cells(); ++c)
      f.at(q, c) = lbm::D3Q19::w[q] * (1.0 + 0.01 * std::sin(0.37 * double(c) + 1.3 * q));
  return solver;
}

// The crowded spheres mapped on the solver with a wall, and their links.
struct CrowdedLinks {
  std::unique_ptr<lbm::FluidSolver> solver = solver_with_a_wall();
  ParticleSet particles = crowded_spheres();
  SphereCoupling coupling{*solver};
  SphereLinks links;
  CrowdedLinks() {
    coupling.map_and_refill(particles.view(true));
    build_sphere_links(coupling.mapping(), particles.view(true), solver->node_types(), links);
  }
};

// The covered cells as a scan of every cell of every image's whole bounding box gives them.
std::vector<std::size_t> covered_by_box_scan(const SphereMapping& m, const ParticleView& view,
                                             const std::vector<std::uint8_t>& type) {
  const auto& layout = m.layout();
  std::vector<int> owner(layout.num_cells(), -1);
  std::vector<std::size_t> cells;
  for (std::size_t p = 0; p < view.num_total; ++p)
    for (int sz = 0; sz <= 0; ++sz)  // z is not periodic
      for (int sy = -1; sy <= 1; ++sy)
        for (int sx = -1; sx <= 1; ++sx) {
          const int s[3] = {sx, sy, sz};
          double c[3];
          for (int a = 0; a < 3; ++a) c[a] = view.x(p)[a] + s[a] * m.box().length[a] - layout.owned().lo[a];
          const double R = view.r(p);
          for (int k = -1; k <= layout.size(2); ++k)
            for (int j = -1; j <= layout.size(1); ++j)
              for (int i = -1; i <= layout.size(0); ++i) {
                const double dx = i - c[0], dy = j - c[1], dz = k - c[2];
                const std::size_t cell = layout.cell(i, j, k);
                if (type[cell] != lbm::kFluid && type[cell] != lbm::kMoving) continue;
                if (dx * dx + dy * dy + dz * dz < R * R && owner[cell] < 0) {
                  owner[cell] = int(p);
                  cells.push_back(cell);
                }
              }
        }
  return cells;
}

// The links as a scan of every covered cell in every direction gives them.
SphereLinks links_by_full_scan(const SphereMapping& m, const ParticleView& view,
                               const std::vector<std::uint8_t>& type) {
  using L = lbm::D3Q19;
  const auto& layout = m.layout();
  SphereLinks out;
  for (std::size_t wall : m.moving_cells()) {
    const auto w = layout.coords(wall);
    const int p = m.particle_at(wall);
    for (int q = 1; q < L::Q; ++q) {
      const int xi = w[0] - L::c[q][0], xj = w[1] - L::c[q][1], xk = w[2] - L::c[q][2];
      if (!layout.is_owned(xi, xj, xk)) continue;
      const std::size_t x = layout.cell(xi, xj, xk);
      if (type[x] != lbm::kFluid) continue;
      const auto g = layout.to_global(xi, xj, xk);
      Vec3 d{g[0] - view.x(p)[0], g[1] - view.x(p)[1], g[2] - view.x(p)[2]};
      for (int a = 0; a < 2; ++a)  // the plain minimum image on the periodic axes x, y
        d[a] -= m.box().length[a] * std::round(d[a] / m.box().length[a]);
      const double s = link_fraction(d, L::c[q], view.r(p));
      const Vec3 arm{d[0] + s * L::c[q][0], d[1] + s * L::c[q][1], d[2] + s * L::c[q][2]};
      lbm::BoundaryLink link;
      link.fluid_cell = x;
      link.q = q;
      link.fraction = s;
      link.wall_velocity = view.surface_velocity(std::size_t(p), arm);
      out.links.push_back(link);
      out.particle.push_back(p);
      out.arm.push_back(arm);
    }
  }
  return out;
}

bool same_bits(const void* a, const void* b, std::size_t bytes) { return std::memcmp(a, b, bytes) == 0; }

void expect_same_links(const SphereLinks& a, const SphereLinks& b) {
  ASSERT_EQ(a.links.size(), b.links.size());
  for (std::size_t l = 0; l < a.links.size(); ++l) {
    EXPECT_EQ(a.links[l].fluid_cell, b.links[l].fluid_cell);
    EXPECT_EQ(a.links[l].q, b.links[l].q);
    EXPECT_TRUE(same_bits(&a.links[l].fraction, &b.links[l].fraction, sizeof(double)));
    EXPECT_TRUE(same_bits(a.links[l].wall_velocity.data(), b.links[l].wall_velocity.data(), 3 * sizeof(double)));
    EXPECT_EQ(a.particle[l], b.particle[l]);
    EXPECT_TRUE(same_bits(a.arm[l].data(), b.arm[l].data(), 3 * sizeof(double)));
  }
}

// One coupled step of the crowded scene; the populations and the loads after it.
struct StepResult {
  lbm::PopulationField::Storage populations;
  HydrodynamicLoads loads;
};
StepResult one_step(lbm::MovingWallScheme scheme, int threads) {
#ifdef _OPENMP
  const int before = omp_get_max_threads();
  omp_set_num_threads(threads);
#else
  (void)threads;
#endif
  auto solver = solver_with_a_wall();
  ParticleSet p = crowded_spheres();
  SphereCouplingOptions o;
  o.wall_scheme = scheme;
  SphereCoupling coupling(*solver, o);
  coupling.map_and_refill(p.view(true));
  for (std::size_t i = 0; i < p.size(); ++i) p.position[3 * i] += 0.3;  // uncovers nodes
  coupling.step(p.view(true));
  coupling.step(p.view(true));
#ifdef _OPENMP
  omp_set_num_threads(before);
#endif
  return {solver->populations().raw(), coupling.loads()};
}
}  // namespace

TEST(CouplingReference, MappingEqualsTheBoundingBoxScan) {
  auto solver = solver_with_a_wall();
  const ParticleSet p = crowded_spheres();
  SphereCoupling coupling(*solver);
  const std::vector<std::uint8_t> before = solver->node_types();
  coupling.map_and_refill(p.view());
  EXPECT_EQ(coupling.mapping().moving_cells(), covered_by_box_scan(coupling.mapping(), p.view(), before));
}

TEST(CouplingReference, LinksEqualTheScanOfEveryCoveredCellBitForBit) {
  auto solver = solver_with_a_wall();
  const ParticleSet p = crowded_spheres();
  SphereCoupling coupling(*solver);
  coupling.map_and_refill(p.view(true));
  const SphereLinks reference = links_by_full_scan(coupling.mapping(), p.view(true), solver->node_types());
  ASSERT_GT(reference.links.size(), 1000u);
  SphereLinks links;
  build_sphere_links(coupling.mapping(), p.view(true), solver->node_types(), links);
  expect_same_links(links, reference);
#ifdef _OPENMP
  const int before = omp_get_max_threads();
  omp_set_num_threads(2);
  std::vector<SphereLinks> scratch;
  build_sphere_links(coupling.mapping(), p.view(true), solver->node_types(), links, &scratch);
  omp_set_num_threads(before);
  expect_same_links(links, reference);
#endif
}

TEST(CouplingReference, TwoThreadsGiveTheOneThreadStepBitForBit) {
  for (auto scheme : {lbm::MovingWallScheme::kMeiLuoShyy, lbm::MovingWallScheme::kBouzidi,
                      lbm::MovingWallScheme::kBounceBack}) {
    const StepResult one = one_step(scheme, 1), two = one_step(scheme, 2);
    ASSERT_EQ(one.populations.size(), two.populations.size());
    EXPECT_TRUE(same_bits(one.populations.data(), two.populations.data(),
                          one.populations.size() * sizeof(lbm::Real)))
        << lbm::moving_wall::label(scheme);
    ASSERT_EQ(one.loads.force.size(), two.loads.force.size());
    EXPECT_TRUE(same_bits(one.loads.force.data(), two.loads.force.data(), one.loads.force.size() * sizeof(Vec3)));
    EXPECT_TRUE(same_bits(one.loads.torque.data(), two.loads.torque.data(), one.loads.torque.size() * sizeof(Vec3)));
  }
}

// The sweep that interleaves the moving walls with the link mass correction
// (lbm/moving_wall/link_sweep.h) against the three stages one after the other on one thread,
// the sweep itself on 1 to 4 threads: with 2 each thread's range has blocks it corrects at
// once and blocks it leaves to the barrier, with 4 (about 17 blocks each, the lag 13) few or
// none are corrected at once.
TEST(CouplingReference, LinkSweepGivesTheSeparateStagesBitForBit) {
  cases::ScopedThreads threads_of_test(1);
  for (auto scheme : {lbm::MovingWallScheme::kMeiLuoShyy, lbm::MovingWallScheme::kBouzidi,
                      lbm::MovingWallScheme::kBounceBack}) {
    CrowdedLinks crowded;
    lbm::FluidSolver& solver = *crowded.solver;
    const std::vector<lbm::BoundaryLink>& links = crowded.links.links;
    lbm::PopulationField& f = solver.populations();
    const lbm::PopulationField::Storage start = f.raw();
    const double rho0 = solver.parameters().rho0;

    threads_of_test.set(1);
    lbm::moving_wall::MomentCache cache;
    std::vector<lbm::LinkPopulations> stages_populations;
    std::vector<double> stages_defects;
    lbm::apply_links(links, scheme, solver, &cache, nullptr, &stages_populations);
    const auto stages = lbm::moving_wall::link_mass_defect(links, rho0, stages_populations, &stages_defects);
    lbm::moving_wall::restore_link_mass(links, solver.layout(), solver.node_types(), stages_defects, f);
    const lbm::PopulationField::Storage after_stages = f.raw();

    for (int threads = 1; threads <= cases::ScopedThreads::most(4); ++threads) {
      threads_of_test.set(threads);
      ASSERT_GE(links.size(), 256u * std::size_t(threads));  // lbm::link_threads splits them
      f.raw() = start;
      std::vector<lbm::LinkPopulations> sweep_populations;
      std::vector<double> sweep_defects;
      lbm::moving_wall::LinkSweep order;
      const auto swept = lbm::moving_wall::apply_links_and_restore_mass(
          links, scheme, solver, cache, order, sweep_populations, sweep_defects);
      ASSERT_GT(order.lag(), 1u);
      const std::string what = std::string(lbm::moving_wall::label(scheme)) + ", " +
                               std::to_string(threads) + " threads";
      EXPECT_TRUE(same_bits(after_stages.data(), f.raw().data(), start.size() * sizeof(lbm::Real))) << what;
      ASSERT_EQ(stages_defects.size(), sweep_defects.size());
      EXPECT_TRUE(same_bits(stages_defects.data(), sweep_defects.data(), stages_defects.size() * sizeof(double)))
          << what;
      EXPECT_TRUE(same_bits(stages_populations.data(), sweep_populations.data(),
                            stages_populations.size() * sizeof(lbm::LinkPopulations)))
          << what;
      EXPECT_TRUE(same_bits(&stages.net, &swept.net, sizeof(double))) << what;
      EXPECT_TRUE(same_bits(&stages.absolute, &swept.absolute, sizeof(double))) << what;
      EXPECT_NE(stages.absolute, 0.0);
    }
  }
}

// The sweep's order: every link once, by fluid node in memory order, a node's links in
// link order (so that the node is gathered and corrected once and the correction's
// roundings are those of link order), and each link's copy the link itself.
TEST(CouplingReference, LinkSweepOrdersTheLinksByNodeInLinkOrder) {
  const CrowdedLinks crowded;
  const std::vector<lbm::BoundaryLink>& links = crowded.links.links;
  lbm::moving_wall::LinkSweep order;
  order.sort(links, crowded.solver->layout());
  const std::size_t n = links.size();
  ASSERT_EQ(order.first(order.num_blocks()), n);
  std::vector<int> seen(n, 0);
  for (std::size_t i = 0; i < n; ++i) {
    const std::uint32_t id = order.id(i);
    ASSERT_LT(id, n);
    ++seen[id];
    EXPECT_EQ(order.link(i).fluid_cell, links[id].fluid_cell);
    EXPECT_EQ(order.link(i).q, links[id].q);
    EXPECT_EQ(order.link(i).fraction, links[id].fraction);
    if (i == 0) continue;
    const std::size_t before = order.link(i - 1).fluid_cell, here = order.link(i).fluid_cell;
    ASSERT_LE(before, here) << "position " << i;
    if (before == here) {
      EXPECT_LT(order.id(i - 1), id) << "position " << i;
    }
  }
  for (std::size_t id = 0; id < n; ++id) EXPECT_EQ(seen[id], 1) << "link " << id;
  for (std::size_t b = 0; b < order.num_blocks(); ++b)
    for (std::size_t i = order.first(b); i < order.first(b + 1); ++i)
      EXPECT_EQ(order.link(i).fluid_cell >> lbm::moving_wall::LinkSweep::kBlockShift, b);
}

// The sweep's ranges: whole blocks, in order, covering every block, each holding about its
// share of the links.
TEST(CouplingReference, LinkSweepSharesCoverEveryBlockOnce) {
  const CrowdedLinks crowded;
  lbm::moving_wall::LinkSweep order;
  order.sort(crowded.links.links, crowded.solver->layout());
  const std::size_t n = crowded.links.links.size();
  for (int shares = 1; shares <= 5; ++shares) {
    EXPECT_EQ(order.block_of_share(0, shares), 0u);
    EXPECT_EQ(order.block_of_share(shares, shares), order.num_blocks());
    for (int t = 0; t < shares; ++t) {
      const std::size_t first = order.block_of_share(t, shares), last = order.block_of_share(t + 1, shares);
      ASSERT_LE(first, last);
      const std::size_t held = order.first(last) - order.first(first);
      const std::size_t linked = last == first ? 0 : held;
      // A range ends at a block boundary: at most one block's links (64 cells, at most
      // 18 links each) from its share.
      EXPECT_NEAR(double(linked), double(n) / shares, 64.0 * 18.0) << t << " of " << shares;
    }
  }
}
