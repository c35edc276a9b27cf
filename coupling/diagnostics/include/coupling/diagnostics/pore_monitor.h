#pragma once
// All diagnostics of a clogging run (paper Sec. III) behind one object: the host calls it
// once per fluid step with the particles and reads the values in its own units, which a
// LIGGGHTS fix exposes as its global vector (f_ID[1..]). The fluid quantities need a scan of
// the lattice, so they are computed only when read after the fluid changed.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "coupling/diagnostics/burst_detector.h"
#include "coupling/diagnostics/deposit_speeds.h"
#include "coupling/diagnostics/pore_diagnostics.h"
#include "coupling/particle_view.h"
#include "coupling/unit_conversion.h"
#include "lbm/fluid_solver.h"
#include "lbm/pore_scene.h"

namespace coupling {

// Where the pore and the counting planes are, in lattice units.
struct PoreMonitorSetup {
  PoreRegion pore;              // deposits count inside it
  double pore_diameter = 0.0;   // D for L_dep = V_dep / (pi D^2 / 4) (cells)
  double inlet_plane = 0.0;     // x of the planes whose particle crossings are counted
  double outlet_plane = 0.0;
  int flow_length = 0;          // nodes along the flow axis (the counters' wrap-around test)
  // The planes "on both sides of the pore" (paper Sec. III) whose pressure difference is the
  // pressure loss across the pore: the last node plane before it and the first after it
  // (node indices along the axis; -1 where the geometry has no such pore).
  int upstream_plane = -1, downstream_plane = -1;
  DepositionCriteria criteria;  // speed threshold of a deposit (lattice units)
  BurstCriteria bursts;         // what counts as an erosive burst (window in fluid steps)
  // An erosive burst tears a deposit off: a fall whose peak had fewer deposited particles
  // than this, at the peak and over the window before it (the start-up transient of a
  // flow, particles passing), is not recorded.
  long long burst_min_deposited = 1;
};

// The paper's scene: "located inside the pore radius" (Sec. III) is the pore's cylinder,
// by default extended upstream through the free region so a clog sitting in the pore's
// mouth counts too (DepositRegion::kFromInlet), or the pore alone (kPore: particles queued
// in the free region upstream, inside the radius, do not count); particles are counted where
// they leave the inlet region and enter the outlet region.
enum class DepositRegion { kFromInlet, kPore };
PoreMonitorSetup pore_scene_monitor(const lbm::PoreSceneSpec& spec,
                                    DepositRegion region = DepositRegion::kFromInlet);
// A geometry from a voxel file: deposits count anywhere in the lattice, D is the equivalent
// diameter of the narrowest cross-section, the planes one node inside either end.
PoreMonitorSetup voxel_geometry_monitor(const lbm::VoxelGeometry& geometry);

class PoreMonitor {
 public:
  // Indices of the values (1-based in thermo: f_ID[i] = index i-1 here), host units.
  enum Quantity {
    kPressureLoss,        // p_in - p_out between the inlet and outlet planes (pressure units)
    kFluidFluxInlet,      // volumetric flux through the inlet plane (volume / time)
    kFluidFluxOutlet,     // ... and the outlet plane
    kParticlesIn,         // particles that crossed the inlet plane downstream (cumulative)
    kParticlesOut,        // particles that crossed the outlet plane (cumulative)
    kDepositedVolume,     // V_dep (volume units)
    kDepositedCount,      // number of deposited particles
    kDepositedLength,     // L_dep = V_dep / (pi D^2 / 4)
    kMaxFluidSpeed,       // largest fluid speed (velocity units)
    kLatticeMach,         // largest speed / lattice speed of sound
    kFluidSteps,          // fluid steps done
    kParticlesInVolume,   // particle volume that crossed the inlet plane (cumulative)
    kParticlesOutVolume,  // ... and the outlet plane
    kHydroForceX,         // total hydrodynamic force on the group along the flow (force units)
    kMaxParticleShift,    // largest particle displacement per fluid step, in cells
    kPressureLossOutlet,  // the pressure loss in units of the outlet pressure, P / P_out
    kLargestPressureLoss, // the largest P / P_out of the run so far
    kBurstCount,          // erosive bursts recorded so far
    // The fluid's mass budget (mass units): mass in = mass out + change of mass held.
    kFluidMassIn,         // mass through the inlet face, sum over fluid steps (cumulative;
                          // the populations that crossed it, lbm::open_face_mass)
    kFluidMassOut,        // ... and out through the outlet face
    kFluidMassHeld,       // mass of the fluid nodes of the lattice now
    // Mass of the fluid the particles displace: their lattice nodes at the reference density.
    // A node a particle covers takes its mass out of kFluidMassHeld, a refilled one brings
    // mass back: in - out = the change of held + displaced.
    kParticleDisplacedMass,
    // What the particles' coupling put into the fluid beyond that (cumulative): the moving
    // surfaces' wall terms (nonzero where a surface meets no fluid: a particle leaving through
    // an open end, one in contact) and the covered and refilled nodes' density over rho0.
    // The budget: in - out = change of held + displaced - surfaces - refill.
    kParticleSurfaceMass,
    kParticleRefillMass,
    // The hold of the paper's force balance: the wall's force on the particles along the
    // flow (force units; from the host's wall, 0 without one) and the deposited particles
    // that touch the wall.
    kWallForceX,
    kDepositedOnWall,
    // The pressure loss across the pore, between the planes next to its ends, P / P_out
    // (0 without such planes). The paper measures it there; kPressureLossOutlet is read at
    // the box's open faces and includes the regions before and after the pore.
    kPressureLossAcrossPore,
    // The deposited count under the speed threshold scaled by kDepositSpeedLadder[i], one
    // quantity per factor in that order (x 1/4, 1/2, 2, 4, 8, 16).
    kDepositedCountScaledSpeed,
    // The fluid's and the wall's force along the flow on the deposited particles alone
    // (force units; Deposition::fluid_force, wall_force): the deposit's own force balance.
    // kHydroForceX and kWallForceX sum over every particle, the queue in the outlet region
    // and a plug on the pore's entrance face among them.
    kDepositFluidForceX = kDepositedCountScaledSpeed + int(kDepositSpeedLadder.size()),
    kDepositWallForceX,
    // Every force along the flow on the deposited particles (Deposition::total_force): minus
    // the two above, the push of particles outside the deposit on it.
    kDepositTotalForceX,
    kCount
  };

  PoreMonitor(const PoreMonitorSetup& setup, const UnitConversion& units);

  // At a fluid step: the particles (lattice view of the step), which of them are bonded and
  // which touch the wall (indexed like the view), this rank's hydrodynamic force on them
  // along the flow and the wall's (host units), in all and per particle. Collective over `comm`.
  struct ParticleLoads {
    double fluid_force = 0.0;  // this rank's hydrodynamic force on its particles along the flow
    double wall_force = 0.0;   // the wall's on them (0 where the host has no wall forces)
    // The same per particle, and every force on each (the host's total), indexed like the
    // view (empty: not given, the deposit's are 0).
    std::vector<double> fluid_along_flow, wall_along_flow, total_along_flow;
  };
  void record_particles(const ParticleView& view, const std::vector<char>& bonded,
                        const std::vector<char>& on_wall, const ParticleLoads& local,
                        const lbm::Communicator& comm);
  // The largest particle shift of the step (cells, already reduced over ranks).
  void record_particle_shift(double cells) { values_[kMaxParticleShift] = cells; }
  // After a coupled fluid step: this rank's surface and refill mass of the step
  // (SphereCoupling::last_surface_mass, last_mass_change().net_over(rho0)), lattice units;
  // summed over the ranks with the face masses by the step's record_fluid_step.
  void record_coupling_mass(double surface_mass, double refill_mass);
  // The fluid advanced: the fluid values are recomputed when next read.
  void fluid_changed() { fluid_stale_ = true; }

  // One value, recomputing the fluid ones if stale (collective: call on every rank).
  double value(int quantity, const lbm::FluidSolver& solver, long long fluid_steps);
  void update_fluid(const lbm::FluidSolver& solver, long long fluid_steps);

  // After each fluid step (collective): the pressure loss in units of P_out, fed to the
  // burst detector with the deposits of record_particles(), and the step's mass through the
  // inlet and outlet planes added to their sums; returns the burst this step
  // completed, if any (also appended to bursts() and written to the burst file). A fluid
  // step already recorded (the setup of a later run) only refreshes P / P_out.
  std::optional<BurstRecord> record_fluid_step(const lbm::FluidSolver& solver, long long fluid_step,
                                               long long step, double time);
  const std::vector<BurstRecord>& bursts() const { return bursts_; }
  // Column `column` of burst `row` (BurstRecord::row), 0 outside the bursts recorded: a
  // host's table of bursts, read at any row and column.
  double burst_value(int row, int column) const;
  // Rank 0 of a host: write each burst to `path` (header with these unit names), appending
  // to it when the run was resumed from a restart. Throws std::runtime_error naming the file
  // when it cannot be opened.
  void write_bursts_to(const std::string& path, const BurstUnits& units, bool append);
  // Every rank: count the speeds of the particles in the deposit region (DepositSpeedHistogram)
  // and sum them over the ranks every `every` fluid steps. Rank 0 may then write each
  // interval's counts to `path` ("" on the others: counted, not written), appending when the
  // run was resumed. Throws std::runtime_error naming the file when it cannot be opened.
  void write_deposit_speeds_to(const std::string& path, long long every, bool append);

  const std::vector<double>& values() const { return values_; }
  // Everything a restart needs (the number of values, the values, with the cumulative
  // fluxes, and the burst detector's state), and back; restore throws std::invalid_argument
  // on a foreign vector (another number of values: a restart file of another version).
  std::vector<double> state() const;
  void restore(const std::vector<double>& state);

  const PoreMonitorSetup& setup() const { return setup_; }

 private:
  PoreMonitorSetup setup_;
  const UnitConversion& units_;
  PlaneCrossingCounter inlet_counter_, outlet_counter_;
  std::vector<double> values_;
  bool fluid_stale_ = true;
  BurstDetector detector_;
  std::vector<BurstRecord> bursts_;  // the detector's falls that eroded a deposit
  void keep_erosive_bursts();
  bool eroded_a_deposit(const BurstRecord& burst) const;
  double fluid_mass_unit() const;
  void add_plane_masses(const lbm::FluidSolver& solver);
  double coupling_mass_[2] = {0.0, 0.0};  // this rank's, since the last fluid step recorded
  long long last_burst_sample_ = -1;  // the fluid step last fed to the detector
  std::unique_ptr<BurstFileWriter> burst_file_;
  DepositSpeedHistogram speeds_;       // the interval's counts
  DepositSpeedHistogram step_speeds_;  // the last record_particles', added at a new fluid step
  std::unique_ptr<DepositSpeedFileWriter> speed_file_;
  long long speed_every_ = 0;         // fluid steps per interval; 0: not counted
  long long speed_first_step_ = -1;   // the interval's first fluid step (-1: none yet)
  void take_deposit_speeds(const lbm::FluidSolver& solver, long long fluid_step);
};

}  // namespace coupling
