// Mass is conserved to round-off in a closed box with walls and internal solids.
#include <gtest/gtest.h>

#include <random>
#include <tuple>

#include "cases/serial_flow.h"
#include "lbm/d3q19.h"
#include "lbm/pore_scene.h"

TEST(MassConservation, ClosedBoxWithObstaclesAndForcing) {
  lbm::VoxelGeometry g({14, 12, 10});
  for (int k = 3; k < 6; ++k)
    for (int j = 2; j < 9; ++j) g.set_solid(6, j, k, true);
  g.set_solid(2, 2, 2, true);
  lbm::FluidParameters p;
  p.tau = 0.7;
  p.magic = 0.25;
  p.body_force = {1e-5, 2e-6, 0.0};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{},
                          cases::serial_decomposition(g, {false, false, false}));
  // Random perturbation of the initial state (non-equilibrium, non-uniform).
  std::mt19937 rng(42);
  std::uniform_real_distribution<double> noise(0.9, 1.1);
  for (std::size_t cell = 0; cell < solver.layout().num_cells(); ++cell)
    if (solver.node_types()[cell] == lbm::kFluid)
      for (int q = 0; q < lbm::D3Q19::Q; ++q) solver.populations().at(q, cell) *= noise(rng);
  const double m0 = lbm::total_mass(solver);
  for (int s = 0; s < 2000; ++s) solver.step();
  const double m1 = lbm::total_mass(solver);
  EXPECT_NEAR(m1 / m0 - 1.0, 0.0, 1e-12) << "mass " << m0 << " -> " << m1;
}

#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <iterator>

#include "lbm/checkpoint.h"

// The small pore scene the checkpoint tests run: geometry, fluid, inlet drive.
std::tuple<lbm::VoxelGeometry, lbm::FluidParameters, lbm::FlowDrive> checkpoint_scene() {
  // inlet, free, pore, outlet lengths, width, pore diameter (cells)
  const lbm::PoreSceneSpec spec{4, 2, 4, 4, 8, 5};
  lbm::FluidParameters p;
  p.periodic = {false, true, true};
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kInletVelocity;
  drive.inlet_velocity = 0.02;
  return {lbm::make_pore_scene(spec), p, drive};
}

// A run stopped, checkpointed and resumed continues exactly as an uninterrupted one.
TEST(Checkpoint, ResumedRunMatchesUninterruptedRun) {
  const auto [g, p, drive] = checkpoint_scene();
  lbm::FluidSolver reference(g, p, drive, cases::serial_decomposition(g, p.periodic));
  for (int s = 0; s < 200; ++s) reference.step();
  lbm::FluidSolver first(g, p, drive, cases::serial_decomposition(g, p.periodic));
  for (int s = 0; s < 120; ++s) first.step();
  const std::string path = ::testing::TempDir() + "fluid.checkpoint";
  lbm::write_checkpoint(first, path);
  lbm::FluidSolver resumed(g, p, drive, cases::serial_decomposition(g, p.periodic));
  lbm::read_checkpoint(resumed, path);
  EXPECT_EQ(resumed.time_step(), 120);
  for (int s = 0; s < 80; ++s) resumed.step();
  EXPECT_EQ(resumed.populations().raw(), reference.populations().raw());

  // A checkpoint of another lattice is refused with a clear message.
  lbm::VoxelGeometry other({6, 8, 8});
  lbm::FluidSolver wrong(other, p, drive, cases::serial_decomposition(other, p.periodic));
  try {
    lbm::read_checkpoint(wrong, path);
    FAIL() << "mismatched checkpoint accepted";
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("another lattice"), std::string::npos) << e.what();
  }
}

// A run resumed on another decomposition (another number of ranks or processor grid) reads
// the part of every rank's file that it owns: here the two halves of a lattice split along
// x, read from one rank's checkpoint and written back into one, node for node.
TEST(Checkpoint, ReadOnAnotherDecomposition) {
  const auto [g, p, drive] = checkpoint_scene();
  lbm::FluidSolver whole(g, p, drive, cases::serial_decomposition(g, p.periodic));
  for (int s = 0; s < 60; ++s) whole.step();
  const std::string one = ::testing::TempDir() + "one_rank.checkpoint";
  lbm::write_checkpoint(whole, one);
  // The halves as two ranks would own them (this process plays both).
  const auto half = [&](int which) {
    lbm::Decomposition d = cases::serial_decomposition(g, p.periodic);
    const int cut = g.dims()[0] / 2 + 1;
    (which == 0 ? d.owned.hi : d.owned.lo)[0] = cut;
    return std::make_unique<lbm::FluidSolver>(g, p, drive, d);
  };
  const auto same_nodes = [&](const lbm::FluidSolver& part) {
    const lbm::BlockLayout& gp = part.layout();
    const lbm::BlockLayout& gw = whole.layout();
    const lbm::Box& owned = part.decomposition().owned;
    int differing = 0;
    for (int k = 0; k < gp.size(2); ++k)
      for (int j = 0; j < gp.size(1); ++j)
        for (int i = 0; i < gp.size(0); ++i) {
          const std::size_t a = gp.cell(i, j, k), b = gw.cell(i + owned.lo[0], j + owned.lo[1], k + owned.lo[2]);
          differing += part.node_types()[a] != whole.node_types()[b];
          for (int q = 0; q < lbm::D3Q19::Q; ++q)
            differing += part.populations().at(q, a) != whole.populations().at(q, b);
        }
    return differing;
  };
  const std::string two = ::testing::TempDir() + "two_ranks.checkpoint";
  for (int which = 0; which < 2; ++which) {
    auto part = half(which);
    lbm::read_checkpoint(*part, one);
    EXPECT_EQ(part->time_step(), 60);
    EXPECT_EQ(same_nodes(*part), 0) << "half " << which;
    lbm::write_checkpoint(*part, two);  // as rank 0; the second half becomes rank 1's file
    const std::string as = two + (which == 0 ? ".first" : ".1");
    ASSERT_EQ(std::rename((two + ".0").c_str(), as.c_str()), 0);
  }
  ASSERT_EQ(std::rename((two + ".first").c_str(), (two + ".0").c_str()), 0);
  lbm::FluidSolver again(g, p, drive, cases::serial_decomposition(g, p.periodic));
  lbm::read_checkpoint(again, two);
  EXPECT_EQ(again.time_step(), 60);
  EXPECT_EQ(same_nodes(again), 0);
  // A rank's file missing: the nodes it held are not found, and the message says so.
  std::remove((two + ".1").c_str());
  lbm::FluidSolver short_of_one(g, p, drive, cases::serial_decomposition(g, p.periodic));
  try {
    lbm::read_checkpoint(short_of_one, two);
    FAIL() << "a checkpoint missing a rank's file was accepted";
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("rank's file missing"), std::string::npos) << e.what();
  }
}

// A checkpoint is written to a temporary name and renamed once complete: a write that fails
// on a full disk (here /dev/full behind the temporary name) leaves the previous checkpoint
// as it was, reports the failure, and leaves no partial file behind.
TEST(Checkpoint, AFailedWriteKeepsThePreviousCheckpoint) {
  lbm::VoxelGeometry g({6, 6, 6});
  lbm::FluidParameters p;
  p.periodic = {true, true, true};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  const std::string path = ::testing::TempDir() + "kept.checkpoint";
  const std::string file = path + ".0";
  lbm::write_checkpoint(solver, path);
  std::ifstream before_stream(file, std::ios::binary);
  const std::string before((std::istreambuf_iterator<char>(before_stream)), std::istreambuf_iterator<char>());
  ASSERT_GT(before.size(), 100u);
  for (int s = 0; s < 5; ++s) solver.step();
  std::remove((file + ".partial").c_str());
  ASSERT_EQ(symlink("/dev/full", (file + ".partial").c_str()), 0);
  try {
    lbm::write_checkpoint(solver, path);
    FAIL() << "a write to a full disk was not reported";
  } catch (const lbm::InputError& e) {
    EXPECT_NE(std::string(e.what()).find("disk full"), std::string::npos) << e.what();
  }
  std::ifstream after_stream(file, std::ios::binary);
  const std::string after((std::istreambuf_iterator<char>(after_stream)), std::istreambuf_iterator<char>());
  EXPECT_EQ(after, before);
  EXPECT_FALSE(std::ifstream(file + ".partial").good());
  lbm::FluidSolver resumed(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  lbm::read_checkpoint(resumed, path);
  EXPECT_EQ(resumed.time_step(), 0);
}

