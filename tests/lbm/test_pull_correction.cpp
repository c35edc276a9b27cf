// CollideStreamArgs::pull_corrections (FluidSolver::correct_pulls_in_next_step): densities
// taken off the populations a node pulls, in the kernel's pass, are the link mass correction
// that LinkMassRestorer writes into those slots before the pass (lbm/moving_wall/link_mass.h):
// the same bits after the step, a node's entries taken in their order, and nothing taken
// where none was given.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <vector>

#include "cases/serial_flow.h"
#include "cases/staged_step.h"
#include "lbm/moving_wall/link_mass.h"

namespace {

std::unique_ptr<lbm::FluidSolver> stirred_solver() {
  lbm::VoxelGeometry g({12, 10, 8});
  g.set_solid(5, 4, 3, true);
  lbm::FluidParameters p;
  p.tau = 0.9;
  p.periodic = {true, true, true};
  p.body_force = {2e-6, 0.0, -1e-6};
  auto solver = std::make_unique<lbm::FluidSolver>(g, p, lbm::FlowDrive{},
                                                   cases::serial_decomposition(g, p.periodic));
  solver->initialise_equilibrium([](int i, int j, int k) {
    return std::array<double, 4>{1.0 + 0.01 * std::sin(0.7 * i + 0.3 * k), 0.02 * std::cos(0.5 * j),
                                 -0.01 * std::sin(0.9 * k), 0.015 * std::cos(0.4 * i)};
  });
  solver->step();
  return solver;
}

// Fluid nodes next to the solid cell and elsewhere, in ascending cell order, with defects of
// either sign; the first node has three entries (three links), whose order matters.
const struct {
  int i, j, k;
  double d;
} kEntries[] = {{10, 2, 1, 9e-5},  {4, 4, 3, 3.1e-4}, {4, 4, 3, -1.3e-7}, {4, 4, 3, 2.2e-9},
                {6, 4, 3, -2.2e-4}, {5, 5, 3, 1.7e-5}, {1, 8, 6, -4.4e-4}};

struct Entries {
  std::vector<std::uint32_t> cell;
  std::vector<double> defect;
};

// All of them, or only those of the nodes with no link to the solid cell.
Entries entries(const lbm::BlockLayout& layout, bool away_from_solid = false) {
  Entries e;
  for (const auto& n : kEntries) {
    if (away_from_solid && std::abs(n.i - 5) <= 1 && std::abs(n.j - 4) <= 1 && std::abs(n.k - 3) <= 1)
      continue;
    e.cell.push_back(std::uint32_t(layout.cell(n.i, n.j, n.k)));
    e.defect.push_back(n.d);
  }
  return e;
}

}  // namespace

TEST(PullCorrection, SameBitsAsTheCorrectionWrittenIntoTheSlots) {
  auto in_slots = stirred_solver(), in_kernel = stirred_solver();
  const Entries e = entries(in_kernel->layout());
  ASSERT_TRUE(std::is_sorted(e.cell.begin(), e.cell.end()));
  for (int step = 0; step < 3; ++step) {
    const lbm::moving_wall::LinkMassRestorer restorer(in_slots->layout(), in_slots->node_types(),
                                                      in_slots->populations());
    // remove_node with each node's entries, in their order (as the moving walls' sweep).
    std::vector<std::uint32_t> ids(e.cell.size());
    for (std::size_t i = 0; i < ids.size(); ++i) ids[i] = std::uint32_t(i);
    for (std::size_t i = 0; i < ids.size();) {
      std::size_t end = i + 1;
      while (end < ids.size() && e.cell[end] == e.cell[i]) ++end;
      restorer.remove_node(e.cell[i], e.defect.data(), ids.data() + i, ids.data() + end);
      i = end;
    }
    in_kernel->correct_pulls_in_next_step(e.cell.data(), e.defect.data(), e.cell.size());
    in_slots->collide_stream();
    in_kernel->collide_stream();
    EXPECT_EQ(cases::max_population_difference(*in_slots, *in_kernel), 0.0) << "step " << step;
  }
}

TEST(PullCorrection, TakesMassOnlyWhenGiven) {
  // (A bare collide-stream moves mass into the solid cell's slots, and how much depends on
  // the populations of the nodes next to it: compare with a twin, at nodes away from it.)
  auto given = stirred_solver(), plain = stirred_solver();
  const Entries e = entries(given->layout(), true);
  ASSERT_EQ(e.cell.size(), 2u);
  given->correct_pulls_in_next_step(e.cell.data(), e.defect.data(), e.cell.size());
  given->collide_stream();
  plain->collide_stream();
  // The nodes lost exactly their defects (sum_q w_q = 1) and no momentum moved. Sums of 960
  // densities of about 1: round-off 1e-12.
  double total = 0.0;
  for (const double d : e.defect) total += d;
  const double taken = cases::fluid_mass(*given) - cases::fluid_mass(*plain);
  EXPECT_NEAR(taken, -total, 1e-12);
  // Taken once: a further pass takes nothing more.
  given->collide_stream();
  plain->collide_stream();
  EXPECT_NEAR(cases::fluid_mass(*given) - cases::fluid_mass(*plain), taken, 1e-12);
}
