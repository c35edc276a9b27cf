// fix lbm/pore's run-time guards (particle speed, fluid state), its calls into the pore
// monitor (deposits, fluxes: coupling/diagnostics), the global vector and the end-of-run
// timing.
#include <mpi.h>

#include "atom.h"
#include "comm.h"
#include "coupling/diagnostics/bonds.h"
#include "coupling/sphere_coupling.h"
#include "error.h"
#include "fix_lbm_pore.h"
#include "liggghts_queries.h"
#include "lbm/fluid_solver.h"
#include "modify.h"
#include "pore_scene_setup.h"
#include "plugin_common/stop_run.h"
#include "plugin_common/stop_signals.h"
#include "update.h"

using namespace LAMMPS_NS;

// The rank that found a problem writes its message, then every rank stops.
void FixLbmPore::stop_everywhere(const coupling::GuardVerdict& verdict, const char* what) {
  if (verdict.found_here)
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, ("fix lbm/pore: " + verdict.message).c_str());
  MPI_Barrier(world);
  error->all(FLERR, (std::string("fix lbm/pore: ") + what + " (see the message of the rank that found it)").c_str());
}

// Guard: a particle may not cross more than kMaxShiftPerFluidStep cells per fluid step.
void FixLbmPore::check_particle_speed() {
  const auto verdict =
      coupling::particle_speed_guard(particles_.view(), update->ntimestep, solver_->decomposition().comm);
  monitor_->record_particle_shift(verdict.value);
  if (verdict.stop) stop_everywhere(verdict, "a particle moves too fast for the lattice");
}

// NaN or runaway speed stops the run, naming the step, the node and the likely cause.
void FixLbmPore::check_fluid_state() {
  const auto verdict = coupling::fluid_state_guard(*solver_, particles_.view(), update->ntimestep, fluid_steps_);
  if (verdict.stop) stop_everywhere(verdict, "fluid became unstable");
}

// Deposits and particle fluxes (paper Sec. III), from the bonds the contact laws would form:
// within the cohesion range of another particle or the adhesion range of the wall; and the
// loads along the flow on the particles, in all and per particle: the fluid's and, where a
// fix exposes this rank's ("local_force" and "atom_wall_force_x", fix wall/voxel, whose
// post_force of this DEM step ran before this end_of_step: the same atom order), the wall's;
// and every force on each, the atoms' f of this DEM step.
void FixLbmPore::record_particles() {
  collect_group_pairs();
  const lbm_pore::AtomArrays atoms = atom_arrays();
  bonded_atoms_.assign(atom->nlocal + atom->nghost, 0);
  coupling::mark_cohesive_bonds(lbm_pore::host_view(atoms), pairs_, bonded_atoms_);
  coupling::PoreMonitor::ParticleLoads loads;
  // With lubrication on, find_walls() searched this fluid step already, over a wider reach.
  loads.fluid_force = states_.mark_deposits(particles_, atoms, bonded_atoms_, options_.lubrication, *surface_,
                                            wall_points_, bonded_, on_wall_, loads.fluid_along_flow);
  lbm_pore::wall_forces_along_x(*modify, particles_, loads.wall_force, loads.wall_along_flow);
  lbm_pore::total_forces_along_x(atom->f, particles_, loads.total_along_flow);
  monitor_->record_particles(particles_.view(), bonded_, on_wall_, loads, solver_->decomposition().comm);
}

// The monitor (from the restart file's state where a run resumes) and its files: the bursts
// (rank 0 writes) and the deposit speeds (every rank counts, rank 0 writes), appended to when
// resumed; a file that cannot be opened stops the run from rank 0, naming the keyword.
void FixLbmPore::start_monitor() {
  monitor_ = lbm_pore::pore_monitor_of(monitor_setup_, *units_, restored_state_);
  const bool resumed = !restored_state_.empty();
  const char* keyword = "burst_file";
  try {
    if (comm->me == 0 && !options_.burst_file.empty())
      monitor_->write_bursts_to(options_.burst_file, lbm_pore::burst_units(update->unit_style), resumed);
    keyword = "deposit_speeds";
    if (options_.deposit_speeds_every > 0)
      monitor_->write_deposit_speeds_to(comm->me == 0 ? options_.deposit_speeds_file : "",
                                        options_.deposit_speeds_every, resumed);
  } catch (const std::runtime_error& e) {  // rank 0 only: stop from here
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile,
                                (std::string("fix lbm/pore: ") + keyword + ": " + e.what()).c_str());
  }
}

// The pressure loss in units of P_out and the burst detector, after every fluid step; a
// burst is announced on rank 0 as it is recorded.
void FixLbmPore::record_fluid_step() {
  const auto burst = monitor_->record_fluid_step(*solver_, fluid_steps_, update->ntimestep,
                                                 units_->time_to_physical(double(fluid_steps_)));
  if (burst && comm->me == 0)
    lbm_pore::print_to_screen_and_log(screen, logfile, ("fix lbm/pore: " + burst->announcement()).c_str());
}

double FixLbmPore::compute_array(int row, int column) { return monitor_->burst_value(row, column); }

// Called on every rank by thermo output and variables, so the reductions inside are safe.
// The fluid values it reads include the lattice Mach number: a flow beyond the lattice's
// accuracy is said once per run.
double FixLbmPore::compute_vector(int index) {
  if (index == kInletVelocityIndex)
    return units_->velocity_to_physical(lbm::drive_inlet_velocity(*solver_, capped_drive_.get()));
  const double value = monitor_->value(index, *solver_, fluid_steps_);
  // The Mach number is reduced over the ranks: all of them locate the fast node together.
  const double mach = monitor_->values()[coupling::PoreMonitor::kLatticeMach];
  if (!fast_flow_warned_ && mach > coupling::kAccurateLatticeMach) {
    fast_flow_warned_ = true;
    const std::string warning = coupling::fast_flow_warning(
        mach, fluid_steps_, coupling::locate_fastest_flow(*solver_, particles_.view()));
    if (comm->me == 0) error->warning(FLERR, warning.c_str());
  }
  return value;
}

// Where the time of the run went, on rank 0.
void FixLbmPore::post_run() {
  // A signal that came after the last step's post_integrate: every rank takes it here, so
  // LIGGGHTS's input loop stops after this run on all of them.
  lbm_pore::take_stop_requests(world);
  const std::string balance = timer_.balance_report(*coupling_, solver_->decomposition().comm);
  if (comm->me != 0) return;
  lbm_pore::print_to_screen_and_log(screen, logfile, (timer_.report(*coupling_) + balance).c_str());
}
