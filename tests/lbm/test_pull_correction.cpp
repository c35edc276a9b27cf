// CollideStreamArgs::pull_correction (FluidSolver::pull_correction_for_next_step): a density
// d(x) taken off the populations node x pulls, d(x) w_q from each, in the kernel's pass, is
// the link mass correction that LinkMassRestorer writes into those slots before the pass
// (lbm/moving_wall/link_mass.h): the same populations after the step to round-off (the
// kernel may fuse w_q d into its subtraction), the field zero again after it, and nothing
// taken where it was not armed.
#include <gtest/gtest.h>

#include <cmath>

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

// Fluid nodes next to the solid cell and elsewhere, with defects of either sign.
const struct {
  int i, j, k;
  double d;
} kNodes[] = {{4, 4, 3, 3.1e-4}, {6, 4, 3, -2.2e-4}, {5, 5, 3, 1.7e-5}, {1, 8, 6, -4.4e-4}, {10, 2, 1, 9e-5}};

}  // namespace

TEST(PullCorrection, EqualsTheCorrectionWrittenIntoTheSlots) {
  auto in_slots = stirred_solver(), in_kernel = stirred_solver();
  for (int step = 0; step < 3; ++step) {
    const lbm::moving_wall::LinkMassRestorer restorer(in_slots->layout(), in_slots->node_types(),
                                                      in_slots->populations());
    double* const d = in_kernel->pull_correction_for_next_step();
    for (const auto& n : kNodes) {
      restorer.remove(in_slots->layout().cell(n.i, n.j, n.k), n.d);
      d[in_kernel->layout().cell(n.i, n.j, n.k)] = n.d;
    }
    in_slots->collide_stream();
    in_kernel->collide_stream();
    // Populations of about 0.03-0.33: a few roundings of their size.
    EXPECT_LT(cases::max_population_difference(*in_slots, *in_kernel), 1e-15);
    EXPECT_NEAR(cases::fluid_mass(*in_slots), cases::fluid_mass(*in_kernel), 1e-12);
  }
  // Taken and zeroed: the field holds nothing for the next step.
  const double* const d = in_kernel->pull_correction_for_next_step();
  for (std::size_t c = 0; c < in_kernel->layout().num_cells(); ++c) ASSERT_EQ(d[c], 0.0) << "cell " << c;
}

TEST(PullCorrection, TakesMassOnlyWhenArmed) {
  // (A bare collide-stream moves mass into the solid cell's slots: compare with a twin.)
  auto armed = stirred_solver(), plain = stirred_solver();
  const auto& n = kNodes[3];
  armed->pull_correction_for_next_step()[armed->layout().cell(n.i, n.j, n.k)] = n.d;
  armed->collide_stream();
  plain->collide_stream();
  // The node lost exactly d (sum_q w_q = 1) and no momentum moved. Sums of 960 densities
  // of about 1: round-off 1e-12.
  const double taken = cases::fluid_mass(*armed) - cases::fluid_mass(*plain);
  EXPECT_NEAR(taken, -n.d, 1e-12);
  // Not armed again: a further pass takes nothing more.
  armed->collide_stream();
  plain->collide_stream();
  EXPECT_NEAR(cases::fluid_mass(*armed) - cases::fluid_mass(*plain), taken, 1e-12);
}
