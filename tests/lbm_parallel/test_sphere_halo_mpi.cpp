// The sphere coupling's halo exchange on 2 ranks (mpirun -np 2): the step's exchange sends
// the five crossing populations per face, and the ghost nodes' moments on the axes where a
// sphere covers a node on the second plane from a face (coupling::whole_ghost_axes,
// Mei-Luo-Shyy reads the moments of the ghost node behind the face). Two spheres sit on the second planes from the rank faces,
// with links of fraction below 1/2 from the face planes (each alone, then both): the coupled step equals the same
// stages with all 19 exchanged bit for bit, equals the serial run to round-off, and the
// crossing five alone would change the result. Links the coupling; lives here for the MPI
// test main.
#include <gtest/gtest.h>
#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <string>

#include "cases/staged_step.h"
#include "coupling/sphere_coupling.h"
#include "lbm/decomposition.h"
#include "owned_pairs.h"

namespace {

using coupling::ParticleSet;
using coupling::SphereCoupling;
using coupling::Vec3;

constexpr int kSteps = 25;
const std::array<int, 3> kDims{16, 12, 10};
const std::array<bool, 3> kPeriodic{false, true, true};

std::unique_ptr<lbm::FluidSolver> make(const lbm::Decomposition& d) {
  lbm::VoxelGeometry g(kDims);
  lbm::FluidParameters p;
  p.tau = 0.8;
  p.magic = 3.0 / 16.0;
  p.periodic = kPeriodic;
  p.body_force = {1e-5, 2e-5, -1e-5};
  auto solver = std::make_unique<lbm::FluidSolver>(g, p, lbm::FlowDrive{}, d);
  solver->initialise_equilibrium([](int i, int j, int k) -> std::array<double, 4> {
    return {1.0 + 0.01 * std::sin(0.7 * i + 0.3 * j + 0.2 * k), 0.01 * std::cos(0.4 * j + 0.2 * k),
            0.005 * std::sin(0.6 * i + 0.9 * k), 0.004 * std::cos(0.8 * i - 0.5 * j)};
  });
  return solver;
}

// Largest |parallel - serial| over this rank's owned populations, all ranks reduced.
double max_difference(const lbm::FluidSolver& parallel, const lbm::FluidSolver& serial) {
  double worst = 0.0;
  lbm_parallel_test::for_owned_pairs(parallel, serial, [&](std::size_t a, std::size_t b) {
    for (int q = 0; q < lbm::D3Q19::Q; ++q)
      worst = std::max(worst, std::abs(double(parallel.populations().at(q, a)) -
                                       double(serial.populations().at(q, b))));
  });
  parallel.decomposition().comm.max(&worst, 1);
  return worst;
}

// `sphere` 0: A alone, 1: B alone (each face on its own: one side's sphere does not raise
// the axis for the other), 2: both.
// `near_spheres`: the ghost moments only near the spheres (every rank's view holds both).
void check_split(int axis, int sphere, bool near_spheres) {
  SCOPED_TRACE("split along " + std::string(1, "xyz"[axis]) + ", spheres " + std::string(1, "ABC"[sphere]) +
               (near_spheres ? ", moments near the spheres" : ", moments on the whole planes"));
  const lbm::Communicator world(MPI_COMM_WORLD);
  lbm::Box global;
  global.hi = kDims;
  std::array<int, 3> procs{1, 1, 1};
  procs[axis] = 2;
  const auto d = lbm::Decomposition::grid(global, kPeriodic, procs, world);
  const int cut = kDims[axis] / 2;  // the grid's cut
  auto run = make(d), all = make(d), crossing = make(d);
  auto serial = make(lbm::Decomposition::serial(global, kPeriodic));
  SphereCoupling c_run(*run), c_all(*all), c_crossing(*crossing), c_serial(*serial);
  if (near_spheres) c_run.set_particle_reach(1e9, 2.2);
  // A: surface at cut + 0.4 (links from the upper rank's plane 0 into its plane 1, delta
  // 0.4); B: surface at cut - 1.3 (from the lower rank's plane n - 1 into n - 2, delta 0.3).
  // B also covers the second plane from a face of another axis (periodic, or a wall).
  const double R = 2.2;
  Vec3 a{8.0, 6.0, 5.0}, b{4.0, 0.4 + R, 0.4 + R};
  a[axis] = cut + 0.4 + R;
  b[axis] = cut - 1.3 - R;
  const Vec3 va{0.003, -0.002, 0.001}, vb{-0.002, 0.001, 0.002};
  ParticleSet particles;
  if (sphere != 1) particles.add(1, a, va, R);
  if (sphere != 0) particles.add(2, b, vb, R);
  const Vec3 x0[2] = {sphere == 1 ? b : a, b}, v[2] = {sphere == 1 ? vb : va, vb};
  long long raised = 0;
  for (int t = 0; t < kSteps; ++t) {
    for (std::size_t p = 0; p < particles.size(); ++p)
      for (int c = 0; c < 3; ++c) particles.position[3 * p + c] = x0[p][c] + v[p][c] * t;
    c_run.step(particles.view());
    c_serial.step(particles.view());
    raised += c_run.ghost_moment_axes()[axis];
    cases::staged_step(c_all, particles.view(), lbm::HaloPopulations::every());
    cases::staged_step(c_crossing, particles.view(), lbm::HaloPopulations::crossing());
    double same = cases::max_population_difference(*run, *all);
    world.max(&same, 1);
    ASSERT_EQ(same, 0.0) << "step " << t << " rank " << world.rank();
    for (std::size_t p = 0; p < particles.size(); ++p)
      for (int c = 0; c < 3; ++c) ASSERT_EQ(c_run.force(p)[c], c_all.force(p)[c]) << "step " << t;
  }
  EXPECT_EQ(raised, kSteps);
  const double serial_difference = max_difference(*run, *serial);
  double control = cases::max_population_difference(*crossing, *all);
  world.max(&control, 1);
  if (world.rank() == 0)
    std::printf("  split %c, spheres %c, moments %s: max |2 ranks - 1 rank| = %.3g; crossing five only: %.3g off\n",
                "xyz"[axis], "ABC"[sphere], near_spheres ? "near the spheres" : "whole planes", serial_difference,
                control);
  EXPECT_LT(serial_difference, 1e-12);
  EXPECT_GT(control, 1e-9);
}

TEST(SphereHaloOnTwoRanks, AllPopulationsWhereASphereIsOnTheSecondPlaneFromARankFace) {
  ASSERT_EQ(lbm::Communicator(MPI_COMM_WORLD).size(), 2);
  for (int axis = 0; axis < 3; ++axis)
    for (int sphere = 0; sphere < 3; ++sphere)
      for (bool near_spheres : {false, true}) check_split(axis, sphere, near_spheres);
}

}  // namespace
