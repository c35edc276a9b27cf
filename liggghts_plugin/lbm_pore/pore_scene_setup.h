#pragma once
// From fix lbm/pore's parsed keywords to the objects lbm/ and coupling/ build on: the voxel
// geometry and where its pore is, the drive in lattice units, the checks that the script's
// box and boundaries match the fluid's. No LIGGGHTS dependency (the fix passes its box).
#include <array>
#include <memory>
#include <string>
#include <vector>

#include "coupling/diagnostics/pore_monitor.h"
#include "coupling/force/substep_load.h"
#include "coupling/lubrication/lubrication_kernel.h"
#include "coupling/sphere_coupling.h"
#include "coupling/unit_conversion.h"
#include "lbm/block_layout.h"
#include "lbm/capped_drive.h"
#include "lbm/communicator.h"
#include "lbm/fluid_solver.h"
#include "lbm/voxel_geometry.h"
#include "lbm_pore_options.h"

namespace lbm_pore {

struct SceneSetup {
  std::shared_ptr<const lbm::VoxelGeometry> geometry;
  coupling::PoreMonitorSetup monitor;  // the pore and the counting planes, lattice units
};

// The paper's scene from its lengths, or a voxel file placed with node 0 at `origin`
// (default: half a cell inside the box's lower corner). Throws lbm::InputError, also before
// allocating a geometry that would not fit in memory (naming dx).
SceneSetup build_scene(const PoreOptions& options, const double* box_lo);

// The folders of the output paths (vtk, checkpoint, burst_file) exist or can be created and
// accept files, and none is a file where a directory is needed or the other way round; checked
// when the fix is defined, not at the first output. Throws lbm::InputError naming the keyword.
void check_output_paths(const PoreOptions& options);

// Collective: before the fluid solver is built, this rank's block (`owned`, of the `global`
// lattice) must fit in the memory of its machine together with the blocks of the other ranks
// there (lbm/memory_estimate.h). Throws lbm::InputError on every rank, naming dx, the lattice's
// size, the bytes and the memory available.
void check_lattice_memory(const PoreOptions& options, const lbm::Box& owned,
                          const std::array<int, 3>& global, const lbm::Communicator& comm);

// The drive along +x in lattice units; throws lbm::InputError naming 'velocity' or
// 'pressure_loss' when it exceeds the scheme's limits (lbm/stability.h).
lbm::FlowDrive drive_of(const PoreOptions& options, const coupling::UnitConversion& units);

// The ceiling on the velocity inlet's pressure loss ('max_pressure_loss'), on the solver's
// drive, continuing from a restart file's state (empty: at the velocity, as a run made without
// the keyword or before the drive had a state); null without the keyword. Throws
// lbm::InputError naming 'max_pressure_loss' when the loss exceeds a pressure drive's limit
// (lbm/stability.h) or the state is not the drive's.
std::unique_ptr<lbm::CappedVelocityDrive> capped_drive_of(const PoreOptions& options,
                                                          const coupling::UnitConversion& units,
                                                          lbm::FluidSolver& solver,
                                                          const std::vector<double>& restored_state);

// The fluid's lateral boundaries and LIGGGHTS's periodicity (domain->periodicity) must agree,
// and the flow axis x must not be periodic. Throws lbm::InputError saying what to change.
void check_boundaries(const PoreOptions& options, const int* periodicity);

// The speed below which a bonded particle counts as deposited (lattice units): the
// 'deposit_speed' keyword, else a fraction of the inlet velocity (when it is not 0: a closed
// box has none), else the default.
double deposit_speed_threshold(const PoreOptions& options, const coupling::UnitConversion& units,
                               const lbm::FlowDrive& drive);

// The burst detector's criteria: burst_drop, and burst_window in fluid steps (default 1000).
coupling::BurstCriteria burst_criteria(const PoreOptions& options, const coupling::UnitConversion& units);

// The monitor's criteria, once the drive is known, set in the scene's `setup`: the deposit
// speed threshold (deposit_speed_threshold), the burst criteria and 'burst_deposits'.
// The pore monitor, continuing from a restart file's state (empty: a new run). Throws
// lbm::InputError starting "restart: " on a state of another version.
std::unique_ptr<coupling::PoreMonitor> pore_monitor_of(const coupling::PoreMonitorSetup& setup,
                                                       const coupling::UnitConversion& units,
                                                       const std::vector<double>& restored_state);

void set_monitor_criteria(coupling::PoreMonitorSetup& setup, const PoreOptions& options,
                          const coupling::UnitConversion& units, const lbm::FlowDrive& drive);

// The sphere coupling's options from the keywords: boundary, mass_correction,
// reference_pressure.
coupling::SphereCouplingOptions coupling_options(const PoreOptions& options);

// The substep load model's parameters: the fluid step, and buoyancy in the fluid's density
// where the script has gravity (`gravity`: its acceleration, null without).
coupling::SubstepLoadParameters substep_load_parameters(const PoreOptions& options, const coupling::UnitConversion& units,
                                                        const coupling::Vec3* gravity);
// The line printed when buoyancy is on, with the acceleration it uses.
std::string buoyancy_summary(const coupling::Vec3& gravity);

// Unit names for the burst file's header, from LIGGGHTS's unit style (pressures in P_out).
coupling::BurstUnits burst_units(const std::string& unit_style);

// The unit conversion's inputs: the options' dx, rho, nu, n_dem and the script's time step.
coupling::UnitInputs unit_inputs(const PoreOptions& options, double dt_dem);

// TRT parameters and periodic axes of the fluid (flow along x, never periodic).
lbm::FluidParameters fluid_parameters(const PoreOptions& options, const coupling::UnitConversion& units);

// The lubrication kernel in the script's units (lattice-unit law, cutoff in cells).
coupling::LubricationKernel lubrication_kernel(const PoreOptions& options, const coupling::UnitConversion& units);

// The neighbour list must hold every pair within the lubrication cutoff (contact distance
// plus skin): throws lbm::InputError saying which skin is needed.
void check_neighbor_skin(const PoreOptions& options, double skin);

// The lines printed at setup: lattice, time steps, tau, drive and its Mach number or
// density difference, the moving-wall scheme and lubrication, and the memory per lattice
// node (the fluid's, lbm::FluidSolver::bytes_per_node, plus coupling::coupling_bytes_per_node
// for `threads`; bytes_per_node 0: not printed).
std::string setup_summary(const PoreOptions& options, const coupling::UnitConversion& units,
                          const std::array<int, 3>& dims, const lbm::FlowDrive& drive, double dt_dem,
                          double pore_diameter, double bytes_per_node, int threads = 1);

}  // namespace lbm_pore
