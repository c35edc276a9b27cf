#include "coupling/sphere_coupling.h"

#include <cmath>

#include "coupling/force/open_face_pressure.h"
#include "coupling/stage_clock.h"
#include "lbm/input_error.h"

namespace coupling {

SphereCoupling::SphereCoupling(lbm::FluidSolver& solver, const SphereCouplingOptions& options)
    : solver_(solver),
      options_(options),
      mapping_(solver.layout(), PeriodicBox::from(solver.decomposition())) {
  const double tau = 1.0 / solver.trt().omega_plus;
  if (options.wall_scheme == lbm::MovingWallScheme::kMeiLuoShyy && std::abs(tau - 2.0) < 0.2)
    throw lbm::InputError("moving walls: the Mei-Luo-Shyy scheme needs tau away from 2 "
                          "(|tau - 2| >= 0.2), got tau = " + std::to_string(tau) +
                          "; choose another tau or the Bouzidi scheme");
  // Mei-Luo-Shyy reads the moments of every fluid node next to a sphere (and of the node
  // behind it): the kernel keeps them as it collides (FluidSolver::keep_node_moments).
  if (options.wall_scheme == lbm::MovingWallScheme::kMeiLuoShyy && options.kernel_moments)
    solver_.keep_node_moments();
}

void SphereCoupling::map_and_refill(const ParticleView& view) {
  MappingChange& change = change_;
  {
    StageTimer t(times_.mapping);
    mapping_.update(view, solver_.node_types(), change);
  }
  {
    StageTimer t(times_.refill);
    // The refill averages the density of the node's fluid neighbours; next to a rank (or
    // periodic) boundary some are halo nodes, whose populations still hold the values of
    // the last exchange (before the previous collide-stream). Their current densities come
    // first, one value per ghost (not 19 populations), so that the refill, and the run,
    // equal the serial one to round-off. Only an owned node on a face plane towards a
    // neighbour rank or periodic image reads such a ghost (its 18 neighbours x + c_q,
    // refill.cpp), and only the averaged-density scheme reads any. The exchange is
    // collective: every rank takes it when any rank needs it. Nothing else reads ghost
    // populations before the step's own exchange, so they may stay stale.
    // The same sum decides, per axis, whether the step's exchange sends the ghost nodes'
    // moments besides the crossing five (whole_ghost_axes: Mei-Luo-Shyy may read the
    // moments of a ghost node): one collective call for both, and every rank sends what its
    // neighbours expect.
    long long counts[4] = {0, 0, 0, 0};
    if (options_.refill == RefillScheme::kEquilibriumAveragedDensity)
      for (std::size_t cell : change.uncovered) counts[0] += solver_.borders_exchanged_ghost(cell);
    const auto whole = whole_ghost_axes(mapping_, options_.wall_scheme, solver_);
    for (int a = 0; a < 3; ++a) counts[1 + a] = whole[a];
    solver_.decomposition().comm.sum(counts, 4);
    const long long uncovered = counts[0];
    for (int a = 0; a < 3; ++a) {
      ghost_moment_axes_[a] = counts[1 + a] > 0;
      halo_counts_.moments[a] += ghost_moment_axes_[a];
    }
    if (ghost_moments_near_spheres_ && !solver_.node_moment_field() &&
        (ghost_moment_axes_[0] || ghost_moment_axes_[1] || ghost_moment_axes_[2]))
      ghost_moment_cells(mapping_, view, solver_, ghost_moment_axes_, ghost_moment_cells_);
    ++halo_counts_.steps;
    if (uncovered > 0) solver_.exchange_ghost_densities(ghost_density_);
    mass_ = refill_uncovered(change, mapping_, view, options_.refill, solver_,
                             uncovered > 0 ? &ghost_density_ : nullptr);
    for (const std::size_t cell : change.uncovered) solver_.refresh_node_moments(cell);
  }
  mapping_.commit(change, solver_.node_types());
}

void SphereCoupling::exchange_halo() {
  solver_.exchange_halo(lbm::HaloPopulations::crossing());
  own_exchange_ = true;
  ghost_moments_fresh_ = ghost_moment_axes_[0] || ghost_moment_axes_[1] || ghost_moment_axes_[2];
  if (!ghost_moments_fresh_) return;
  if (solver_.node_moment_field()) {
    // The sent planes hold the moments the kernel kept: carried as they are, no gather.
    solver_.exchange_ghost_node_moments(ghost_moment_axes_);
    return;
  }
  if (ghost_moments_near_spheres_)
    lbm::moving_wall::exchange_ghost_moments(solver_, ghost_moment_axes_, ghost_moments_,
                                             &ghost_moment_cells_.sent, &ghost_moment_cells_.received);
  else
    lbm::moving_wall::exchange_ghost_moments(solver_, ghost_moment_axes_, ghost_moments_);
}

void SphereCoupling::set_particle_reach(double view_reach, double radius_bound) {
  ghost_moments_near_spheres_ = view_reach >= radius_bound + kGhostMomentMargin;
}

bool SphereCoupling::moving_walls_in_kernel(const lbm::NodeMomentField* field) const {
  return options_.moving_walls_in_kernel && options_.conserve_link_mass &&
         options_.correct_mass_in_kernel &&
         options_.wall_scheme == lbm::MovingWallScheme::kMeiLuoShyy && field != nullptr;
}

void SphereCoupling::apply_moving_walls(const ParticleView& view) {
  const double rho0 = solver_.parameters().rho0;
  const bool conserve = options_.conserve_link_mass;
  // Received by this step's exchange_halo, or none (a host that exchanged by itself).
  const lbm::moving_wall::GhostMoments* ghosts = ghost_moments_fresh_ ? &ghost_moments_ : nullptr;
  // The kernel's moments, where its ghosts hold what links read: this step's own exchange
  // carried them there, or no link reads a ghost's moments (whole_ghost_axes).
  const bool any_axis = ghost_moment_axes_[0] || ghost_moment_axes_[1] || ghost_moment_axes_[2];
  const lbm::NodeMomentField* field =
      (own_exchange_ || !any_axis) ? solver_.node_moment_field() : nullptr;
  ghost_moments_fresh_ = false;
  own_exchange_ = false;
  {
    StageTimer t(times_.moving_walls);
    build_sphere_links(mapping_, view, solver_.node_types(), links_, &link_scratch_);
    links_in_kernel_ = moving_walls_in_kernel(field);
    if (links_in_kernel_) {
      // Left to the next collide_stream's pass (lbm/moving_wall/link_sweep.h, KernelLinks):
      // the populations and defects of the links are complete after it.
      kernel_links_.begin(links_.links, solver_, *field, link_sweep_, link_populations_,
                          defect_per_link_);
    } else if (conserve) {
      // The moving walls, their mass defect and its correction in one sweep over the lattice
      // (lbm/moving_wall/link_sweep.h); the correction moves no momentum, and the momentum
      // exchange reads the returned populations as the moving walls recorded them, so the
      // force is the scheme's own.
      link_defect_ = lbm::moving_wall::apply_links_and_restore_mass(
          links_.links, options_.wall_scheme, solver_, moment_cache_, link_sweep_,
          link_populations_, defect_per_link_, ghosts, field, options_.correct_mass_in_kernel);
    } else {
      lbm::apply_links(links_.links, options_.wall_scheme, solver_, &moment_cache_, nullptr,
                       &link_populations_, ghosts);
      link_defect_ = lbm::moving_wall::link_mass_defect(links_.links, rho0, link_populations_);
    }
  }
  StageTimer t(times_.force);
  // The fluid beyond the open faces on the spheres that reach them (the same gauge), read
  // before the open boundaries and the collide-stream change the faces' densities.
  record_open_face_pressure(view, solver_, gauge_density(options_.reference_pressure, rho0),
                            open_face_pushes_);
  num_particles_ = view.num_total;
  ++link_counts_.steps;
  link_counts_.links += static_cast<long long>(links_.links.size());
}

void SphereCoupling::exchange_momentum() {
  const double rho0 = solver_.parameters().rho0;
  if (links_in_kernel_) {
    // The links the kernel applied in its pass are the moving walls' work, not the fluid's.
    const double in_kernel = kernel_links_.prepared_seconds();
    times_.collide_stream -= in_kernel;
    times_.moving_walls += in_kernel;
    StageTimer t(times_.moving_walls);
    link_defect_ = lbm::moving_wall::sum_link_defects(defect_per_link_);
  }
  surface_mass_ = lbm::moving_wall::moving_surface_mass(links_.links, rho0) +
                  (options_.conserve_link_mass ? 0.0 : link_defect_.net);
  StageTimer t(times_.force);
  loads_.reset(num_particles_);
  add_momentum_exchange(links_, link_populations_, options_.momentum_exchange, rho0, loads_,
                        options_.reference_pressure);
  add_open_face_pushes(open_face_pushes_, loads_);
}

void SphereCoupling::step(const ParticleView& view) {
  map_and_refill(view);
  {
    StageTimer t(times_.halo);
    exchange_halo();
  }
  {
    StageTimer t(times_.static_walls);
    solver_.apply_wall_bounce_back();
  }
  apply_moving_walls(view);
  {
    StageTimer t(times_.open_boundaries);
    solver_.apply_open_boundaries();
  }
  {
    StageTimer t(times_.collide_stream);
    solver_.collide_stream();
  }
  exchange_momentum();
}

void SphereCoupling::add_loads(std::size_t count, double* force, double* torque) const {
  for (std::size_t p = 0; p < count && p < loads_.force.size(); ++p)
    for (int a = 0; a < 3; ++a) {
      force[3 * p + a] += loads_.force[p][a];
      if (torque) torque[3 * p + a] += loads_.torque[p][a];
    }
}

}  // namespace coupling
