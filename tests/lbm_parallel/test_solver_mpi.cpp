// The key parallel claim: the same flow on 2 ranks equals the flow on 1 rank to round-off.
// Every rank runs the parallel solver on MPI_COMM_WORLD and a serial reference solver on
// MPI_COMM_SELF, and compares the populations and fields of the nodes it owns.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "flow_setup.h"
#include "lbm/decomposition.h"
#include "lbm/macroscopic.h"
#include "owned_pairs.h"

namespace {
using namespace lbm_parallel_test;

constexpr int kSteps = 200;

struct Split {
  std::string name;
  int axis;
  int cut;        // < 0: the regular grid cut; else a hand-made cut at this global index
  bool reversed;  // hand-made: rank 1 holds the lower part
};

lbm::Decomposition decompose(const FlowCase& c, const Split& s) {
  const lbm::Communicator world(MPI_COMM_WORLD);
  lbm::Box global;
  global.hi = c.geometry.dims();
  if (s.cut < 0) {
    std::array<int, 3> procs{1, 1, 1};
    procs[s.axis] = 2;
    return lbm::Decomposition::grid(global, c.parameters.periodic, procs, world);
  }
  // As LIGGGHTS would hand it over: boxes and neighbours set by the host.
  lbm::Decomposition d;
  d.global = global;
  d.periodic = c.parameters.periodic;
  d.comm = world;
  const int rank = world.rank(), other = 1 - rank;
  const bool lower = (rank == 0) != s.reversed;
  d.owned = global;
  (lower ? d.owned.hi : d.owned.lo)[s.axis] = s.cut;
  for (int a = 0; a < 3; ++a)
    d.neighbor[a] = d.periodic[a] ? std::array<int, 2>{rank, rank} : std::array<int, 2>{-1, -1};
  d.neighbor[s.axis][lower ? 1 : 0] = other;
  d.neighbor[s.axis][lower ? 0 : 1] = d.periodic[s.axis] ? other : -1;
  return d;
}

// Largest |parallel - serial| over this rank's owned nodes, all ranks reduced.
double max_difference(const lbm::FluidSolver& parallel, const lbm::FluidSolver& serial) {
  double worst = 0.0;
  lbm_parallel_test::for_owned_pairs(parallel, serial, [&](std::size_t a, std::size_t b) {
    EXPECT_EQ(parallel.node_types()[a], serial.node_types()[b]);
    if (parallel.node_types()[a] != lbm::kFluid) return;
    for (int q = 0; q < lbm::D3Q19::Q; ++q)
      worst = std::max(worst, std::abs(double(parallel.populations().at(q, a)) -
                                       double(serial.populations().at(q, b))));
    worst = std::max(worst, std::abs(parallel.density(a) - serial.density(b)));
    for (int c = 0; c < 3; ++c)
      worst = std::max(worst, std::abs(parallel.velocity(a)[c] - serial.velocity(b)[c]));
  });
  parallel.decomposition().comm.max(&worst, 1);
  return worst;
}

void compare(const FlowCase& c, const Split& split) {
  lbm::FluidSolver serial(c.geometry, c.parameters, c.drive, serial_decomposition(c));
  lbm::FluidSolver parallel(c.geometry, c.parameters, c.drive, decompose(c, split));
  start(serial);
  start(parallel);
  for (int s = 0; s < kSteps; ++s) {
    serial.step();
    parallel.step();
  }
  const double difference = max_difference(parallel, serial);
  // The flow did develop (otherwise equality would prove little).
  const double flux = lbm::plane_flux(parallel, 0, 7);
  const double serial_flux = lbm::plane_flux(serial, 0, 7);
  if (parallel.decomposition().comm.rank() == 0)
    std::printf("  %-28s max |2 ranks - 1 rank| = %.3g after %d steps (flux %.6g)\n",
                split.name.c_str(), difference, kSteps, flux);
  EXPECT_LT(difference, 1e-12) << split.name;
  EXPECT_NEAR(flux, serial_flux, 1e-12) << split.name;
  EXPECT_GT(std::abs(flux), 1e-3) << split.name;
  EXPECT_NEAR(lbm::total_mass(parallel), lbm::total_mass(serial), 1e-10) << split.name;
}

const Split kSplits[] = {
    {"grid along x", 0, -1, false},
    {"grid along y", 1, -1, false},
    {"grid along z", 2, -1, false},
    {"hand-made x cut at 5", 0, 5, false},
    {"hand-made y cut at 3, reversed", 1, 3, true},
    {"hand-made z cut at 1", 2, 1, false},
};

TEST(OneRankEqualsTwoRanks, BodyForceChannelWithSolidVoxels) {
  ASSERT_EQ(lbm::Communicator(MPI_COMM_WORLD).size(), 2);
  for (const Split& s : kSplits) compare(body_force_channel(), s);
}

// Negative control: the comparison does see a missing halo exchange.
TEST(OneRankEqualsTwoRanks, WithoutHaloExchangeTheRunsDiffer) {
  const FlowCase c = body_force_channel();
  lbm::FluidSolver serial(c.geometry, c.parameters, c.drive, serial_decomposition(c));
  lbm::FluidSolver parallel(c.geometry, c.parameters, c.drive, decompose(c, kSplits[0]));
  start(serial);
  start(parallel);
  for (int s = 0; s < 20; ++s) {
    serial.step();
    parallel.apply_wall_bounce_back();
    parallel.apply_open_boundaries();
    parallel.collide_stream();
  }
  EXPECT_GT(max_difference(parallel, serial), 1e-6);
}

TEST(OneRankEqualsTwoRanks, PressureDrivenChannelWithInletAndOutletOnDifferentRanks) {
  for (const Split& s : kSplits) compare(pressure_driven_channel(), s);
}

}  // namespace
