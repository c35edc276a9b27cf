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
#include "plugin_common/stop_run.h"
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
  const auto fastest = coupling::fastest_particle(particles_.view());
  struct {
    double value;
    int rank;
  } local{fastest.value, comm->me}, global{0.0, 0};
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
  monitor_->record_particle_shift(global.value);
  if (global.value <= coupling::kMaxShiftPerFluidStep) return;
  char text[600];
  std::snprintf(text, sizeof text,
                "fix lbm/pore: particle %d moves %.3g cells per fluid step at DEM step " BIGINT_FORMAT
                " (limit %.2f): the fluid cannot follow it. Likely cause: a contact too stiff "
                "for the DEM step, or n_dem too large for this speed; lower n_dem or the time "
                "step",
                fastest.id, global.value, update->ntimestep, coupling::kMaxShiftPerFluidStep);
  stop_everywhere(error, world, comm->me, comm->me == global.rank, screen, logfile, text,
                  "fix lbm/pore: a particle moves too fast for the lattice (see the message of the rank that found it)");
}

// NaN or runaway speed stops the run, naming the step, the node and the likely cause.
void FixLbmPore::check_fluid_state() {
  const auto problem = lbm::check_fluid_state(*solver_, 0.5);
  int local_bad = problem.found ? 1 : 0, any_bad = 0;
  MPI_Allreduce(&local_bad, &any_bad, 1, MPI_INT, MPI_MAX, world);
  if (!any_bad) return;
  char text[1200] = "";
  if (problem.found) {
    // Most blow-ups start in the gap between a particle and a wall or another particle.
    const coupling::Vec3 node{double(problem.node[0]), double(problem.node[1]), double(problem.node[2])};
    const auto nearest = coupling::nearest_particle_surface(
        particles_.view(), coupling::PeriodicBox::from(solver_->decomposition()), node);
    char near[200] = "";
    if (nearest.id >= 0)
      std::snprintf(near, sizeof near, "; nearest particle %d, its surface %.2f cells away", nearest.id,
                    nearest.value);
    char cause[400];
    if (nearest.value < 1.0)
      std::snprintf(cause, sizeof cause,
                    "the flow is squeezed through a gap of less than a cell next to a particle: "
                    "with 'velocity' the inlet flux must pass however tightly the pore clogs. "
                    "Lower 'velocity' (gap speeds scale with it), drive by 'pressure_loss' "
                    "(bounded gap speeds), or refine dx");
    else
      std::snprintf(cause, sizeof cause,
                    "the drive or a particle is too fast for the lattice (keep speeds below "
                    "%.2f in lattice units: lower 'velocity' or 'pressure_loss', refine dx or "
                    "lower n_dem) or tau too close to 0.5",
                    lbm::kMaxLatticeSpeed);
    std::snprintf(text, sizeof text,
                  "fix lbm/pore: fluid became unstable at DEM step " BIGINT_FORMAT
                  " (fluid step %lld), %s%s. Likely cause: %s",
                  update->ntimestep, fluid_steps_, problem.describe().c_str(), near, cause);
  }
  stop_everywhere(error, world, comm->me, problem.found, screen, logfile, text,
                  "fix lbm/pore: fluid became unstable (see the message of the rank that found it)");
}

// Deposits and particle fluxes (paper Sec. III), from the bonds the contact laws would form:
// within the cohesion range of another particle or the adhesion range of the wall.
void FixLbmPore::record_particles() {
  collect_group_pairs();
  const int ntotal = atom->nlocal + atom->nghost;
  bonded_atoms_.assign(ntotal, 0);
  coupling::mark_cohesive_bonds(atoms_view(), pairs_, bonded_atoms_);
  const auto view = particles_.view();
  bonded_.assign(view.num_total, 0);
  double force_x = 0.0;
  for (std::size_t p = 0; p < view.num_total; ++p) {
    const int i = particles_.atom(p);
    bonded_[p] = bonded_atoms_[i];
    if (p >= view.num_owned) continue;
    force_x += state_[i].load.force[0];
    if (bonded_[p]) continue;
    const double* x = atom->x[i];
    // With lubrication on, find_walls() searched this fluid step already, over a wider reach.
    bonded_[p] = options_.lubrication
                     ? state_[i].wall.known && coupling::within_adhesion_range(state_[i].wall.distance, atom->radius[i])
                     : coupling::adheres_to_wall(*surface_, {x[0], x[1], x[2]}, atom->radius[i], wall_points_);
  }
  monitor_->record_particles(view, bonded_, force_x, solver_->decomposition().comm);
}

// Called on every rank by thermo output and variables, so the reductions inside are safe.
double FixLbmPore::compute_vector(int index) { return monitor_->value(index, *solver_, fluid_steps_); }

// Where the time of a run went: the fluid steps (with mapping and moving walls), the
// lubrication, the diagnostics, and the rest (DEM), summed over the run on rank 0.
void FixLbmPore::post_run() {
  if (comm->me != 0 || run_fluid_steps_ == 0) return;
  const double total = MPI_Wtime() - run_start_;
  const auto& t = coupling_->times();
  const double coupling = t.mapping + t.refill + t.moving_walls + t.force;
  char text[800];
  std::snprintf(text, sizeof text,
                "fix lbm/pore: %lld fluid steps in %.3f s: fluid %.3f s (of which mapping, refill, "
                "moving walls and force %.3f s since the lattice was built), lubrication %.3f s, "
                "diagnostics %.3f s, DEM and the rest %.3f s; %.3g s per fluid step\n",
                run_fluid_steps_, total, time_fluid_, coupling, time_lubrication_, time_diagnostics_,
                total - time_fluid_ - time_lubrication_ - time_diagnostics_,
                total / double(run_fluid_steps_));
  std::snprintf(text + std::strlen(text), sizeof text - std::strlen(text),
                "fix lbm/pore: coupling stages since the lattice was built: mapping %.3f s, refill "
                "%.3f s, moving walls %.3f s, force %.3f s, collide-stream %.3f s\n",
                t.mapping, t.refill, t.moving_walls, t.force, t.collide_stream);
  if (screen) std::fputs(text, screen);
  if (logfile) std::fputs(text, logfile);
}
