// fix lbm/pore's guards (particle speed, fluid state) and diagnostics (deposits, fluxes,
// the global vector, the end-of-run timing).
#include <mpi.h>

#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <string>

#include "atom.h"
#include "comm.h"
#include "contact/short_range_attraction.h"
#include "contact/voxel_surface.h"
#include "coupling/lattice_frame.h"
#include "coupling/periodic_box.h"
#include "coupling/sphere_coupling.h"
#include "coupling/unit_conversion.h"
#include "error.h"
#include "fix_lbm_pore.h"
#include "fix_lbm_pore_internal.h"
#include "lbm/fluid_solver.h"
#include "lbm/macroscopic.h"
#include "lbm/stability.h"
#include "neigh_list.h"
#include "plugin_common/stop_run.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace lbm_pore::slots;
using namespace lbm_pore::limits;

// Guard: a particle may not cross more than kMaxShiftPerFluidStep cells per fluid step.
void FixLbmPore::check_particle_speed() {
  const auto view = particles_.view();
  double fastest = 0.0;
  int fastest_tag = -1;
  for (std::size_t p = 0; p < view.num_owned; ++p) {
    const auto u = view.v(p);
    double speed = std::sqrt(coupling::dot(u, u));
    if (!std::isfinite(speed)) speed = std::numeric_limits<double>::infinity();  // NaN -> stop
    if (speed > fastest) {
      fastest = speed;
      fastest_tag = view.identifier(p);
    }
  }
  struct {
    double value;
    int rank;
  } local{fastest, comm->me}, global{0.0, 0};
  MPI_Allreduce(&local, &global, 1, MPI_DOUBLE_INT, MPI_MAXLOC, world);
  diagnostics_[kMaxParticleShift] = global.value;
  if (global.value <= kMaxShiftPerFluidStep) return;
  if (comm->me == global.rank) {
    char text[600];
    std::snprintf(text, sizeof text,
                  "fix lbm/pore: particle %d moves %.3g cells per fluid step at DEM step " BIGINT_FORMAT
                  " (limit %.2f): the fluid cannot follow it. Likely cause: a contact too stiff "
                  "for the DEM step, or n_dem too large for this speed; lower n_dem or the time "
                  "step",
                  fastest_tag, global.value, update->ntimestep, kMaxShiftPerFluidStep);
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, text);
  }
  MPI_Barrier(world);
  error->all(FLERR, "fix lbm/pore: a particle moves too fast for the lattice (see the message of the rank that found it)");
}

// NaN or runaway speed stops the run, naming the step, the node and the likely cause.
void FixLbmPore::check_fluid_state() {
  const auto problem = lbm::check_fluid_state(*solver_, 0.5);
  int local_bad = problem.found ? 1 : 0, any_bad = 0;
  MPI_Allreduce(&local_bad, &any_bad, 1, MPI_INT, MPI_MAX, world);
  if (!any_bad) return;
  if (problem.found) {
    // Name the particle whose surface is nearest to the node: most blow-ups start in the
    // gap between a particle and a wall or another particle.
    const auto view = particles_.view();
    int nearest_id = -1;
    double nearest_gap = 1e300;
    const coupling::PeriodicBox box = coupling::PeriodicBox::from(solver_->decomposition());
    const coupling::Vec3 node{double(problem.node[0]), double(problem.node[1]), double(problem.node[2])};
    for (std::size_t p = 0; p < view.num_total; ++p) {
      const auto d = box.displacement(view.x(p), node);
      const double gap = std::sqrt(coupling::dot(d, d)) - view.r(p);
      if (gap < nearest_gap) {
        nearest_gap = gap;
        nearest_id = view.identifier(p);
      }
    }
    char near[200] = "";
    if (nearest_id >= 0)
      std::snprintf(near, sizeof near, "; nearest particle %d, its surface %.2f cells away",
                    nearest_id, nearest_gap);
    char cause[400];
    if (nearest_gap < 1.0)
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
                    kMaxLatticeSpeed);
    char text[1200];
    std::snprintf(text, sizeof text,
                  "fix lbm/pore: fluid became unstable at DEM step " BIGINT_FORMAT
                  " (fluid step %lld), %s%s. Likely cause: %s",
                  update->ntimestep, fluid_steps_, problem.describe().c_str(), near, cause);
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, text);
  }
  MPI_Barrier(world);
  error->all(FLERR, "fix lbm/pore: fluid became unstable (see the message of the rank that found it)");
}

// Deposits and particle fluxes (paper Sec. III). A particle is bonded when it lies within
// the attraction range of another particle (cohesion, 0.03 (Ri + Rj)) or of the wall
// (adhesion, 0.03 R).
void FixLbmPore::update_particle_diagnostics() {
  const auto view = particles_.view();
  std::vector<char>& bonded = bonded_;  // reused: no allocation per fluid step
  bonded.assign(view.num_total, 0);
  double** x = atom->x;
  const double* radius = atom->radius;
  if (list_) {
    for (int ii = 0; ii < list_->inum; ++ii) {
      const int i = list_->ilist[ii];
      if (i >= int(view_of_atom_.size()) || view_of_atom_[i] < 0) continue;
      const int* neighbors = list_->firstneigh[i];
      for (int jj = 0; jj < list_->numneigh[i]; ++jj) {
        const int j = neighbors[jj] & NEIGHMASK;
        if (j >= int(view_of_atom_.size()) || view_of_atom_[j] < 0) continue;
        const double d[3] = {x[j][0] - x[i][0], x[j][1] - x[i][1], x[j][2] - x[i][2]};
        const double gap = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - radius[i] - radius[j];
        if (gap <= contact::kAttractionRangeFactor * (radius[i] + radius[j])) {
          bonded[view_of_atom_[i]] = 1;
          bonded[view_of_atom_[j]] = 1;
        }
      }
    }
  }
  double force_x = 0.0;
  for (std::size_t p = 0; p < view.num_owned; ++p) {
    const int i = particles_.atom(p);
    force_x += loads_[i][0];
    if (bonded[p]) continue;
    const double reach = radius[i] * (1.0 + contact::kAttractionRangeFactor);
    if (options_.lubrication) {
      // find_walls() searched this fluid step already, over a wider reach.
      bonded[p] = loads_[i][kWallKnown] > 0.0 && loads_[i][kWallDistance] <= reach;
    } else {
      surface_->find({x[i][0], x[i][1], x[i][2]}, reach, wall_points_);
      bonded[p] = !wall_points_.empty();
    }
  }
  coupling::DepositionCriteria criteria;
  if (options_.deposit_speed >= 0.0)
    criteria.speed_threshold = units_->velocity_to_lattice(options_.deposit_speed);
  else if (options_.drive == lbm_pore::PoreOptions::Drive::kVelocity)
    criteria.speed_threshold = kDepositSpeedFraction * std::abs(solver_->drive().inlet_velocity);
  const lbm::Communicator& c = solver_->decomposition().comm;
  const auto deposit = coupling::deposited(view, bonded, pore_, criteria, c);
  const double volume_unit = options_.dx * options_.dx * options_.dx;
  auto& v = diagnostics_;
  v[kDepositedVolume] = deposit.volume * volume_unit;
  v[kDepositedCount] = double(deposit.count);
  // L_dep = V_dep / (pi D^2 / 4) with the pore's diameter (the equivalent one for a voxel file).
  v[kDepositedLength] =
      deposit.volume / (M_PI * pore_diameter_lattice_ * pore_diameter_lattice_ / 4.0) * options_.dx;
  const auto in = inlet_counter_->update(view, frame_->dims[0], c);
  const auto out = outlet_counter_->update(view, frame_->dims[0], c);
  v[kParticlesIn] += double(in.count);
  v[kParticlesOut] += double(out.count);
  v[kParticlesInVolume] += in.volume * volume_unit;
  v[kParticlesOutVolume] += out.volume * volume_unit;
  MPI_Allreduce(&force_x, &v[kHydroForceX], 1, MPI_DOUBLE, MPI_SUM, world);
}

void FixLbmPore::update_diagnostics() {
  fluid_diagnostics_stale_ = false;
  auto& v = diagnostics_;
  v[kPressureLoss] = units_->pressure_to_physical(lbm::pressure_loss(*solver_));
  // plane_flux is in lattice volume per lattice time step.
  const double flux_unit = options_.dx * options_.dx * options_.dx / units_->dt_lbm();
  v[kFluidFluxInlet] = lbm::plane_flux(*solver_, 0, 0) * flux_unit;
  v[kFluidFluxOutlet] = lbm::plane_flux(*solver_, 0, frame_->dims[0] - 1) * flux_unit;
  const double speed = lbm::max_speed(*solver_);
  v[kMaxFluidSpeed] = units_->velocity_to_physical(speed);
  v[kLatticeMach] = speed / kSoundSpeed;
  v[kFluidSteps] = double(fluid_steps_);
}

// Called on every rank by thermo output and variables, so the reductions inside are safe.
double FixLbmPore::compute_vector(int index) {
  if (index < 0 || index >= kNumDiagnostics) return 0.0;
  if (fluid_diagnostics_stale_) update_diagnostics();
  return diagnostics_[index];
}

// Where the time of a run went: the fluid steps (with mapping and moving walls), the
// lubrication, the diagnostics, and the rest (DEM), summed over the run on rank 0.
void FixLbmPore::post_run() {
  if (comm->me != 0 || run_fluid_steps_ == 0) return;
  const double total = now() - run_start_;
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

