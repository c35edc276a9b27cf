// Where a run's time went (coupling/diagnostics/run_timer.h) on a clock the test sets: the
// parts' scopes nest, the rest is what no scope took, and the report reads the coupling's
// own stage times; the stage timer adds its seconds (coupling/stage_clock.h).
#include <gtest/gtest.h>

#include <cstdio>
#include <string>

#include "cases/serial_flow.h"
#include "coupling/diagnostics/run_timer.h"
#include "coupling/stage_clock.h"

using coupling::RunTimer;

namespace {
double g_now = 0.0;
double test_clock() { return g_now; }
}  // namespace

TEST(RunTimer, ScopesNestAndEachSecondGoesToOnePart) {
  RunTimer timer(test_clock);
  g_now = 100.0;
  timer.start();
  g_now = 101.0;  // 1 s of the rest
  {
    const RunTimer::Scope fluid(timer, RunTimer::kFluid);
    g_now = 103.0;  // 2 s of fluid
    {
      const RunTimer::Scope walls(timer, RunTimer::kLubrication);
      g_now = 103.5;  // 0.5 s of lubrication, not fluid
    }
    g_now = 104.0;  // 0.5 s more of fluid
    timer.count_fluid_step();
  }
  {
    const RunTimer::Scope diagnostics(timer, RunTimer::kDiagnostics);
    g_now = 104.25;
  }
  EXPECT_EQ(timer.seconds(RunTimer::kFluid), 2.5);
  EXPECT_EQ(timer.seconds(RunTimer::kLubrication), 0.5);
  EXPECT_EQ(timer.seconds(RunTimer::kDiagnostics), 0.25);
  EXPECT_EQ(timer.fluid_steps(), 1);
  g_now = 200.0;
  timer.start();  // a new run forgets the last one
  EXPECT_EQ(timer.seconds(RunTimer::kFluid), 0.0);
  EXPECT_EQ(timer.fluid_steps(), 0);
}

TEST(RunTimer, TheReportReadsTheCouplingsStageTimes) {
  auto solver = cases::make_solver({8, 8, 8}, {true, true, true});
  coupling::SphereCoupling coupling(*solver);
  RunTimer timer(test_clock);
  g_now = 0.0;
  timer.start();
  EXPECT_EQ(timer.report(coupling), "");  // no fluid step yet
  {
    const RunTimer::Scope fluid(timer, RunTimer::kFluid);
    g_now = 3.0;
    timer.count_fluid_step();
    timer.count_fluid_step();
  }
  g_now = 4.0;
  const std::string report = timer.report(coupling);
  EXPECT_NE(report.find("fix lbm/pore: 2 fluid steps in 4.000 s: fluid 3.000 s"), std::string::npos) << report;
  EXPECT_NE(report.find("DEM and the rest 1.000 s; 2 s per fluid step\n"), std::string::npos) << report;
  EXPECT_NE(report.find("coupling stages since the lattice was built: mapping 0.000 s"), std::string::npos)
      << report;
  EXPECT_EQ(report.find("halo exchange of the coupled steps"), std::string::npos);  // none counted
}

// The balance line compares ranks: on one rank there is nothing to compare (the 2-rank line
// is checked by the pore_parallel integration test).
TEST(RunTimer, TheBalanceLineNeedsMoreThanOneRank) {
  auto solver = cases::make_solver({8, 8, 8}, {true, true, true});
  coupling::SphereCoupling coupling(*solver);
  RunTimer timer(test_clock);
  g_now = 0.0;
  timer.start();
  timer.count_fluid_step();
  EXPECT_EQ(timer.balance_report(coupling, solver->decomposition().comm), "");
}

// The fourth line counts the links the coupling applied per step, as the links of the step
// are: a sphere at rest keeps the same links every step.
TEST(RunTimer, TheReportCountsTheLinksPerStep) {
  auto solver = cases::make_solver({16, 16, 16}, {true, true, true});
  coupling::SphereCoupling coupling(*solver);
  coupling::ParticleSet particles;
  particles.add(1, {8.2, 7.9, 8.4}, {0, 0, 0}, 3.5);
  RunTimer timer(test_clock);
  timer.start();
  for (int step = 0; step < 3; ++step) {
    coupling.step(particles.view());
    timer.count_fluid_step();
  }
  const auto& links = coupling.links().links;
  ASSERT_GT(links.size(), 100u);  // a sphere of radius 3.5 cells: several hundred links
  EXPECT_EQ(coupling.link_counts().steps, 3);
  EXPECT_EQ(coupling.link_counts().links, 3 * static_cast<long long>(links.size()));
  char expected[200];
  std::snprintf(expected, sizeof expected,
                "fix lbm/pore: links of the moving surfaces on this rank: %zu per fluid step;",
                links.size());
  const std::string report = timer.report(coupling);
  EXPECT_NE(report.find(expected), std::string::npos) << report;
  EXPECT_NE(report.find("fluid-cell updates per link (collide-stream"), std::string::npos) << report;
  EXPECT_NE(report.find("of 4096 cells)"), std::string::npos) << report;  // 16^3, no walls
}

TEST(StageClock, AStageTimerAddsItsSecondsToItsTotal) {
  double total = 1.0;
  const double before = coupling::clock_seconds();
  {
    const coupling::StageTimer t(total);
    while (coupling::clock_seconds() == before) {
    }
  }
  EXPECT_GT(total, 1.0);
  EXPECT_LE(total - 1.0, coupling::clock_seconds() - before);
}
