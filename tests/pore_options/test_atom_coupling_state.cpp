// fix lbm/pore's per-atom state: every field survives the flat buffer LIGGGHTS moves it in
// (exchange, restart), and the reverse communication sums exactly the fluid step's load.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "atom_coupling_state.h"

using lbm_pore::AtomCouplingState;

namespace {
AtomCouplingState numbered() {
  AtomCouplingState s;
  double v = 1.0;
  auto next = [&] { return v += 1.0; };
  for (auto* vec : {&s.load.force, &s.load.torque, &s.load.step_velocity, &s.load.previous_force,
                    &s.load.previous_velocity, &s.motion.position, &s.fluid_velocity, &s.wall.normal,
                    &s.wall.searched_from, &s.motion.last_velocity})
    for (double& x : *vec) x = next();
  s.load.coefficient = next();
  s.tag = 42.0;
  s.wall.distance = next();
  s.motion.has_position = true;
  s.motion.has_last_velocity = true;
  s.wall.known = true;
  return s;
}

bool same(const AtomCouplingState& a, const AtomCouplingState& b) {
  return a.load.force == b.load.force && a.load.torque == b.load.torque &&
         a.load.coefficient == b.load.coefficient && a.load.step_velocity == b.load.step_velocity &&
         a.load.previous_force == b.load.previous_force && a.load.previous_velocity == b.load.previous_velocity &&
         a.motion.position == b.motion.position && a.motion.has_position == b.motion.has_position &&
         a.motion.last_velocity == b.motion.last_velocity &&
         a.motion.has_last_velocity == b.motion.has_last_velocity &&
         a.fluid_velocity == b.fluid_velocity && a.tag == b.tag && a.wall.known == b.wall.known &&
         a.wall.distance == b.wall.distance && a.wall.normal == b.wall.normal &&
         a.wall.searched_from == b.wall.searched_from;
}
}  // namespace

TEST(AtomCouplingState, EveryFieldSurvivesTheFlatBuffer) {
  const AtomCouplingState s = numbered();
  std::vector<double> buffer(AtomCouplingState::kDoubles + 1, -7.0);
  s.pack(buffer.data());
  EXPECT_EQ(buffer[AtomCouplingState::kDoubles], -7.0);  // writes exactly kDoubles
  AtomCouplingState back;
  back.unpack(buffer.data());
  EXPECT_TRUE(same(s, back));
  // All values distinct: a field packed twice or not at all would show.
  std::vector<double> sorted(buffer.begin(), buffer.end() - 1);
  std::sort(sorted.begin(), sorted.end());
  EXPECT_EQ(std::unique(sorted.begin(), sorted.end()) - sorted.begin(), AtomCouplingState::kDoubles - 2)
      << "only the three flags share the value 1";
}

// A restart file of the layout before motion.last_velocity: its kDoubles1 values are the
// prefix of today's, the field added since starts unset (the two-step mean then begins with
// the one-step one).
TEST(AtomCouplingState, TheEarlierLayoutReadsAsAPrefix) {
  const AtomCouplingState s = numbered();
  std::vector<double> buffer(AtomCouplingState::kDoubles);
  s.pack(buffer.data());
  AtomCouplingState back;
  back.motion.last_velocity = {9.0, 9.0, 9.0};
  back.unpack(buffer.data(), AtomCouplingState::kDoubles1);
  AtomCouplingState expected = s;
  expected.motion.last_velocity = {0.0, 0.0, 0.0};
  expected.motion.has_last_velocity = false;
  EXPECT_TRUE(same(expected, back));
}

TEST(AtomCouplingState, ReverseCommunicationSumsTheForceTorqueAndCoefficient) {
  AtomCouplingState owner = numbered(), ghost = numbered();
  const AtomCouplingState before = owner;
  std::vector<double> buffer(AtomCouplingState::kSummed);
  ghost.pack_summed(buffer.data());
  owner.add_summed(buffer.data());
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(owner.load.force[a], 2.0 * before.load.force[a]);
    EXPECT_EQ(owner.load.torque[a], 2.0 * before.load.torque[a]);
    EXPECT_EQ(owner.load.step_velocity[a], before.load.step_velocity[a]);
  }
  EXPECT_EQ(owner.load.coefficient, 2.0 * before.load.coefficient);
}
