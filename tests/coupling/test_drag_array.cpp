// Drag on a fixed sphere in a periodic simple-cubic array driven by a body force g, against
// Sangani & Acrivos (1982); the set-up is cases/sphere_array_drag.h, shared with
// examples/accuracy. The momentum exchange must also balance the body force on the fluid:
// F_me = g N_fluid.
#include <gtest/gtest.h>

#include <cstdio>

#include "cases/sphere_array_drag.h"

using namespace coupling;
using lbm::MovingWallScheme;

namespace {
struct ArrayResult {
  cases::DragArrayRun run;
  double seconds = 0.0;
};

ArrayResult run_array(int diameter, MovingWallScheme scheme) {
  cases::Stopwatch watch;
  ArrayResult r;
  r.run = cases::drag_in_sphere_array(diameter, scheme, 8000);
  r.seconds = watch.seconds();
  return r;
}
}  // namespace

TEST(DragArray, MeiLuoShyyMatchesSangoniAcrivos) {
  const double K_ref = cases::kDragKRef;
  double previous_error = 1.0;
  for (int d : {6, 8, 12}) {
    const ArrayResult r = run_array(d, MovingWallScheme::kMeiLuoShyy);
    const double error = r.run.K / K_ref - 1.0;
    std::printf(
        "SC array chi=0.5 d=%2d Mei-Luo-Shyy: K = %.4f (ref 2.8420, error %+.2f %%), "
        "F_me/(g N_fluid) = %.5f, %ld steps, %.2f s\n",
        d, r.run.K, 100 * error, r.run.force_balance, r.run.steps, r.seconds);
    // Measured -4.8 %, -2.3 %, -1.2 % with the link mass correction (-5.0, -2.6, -1.4 %
    // without it) (d = 6, 8, 12; first- to second-order convergence,
    // the sphere looks slightly small to the flow): bounds with ~30 % margin.
    const double bound = d == 6 ? 0.065 : (d == 8 ? 0.035 : 0.02);
    EXPECT_LT(std::abs(error), bound) << "d = " << d;
    EXPECT_LT(std::abs(error), previous_error) << "the error must shrink with resolution";
    previous_error = std::abs(error);
    EXPECT_NEAR(r.run.force_balance, 1.0, 1e-3) << "d = " << d;
  }
}

TEST(DragArray, OtherSchemesForComparison) {
  const double K_ref = cases::kDragKRef;
  for (MovingWallScheme scheme : {MovingWallScheme::kBouzidi, MovingWallScheme::kBounceBack}) {
    const ArrayResult r = run_array(8, scheme);
    const double error = r.run.K / K_ref - 1.0;
    std::printf(
        "SC array chi=0.5 d= 8 %s: K = %.4f (error %+.2f %%), F_me/(g N_fluid) = %.5f, %.2f s\n",
        lbm::moving_wall::label(scheme), r.run.K, 100 * error, r.run.force_balance, r.seconds);
    EXPECT_NEAR(r.run.force_balance, 1.0, 1e-3);
    // Measured at d = 8: Bouzidi -2.3 % (-2.8 % without the link mass correction),
    // bounce-back +2.6 % (its errors do not shrink
    // systematically with resolution, the wall sits mid-link whatever the fraction).
    EXPECT_LT(std::abs(error), 0.04);
  }
}
