// What fix lbm/pore does with its per-atom states, without LIGGGHTS (atom_states.h,
// lattice_particles.h, restart_record.h): a slot of another atom is reset, the velocity the
// fluid sees travels to the ghosts and into the lattice copies, the loads come back in script
// units and the ghosts' shares sum onto their owners, restart entries of both layouts read
// back; the monitor's restart record and the set-up helpers of pore_scene_setup.h.
#include <gtest/gtest.h>

#include <cstring>
#include <string>
#include <vector>

#include "atom_states.h"
#include "lattice_particles.h"
#include "lbm_pore_options.h"
#include "pore_scene_setup.h"
#include "restart_record.h"

using lbm_pore::AtomArrays;
using lbm_pore::AtomCouplingState;
using lbm_pore::AtomStates;

namespace {
// Two owned atoms (tags 5, 6) and one ghost (an image of atom 5), rows as LIGGGHTS keeps them.
struct Atoms {
  double x_data[9] = {1.0, 1.0, 1.0, 3.0, 1.0, 1.0, 11.0, 1.0, 1.0};
  double v_data[9] = {0.1, 0.0, 0.0, 0.0, 0.2, 0.0, 0.1, 0.0, 0.0};
  double* x[3] = {x_data, x_data + 3, x_data + 6};
  double* v[3] = {v_data, v_data + 3, v_data + 6};
  int tag[3] = {5, 6, 5};
  int mask[3] = {1, 1, 1};
  double radius[3] = {0.5, 0.25, 0.5};
  AtomArrays arrays() { return {2, 1, mask, 1, tag, x, v, nullptr, radius}; }
};

coupling::UnitConversion units(double dx = 0.5) {
  coupling::UnitInputs in;
  in.dx = dx;
  in.rho = 2.0;
  in.nu = 1.0 / 6.0 * dx * dx;  // tau 1 at dt_lbm = 1
  return coupling::UnitConversion(in);
}
}  // namespace

TEST(AtomStates, ASlotThatHeldAnotherAtomIsResetBeforeUse) {
  AtomStates states;
  states.resize(2);
  states.reset(0, 5.0);
  states[0].load.force = {1.0, 2.0, 3.0};
  EXPECT_EQ(states.own(0, 5.0).load.force[0], 1.0);   // its own atom: kept
  EXPECT_EQ(states.own(0, 9.0).load.force[0], 0.0);   // another atom now: reset
  EXPECT_EQ(states[0].tag, 9.0);
}

TEST(AtomStates, TheVelocityTheFluidSeesReachesTheGhostsAndTheLatticeCopies) {
  Atoms atoms;
  AtomStates states;
  states.resize(3);
  const auto no_wrap = [](double*) {};
  states.step_motion(atoms.arrays(), 1.0, false, no_wrap);  // a run's start: the velocities
  atoms.x_data[0] += 0.25;                                  // atom 5 moves 0.25 in a step
  states.step_motion(atoms.arrays(), 1.0, true, no_wrap);
  EXPECT_EQ(states[0].fluid_velocity, (coupling::Vec3{0.25, 0.0, 0.0}));
  EXPECT_EQ(states[1].fluid_velocity, (coupling::Vec3{0.0, 0.0, 0.0}));  // atom 6 stood still
  // Forward communication to the ghost (slot 2), as LIGGGHTS's Comm would do it.
  std::vector<double> buffer(AtomStates::kForward);
  const int list[1] = {0};
  EXPECT_EQ(states.pack_forward(1, list, nullptr, buffer.data()), AtomStates::kForward);
  states.unpack_forward(1, 2, nullptr, buffer.data());
  EXPECT_EQ(states[2].fluid_velocity, states[0].fluid_velocity);
  // The lattice copies: positions through the frame, the velocity the fluid sees and radii
  // through the units (dx 0.5, dt_lbm 1).
  const coupling::UnitConversion u = units();
  coupling::LatticeFrame frame;
  frame.dx = 0.5;
  lbm_pore::LatticeParticles particles;
  particles.gather(states.seen_by_fluid(atoms.arrays()), frame, u);
  const coupling::ParticleView view = particles.view();
  ASSERT_EQ(view.num_total, 3u);
  EXPECT_EQ(view.num_owned, 2u);
  EXPECT_EQ(view.v(0)[0], states[0].fluid_velocity[0] * u.velocity_to_lattice_factor());
  EXPECT_EQ(view.v(2)[0], view.v(0)[0]);
  EXPECT_EQ(view.r(1), 0.5);
  EXPECT_EQ(view.x(1)[0], 6.0);
  EXPECT_EQ(lbm_pore::host_view(atoms.arrays()).v(1)[1], 0.2);  // the host's own velocities
}

TEST(AtomStates, LoadsComeBackInScriptUnitsAndGhostSharesSumOntoTheirOwners) {
  Atoms atoms;
  AtomStates states;
  states.resize(3);
  for (int i = 0; i < 3; ++i) states.reset(i, atoms.tag[i]);
  const coupling::UnitConversion u = units();
  coupling::LatticeFrame frame;
  frame.dx = 0.5;
  lbm_pore::LatticeParticles particles;
  particles.gather(atoms.arrays(), frame, u);
  coupling::HydrodynamicLoads loads;
  loads.reset(3);
  loads.force = {{1.0, 0.0, 0.0}, {0.0, 2.0, 0.0}, {0.5, 0.0, 0.0}};
  loads.torque = {{0.0, 0.0, 1.0}, {0.0, 0.0, 0.0}, {0.0, 0.0, 0.25}};
  loads.velocity_coefficient = {3.0, 4.0, 1.0};
  states.start_fluid_step(2, 3);
  states.store_loads(particles, loads, u);
  EXPECT_EQ(states[0].load.force[0], 1.0 * u.force_unit());
  EXPECT_EQ(states[0].load.torque[2], 1.0 * u.torque_unit());
  EXPECT_EQ(states[1].load.coefficient, 4.0 * u.velocity_coefficient_unit());
  // Reverse communication: the ghost's share onto its owner, slot 0.
  std::vector<double> buffer(AtomStates::kReverse);
  EXPECT_EQ(states.pack_reverse(1, 2, buffer.data()), AtomStates::kReverse);
  const int list[1] = {0};
  states.unpack_reverse(1, list, buffer.data());
  EXPECT_EQ(states[0].load.force[0], 1.0 * u.force_unit() + 0.5 * u.force_unit());
  EXPECT_EQ(states[0].load.torque[2], 1.0 * u.torque_unit() + 0.25 * u.torque_unit());
  EXPECT_EQ(states[0].load.coefficient, 3.0 * u.velocity_coefficient_unit() + 1.0 * u.velocity_coefficient_unit());
}

TEST(AtomStates, RestartEntriesOfBothLayoutsReadAForeignOneIsRefusedAndExchangeMovesTheState) {
  AtomStates states;
  states.resize(2);
  states.reset(0, 7.0);
  states[0].motion.last_velocity = {1.0, 2.0, 3.0};
  states[0].motion.has_last_velocity = true;
  std::vector<double> entry(AtomStates::kRestart + 1, -1.0);
  EXPECT_EQ(states.pack_restart(0, entry.data()), AtomStates::kRestart);
  EXPECT_EQ(entry[0], double(AtomStates::kRestart));
  ASSERT_TRUE(states.unpack_restart(1, entry.data()));
  EXPECT_EQ(states[1].tag, 7.0);
  EXPECT_EQ(states[1].motion.last_velocity, (coupling::Vec3{1.0, 2.0, 3.0}));
  entry[0] = AtomCouplingState::kDoubles1 + 1;  // the layout before the two-step velocity
  ASSERT_TRUE(states.unpack_restart(1, entry.data()));
  EXPECT_EQ(states[1].tag, 7.0);
  EXPECT_FALSE(states[1].motion.has_last_velocity);
  entry[0] = 12.0;
  EXPECT_FALSE(states.unpack_restart(1, entry.data()));
  EXPECT_EQ(states[1].tag, 7.0);  // untouched
  // Exchange: the state alone, no size.
  std::vector<double> moved(AtomCouplingState::kDoubles);
  EXPECT_EQ(states.pack_exchange(0, moved.data()), AtomCouplingState::kDoubles);
  states.reset(1, 8.0);
  EXPECT_EQ(states.unpack_exchange(1, moved.data()), AtomCouplingState::kDoubles);
  EXPECT_EQ(states[1].tag, 7.0);
  EXPECT_TRUE(states[1].motion.has_last_velocity);
}

TEST(RestartRecord, TheMonitorStateAndTheCheckpointPathRoundTrip) {
  const lbm_pore::RestartRecord record{{3.0, 1.5, -2.0}, "out/pore.fluid.1200", {0.001, 0.25}};
  const std::string bytes = record.bytes();
  EXPECT_EQ(bytes.size(), 8 * sizeof(double) + record.checkpoint.size() + 1);
  const lbm_pore::RestartRecord back = lbm_pore::RestartRecord::read(bytes.data());
  EXPECT_EQ(back.monitor_state, record.monitor_state);
  EXPECT_EQ(back.drive_state, record.drive_state);
  EXPECT_EQ(back.checkpoint, record.checkpoint);
  // A record written before the drive had a state: the monitor's values and the path, read
  // with an empty drive state (restart files of runs parked then continue).
  std::string old(sizeof(double), '\0');
  const double count = 2.0, values[2] = {7.0, -1.0};
  std::memcpy(old.data(), &count, sizeof(double));
  old.append(reinterpret_cast<const char*>(values), sizeof values);
  old.append("pore.fluid.800", 15);
  const lbm_pore::RestartRecord earlier = lbm_pore::RestartRecord::read(old.data());
  EXPECT_EQ(earlier.monitor_state, std::vector<double>({7.0, -1.0}));
  EXPECT_TRUE(earlier.drive_state.empty());
  EXPECT_EQ(earlier.checkpoint, "pore.fluid.800");
  lbm_pore::PoreOptions options;
  EXPECT_EQ(lbm_pore::checkpoint_path(lbm_pore::checkpoint_prefix(options, "pore"), 1200), "pore.fluid.1200");
  options.checkpoint_prefix = "run/state";
  EXPECT_EQ(lbm_pore::checkpoint_prefix(options, "pore"), "run/state");
}

TEST(SceneSetup, CouplingAndLoadModelParametersFromTheOptions) {
  lbm_pore::PoreOptions options;
  options.boundary = "bouzidi";
  options.mass_correction = false;
  options.rho = 1.25;
  const coupling::SphereCouplingOptions co = lbm_pore::coupling_options(options);
  EXPECT_EQ(co.wall_scheme, lbm::moving_wall::parse("bouzidi"));
  EXPECT_FALSE(co.conserve_link_mass);
  const coupling::UnitConversion u = units();
  const coupling::Vec3 g{0.0, 0.0, -9.81};
  const coupling::SubstepLoadParameters with = lbm_pore::substep_load_parameters(options, u, &g);
  EXPECT_TRUE(with.buoyancy);
  EXPECT_EQ(with.gravity, g);
  EXPECT_EQ(with.fluid_density, 1.25);
  EXPECT_EQ(with.dt_fluid, u.dt_lbm());
  const coupling::SubstepLoadParameters without = lbm_pore::substep_load_parameters(options, u, nullptr);
  EXPECT_FALSE(without.buoyancy);
  EXPECT_EQ(without.gravity, (coupling::Vec3{0.0, 0.0, 0.0}));
  EXPECT_EQ(lbm_pore::buoyancy_summary(g),
            "fix lbm/pore: fix gravity found: buoyancy -rho V g added to each particle, g = (0, 0, -9.81)\n");
}
