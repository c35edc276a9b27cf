// Mass conservation at interpolated moving walls over long runs: a fixed
// sphere in a dense periodic simple-cubic array driven by a body force (solid fraction 0.22
// and 0.45, d ~ 8 cells) and a sphere spinning in a closed box, with Bouzidi and
// Mei-Luo-Shyy, 50,000 steps each. Without the link mass correction
// (lbm/moving_wall/link_mass.h) the array's mass grows by up to 8 % and the momentum
// exchange never balances the body force; the DISABLED_ test prints those figures and
// asserts the drift the correction removes (--gtest_also_run_disabled_tests).
#include <gtest/gtest.h>

#include <cstdio>

#include "cases/link_mass_runs.h"

using lbm::MovingWallScheme;

namespace {
constexpr long kSteps = 50000;

struct Packing {
  double solid_fraction;
  int period;  // cells; the diameter follows (8.2 and 8.6 cells)
};
constexpr Packing kPackings[] = {{0.22, 11}, {0.45, 9}};
constexpr MovingWallScheme kSchemes[] = {MovingWallScheme::kBouzidi, MovingWallScheme::kMeiLuoShyy};

void print(const char* what, MovingWallScheme scheme, bool conserve, const cases::LinkMassRun& r) {
  std::printf("%-28s %-13s correction %-3s: mass drift %+.3e, link defect %+.3e, "
              "F_me/(g N_fluid) %.7f (last step %.5f), dU/U last 1000 steps %.1e (%ld steps)\n",
              what, lbm::moving_wall::label(scheme), conserve ? "on" : "off", r.mass_drift,
              r.link_defect, r.force_balance, r.force_last_step, r.velocity_change, r.steps);
}

void run_all(bool conserve) {
  for (const Packing& p : kPackings)
    for (MovingWallScheme scheme : kSchemes) {
      char what[64];
      std::snprintf(what, sizeof what, "SC array phi %.2f L %d", p.solid_fraction, p.period);
      const cases::LinkMassRun r =
          cases::dense_array_run(p.solid_fraction, p.period, scheme, conserve, kSteps);
      print(what, scheme, conserve, r);
      // Without the correction: drift +4e-4 to +1.4e-3, velocity change 8e-6 to 2.9e-5, what
      // the correction is there to remove.
      if (!conserve) {
        EXPECT_GT(r.mass_drift, 1e-4) << what;
        continue;
      }
      // Measured: drift -2.3e-12 to -2.8e-12 (round-off), force balance 1.0000000, velocity
      // change 2e-15 to 1.2e-13 (MLS phi 0.45: 8.7e-9, its period-two oscillation grows).
      EXPECT_LT(std::abs(r.mass_drift), 1e-10) << what;
      EXPECT_NEAR(r.force_balance, 1.0, 1e-5) << what;
      EXPECT_LT(r.velocity_change, 1e-7) << what;
    }
  for (MovingWallScheme scheme : kSchemes) {
    const cases::LinkMassRun r = cases::spinning_sphere_run(scheme, conserve, kSteps);
    print("spinning sphere, closed box", scheme, conserve, r);
    // Measured -2.1e-12; without the correction +3.1e-3 (MLS), +8.2e-3.
    if (conserve) {
      EXPECT_LT(std::abs(r.mass_drift), 1e-10);
    } else {
      EXPECT_GT(r.mass_drift, 1e-3);
    }
  }
}
}  // namespace

TEST(LinkMass, DenseArraysAndClosedBoxConserveMass) { run_all(true); }

TEST(LinkMass, DISABLED_WithoutCorrectionTheMassDrifts) { run_all(false); }
