// fix lbm/pore's run-time guards (particle speed, fluid state), its calls into the pore
// monitor (deposits, fluxes: coupling/diagnostics), the global vector and the end-of-run
// timing.
#include <mpi.h>

#include <cstdio>
#include <cstring>

#include "atom.h"
#include "comm.h"
#include "coupling/diagnostics/bonds.h"
#include "coupling/diagnostics/particle_probes.h"
#include "coupling/periodic_box.h"
#include "coupling/sphere_coupling.h"
#include "error.h"
#include "fix_lbm_pore.h"
#include "lbm/fluid_solver.h"
#include "lbm/stability.h"
#include "modify.h"
#include "plugin_common/stop_run.h"
#include "plugin_common/stop_signals.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
// The rank that found a problem writes its message, then every rank stops.
void stop_everywhere(Error* error, MPI_Comm world, int me, bool found_here, FILE* screen, FILE* logfile,
                     const char* text, const char* summary) {
  if (found_here) lbm_pore::stop_on_this_rank(error, me, screen, logfile, text);
  MPI_Barrier(world);
  error->all(FLERR, summary);
}
}  // namespace

// Guard: a particle may not cross more than kMaxShiftPerFluidStep cells per fluid step.
void FixLbmPore::check_particle_speed() {
  auto fastest = coupling::fastest_particle(particles_.view());
  struct {
    double value;
    int rank;
  } local{fastest.value, comm->me}, global{0.0, 0};
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
  monitor_->record_particle_shift(global.value);
  if (global.value <= coupling::kMaxShiftPerFluidStep) return;
  stop_everywhere(error, world, comm->me, comm->me == global.rank, screen, logfile,
                  coupling::fast_particle_message(fastest, update->ntimestep).c_str(),
                  "fix lbm/pore: a particle moves too fast for the lattice (see the message of the rank that found it)");
}

// NaN or runaway speed stops the run, naming the step, the node and the likely cause.
void FixLbmPore::check_fluid_state() {
  const auto problem = lbm::check_fluid_state(*solver_, 0.5);
  int local_bad = problem.found ? 1 : 0, any_bad = 0;
  MPI_Allreduce(&local_bad, &any_bad, 1, MPI_INT, MPI_MAX, world);
  if (!any_bad) return;
  std::string text;
  if (problem.found) {
    const coupling::Vec3 node{double(problem.node[0]), double(problem.node[1]), double(problem.node[2])};
    const auto nearest = coupling::nearest_particle_surface(
        particles_.view(), coupling::PeriodicBox::from(solver_->decomposition()), node);
    text = "fix lbm/pore: fluid became unstable at DEM step " + std::to_string(update->ntimestep) +
           " (fluid step " + std::to_string(fluid_steps_) + "), " + problem.describe() +
           coupling::instability_cause(nearest);
  }
  stop_everywhere(error, world, comm->me, problem.found, screen, logfile, text.c_str(),
                  "fix lbm/pore: fluid became unstable (see the message of the rank that found it)");
}

// Deposits and particle fluxes (paper Sec. III), from the bonds the contact laws would form:
// within the cohesion range of another particle or the adhesion range of the wall; and the
// loads along the flow on the particles: the fluid's and, where a fix exposes this rank's
// ("local_force", fix wall/voxel), the wall's.
void FixLbmPore::record_particles() {
  collect_group_pairs();
  const int ntotal = atom->nlocal + atom->nghost;
  bonded_atoms_.assign(ntotal, 0);
  coupling::mark_cohesive_bonds(atoms_view(), pairs_, bonded_atoms_);
  const auto view = particles_.view();
  bonded_.assign(view.num_total, 0);
  on_wall_.assign(view.num_total, 0);
  coupling::PoreMonitor::ParticleLoads loads;
  for (std::size_t p = 0; p < view.num_total; ++p) {
    const int i = particles_.atom(p);
    if (p >= view.num_owned) {
      bonded_[p] = bonded_atoms_[i];
      continue;
    }
    loads.fluid_force += state_[i].load.force[0];
    const double* x = atom->x[i];
    // With lubrication on, find_walls() searched this fluid step already, over a wider reach.
    on_wall_[p] = options_.lubrication
                      ? state_[i].wall.known && coupling::within_adhesion_range(state_[i].wall.distance, atom->radius[i])
                      : coupling::adheres_to_wall(*surface_, {x[0], x[1], x[2]}, atom->radius[i], wall_points_);
    bonded_[p] = bonded_atoms_[i] || on_wall_[p];
  }
  for (int f = 0; f < modify->nfix; ++f) {
    int dim = 0;
    const auto* wall = static_cast<const double*>(modify->fix[f]->extract("local_force", dim));
    if (wall && dim == 1) loads.wall_force += wall[0];
  }
  monitor_->record_particles(view, bonded_, on_wall_, loads, solver_->decomposition().comm);
}

// The pressure loss in units of P_out and the burst detector, after every fluid step; a
// burst is announced on rank 0 as it is recorded.
void FixLbmPore::record_fluid_step() {
  const auto burst = monitor_->record_fluid_step(*solver_, fluid_steps_, update->ntimestep,
                                                 units_->time_to_physical(double(fluid_steps_)));
  if (burst && comm->me == 0)
    lbm_pore::print_to_screen_and_log(screen, logfile, ("fix lbm/pore: " + burst->announcement()).c_str());
}

double FixLbmPore::compute_array(int row, int column) {
  const auto& bursts = monitor_->bursts();
  if (row < 0 || row >= int(bursts.size()) || column < 0 || column >= coupling::BurstRecord::kColumns) return 0.0;
  return bursts[row].row()[column];
}

// Called on every rank by thermo output and variables, so the reductions inside are safe.
double FixLbmPore::compute_vector(int index) { return monitor_->value(index, *solver_, fluid_steps_); }

// Where the time of the run went, on rank 0.
void FixLbmPore::post_run() {
  // A signal that came after the last step's post_integrate: every rank takes it here, so
  // LIGGGHTS's input loop stops after this run on all of them.
  lbm_pore::take_stop_requests(world);
  if (comm->me != 0) return;
  lbm_pore::print_to_screen_and_log(screen, logfile, timer_.report(*coupling_).c_str());
}
