// Pore diagnostics: deposited volume and length, particle plane crossings.
#include <gtest/gtest.h>

#include "cases/serial_flow.h"
#include "coupling/diagnostics/pore_diagnostics.h"
#include "coupling/sphere_coupling.h"

using namespace coupling;

TEST(Diagnostics, DepositedVolumeCountsBondedSlowParticlesInThePore) {
  ParticleSet p;
  p.add(1, {10, 5, 5}, {0, 0, 0}, 2.0);      // deposited
  p.add(2, {10, 5, 5}, {0.01, 0, 0}, 2.0);   // too fast
  p.add(3, {10, 9.5, 5}, {0, 0, 0}, 2.0);    // outside the pore radius
  p.add(4, {30, 5, 5}, {0, 0, 0}, 2.0);      // beyond the pore's end
  p.add(5, {12, 6, 4}, {0, 0, 0}, 2.0);      // not bonded
  const std::vector<char> bonded{1, 1, 1, 1, 0};
  PoreRegion pore;
  pore.axis = 0;
  pore.start = 5;
  pore.end = 20;
  pore.centre = {5, 5};
  pore.diameter = 8;
  const Deposition d = deposited(p.view(), bonded, pore, DepositionCriteria{}, lbm::Communicator{});
  const double v = 4.0 / 3.0 * cases::kPi * 8.0;
  EXPECT_EQ(d.count, 1);
  EXPECT_NEAR(d.volume, v, 1e-12);
  EXPECT_NEAR(d.length, v / (cases::kPi * 16.0), 1e-12);
}

TEST(Diagnostics, PlaneCrossingsAreCountedWithDirection) {
  ParticleSet p;
  p.add(1, {9.5, 0, 0}, {0, 0, 0}, 1.0);
  p.add(2, {10.5, 0, 0}, {0, 0, 0}, 1.0);
  p.add(3, {3.0, 0, 0}, {0, 0, 0}, 1.0);
  PlaneCrossingCounter counter(0, 10.0);
  EXPECT_EQ(counter.update(p.view(), 40.0, lbm::Communicator{}).count, 0);  // records only
  p.set_position(0, {10.2, 0, 0});  // forward
  p.set_position(2, {39.0, 0, 0});  // periodic wrap, ignored
  auto c = counter.update(p.view(), 40.0, lbm::Communicator{});
  EXPECT_EQ(c.count, 1);
  EXPECT_NEAR(c.volume, 4.0 / 3.0 * cases::kPi, 1e-12);
  p.set_position(0, {9.0, 0, 0});   // back
  p.set_position(1, {9.9, 0, 0});   // back
  EXPECT_EQ(counter.update(p.view(), 40.0, lbm::Communicator{}).count, -2);
}
