#include <gtest/gtest.h>

#include <cmath>

#include "contact/dash_dot.h"
#include "contact/pair_contact.h"

using namespace contact;

TEST(DashDot, ForceIsSpringPlusDashpot) {
  DashDotParams p{0.1, 0.25};
  NormalContactInput in{0.02, 0.5, 4.0};
  const double k_d = 2.0 * 0.25 * std::sqrt(0.1 * 4.0);
  EXPECT_DOUBLE_EQ(dash_dot_force(p, in), 0.1 * 0.02 + k_d * 0.5);
}

TEST(DashDot, NoForceWithoutOverlap) {
  DashDotParams p;
  EXPECT_EQ(dash_dot_force(p, {-0.01, 3.0, 1.0}), 0.0);
  EXPECT_EQ(dash_dot_force(p, {0.0, 3.0, 1.0}), 0.0);
}

TEST(DashDot, DefaultDampingIsThePaperTableValue) {
  // Paper appendix: k_d = 0.5 sqrt(k_n mi mj / (mi + mj)).
  DashDotParams p;
  const double mi = 3.0, mj = 5.0, m_eff = mi * mj / (mi + mj);
  EXPECT_NEAR(damping_coefficient(p, m_eff), 0.5 * std::sqrt(p.k_n * m_eff), 1e-15);
}

// Velocity-Verlet integration of a head-on collision of a particle with a fixed body:
// restitution converges to the analytic e(zeta) as the step shrinks.
double simulated_restitution(double zeta, int steps_per_contact) {
  DashDotParams p{1.0, zeta};
  const double m = 1.0;
  const double dt = contact_duration(p, m) / steps_per_contact;
  double gap = 0.001, v = -1.0;  // approaching
  auto force = [&](double g, double vel) {
    return pair_normal_force({p, CohesionParams{0.0}}, {g, vel, 1.0, 1.0, m});
  };
  double f = force(gap, v);
  for (int step = 0; step < 100 * steps_per_contact; ++step) {
    v += 0.5 * dt * f / m;
    gap += dt * v;
    f = force(gap, v);
    v += 0.5 * dt * f / m;
    if (gap > 0.0 && v > 0.0 && step > 2) break;
  }
  return v / 1.0;
}

TEST(DashDot, RestitutionMatchesAnalyticValue) {
  for (double zeta : {0.1, 0.25, 0.5}) {
    const double e = restitution_coefficient(zeta);
    EXPECT_NEAR(simulated_restitution(zeta, 1000), e, 0.005 * e) << "zeta " << zeta;
  }
  EXPECT_NEAR(restitution_coefficient(0.25), std::exp(-M_PI * 0.25 / std::sqrt(1 - 0.0625)),
              1e-15);
}

TEST(DashDot, ContactDurationAndStabilityLimit) {
  DashDotParams p{4.0, 0.0};
  EXPECT_NEAR(contact_duration(p, 1.0), M_PI / 2.0, 1e-14);
  EXPECT_NEAR(stability_limit(p, 1.0), 1.0, 1e-14);
}
