#pragma once
// One coupled fluid step with resolved moving spheres, as a named pipeline of stages
// (waLBerla's time loop): map -> refill -> exchange_halo -> static walls -> moving walls
// with the link mass correction -> open boundaries -> collide_stream -> momentum exchange.
// By default the moving walls' links are applied inside the collide-stream's pass
// (SphereCouplingOptions::moving_walls_in_kernel), so the momentum exchange, which reads
// what they recorded, comes after it.
#include "coupling/boundary/ghost_moment_cells.h"
#include "coupling/boundary/sphere_links.h"
#include "coupling/boundary/whole_ghost_axes.h"
#include "coupling/force/momentum_exchange.h"
#include "coupling/force/open_face_pressure.h"
#include "coupling/mapping/sphere_mapping.h"
#include "coupling/particle_view.h"
#include "coupling/reconstruction/refill.h"
#include "lbm/fluid_solver.h"
#include "lbm/moving_wall/ghost_moments.h"
#include "lbm/moving_wall/link_boundary.h"
#include "lbm/moving_wall/link_mass.h"
#include "lbm/moving_wall/link_sweep.h"

namespace coupling {

struct SphereCouplingOptions {
  lbm::MovingWallScheme wall_scheme = lbm::MovingWallScheme::kMeiLuoShyy;
  RefillScheme refill = RefillScheme::kEquilibriumAveragedDensity;
  MomentumExchange momentum_exchange = MomentumExchange::kGalileanInvariant;
  ReferencePressure reference_pressure = ReferencePressure::kRemoved;
  // Put back, at each fluid node, the mass its interpolated links created or destroyed
  // (lbm/moving_wall/link_mass.h); without it the fluid mass grows in dense fixed arrays.
  bool conserve_link_mass = true;
  // That correction taken in the collide-stream kernel's pass, which reads the populations it
  // changes anyway, instead of in the moving walls' sweep (FluidSolver::
  // correct_pulls_in_next_step): the same operations on the same values, the same bits.
  bool correct_mass_in_kernel = true;
  // Mei-Luo-Shyy reads the moments of the nodes next to the spheres from the field the
  // collide-stream kernel keeps (FluidSolver::keep_node_moments) rather than gathering each
  // node's 19 populations (the same values bit for bit; which is faster depends on the load:
  // bench_coupling_stages, bench_paper_run).
  bool kernel_moments = true;
  // The moving walls themselves (the links' returning populations and their defects) taken
  // in that pass too, each node's links just ahead of the cells the kernel computes
  // (lbm::moving_wall::KernelLinks): the same operations on the same values, the same bits,
  // one pass over the boundary nodes' populations instead of two. Where Mei-Luo-Shyy reads
  // the kernel's moments with the correction in the kernel; otherwise the sweep.
  bool moving_walls_in_kernel = true;
};

// Wall-clock seconds spent in each stage, accumulated over steps (coupling/stage_clock.h, the
// clock a host's RunTimer reads too).
struct StageTimes {
  double mapping = 0.0, refill = 0.0, halo = 0.0, static_walls = 0.0, moving_walls = 0.0,
         force = 0.0, open_boundaries = 0.0, collide_stream = 0.0;
};

// The links of the moving surfaces summed over `steps` calls of apply_moving_walls
// on this rank: the work of the coupling stages, which cost per link.
struct LinkCounts {
  long long steps = 0, links = 0;
};

// How often the step's halo exchange sent, on each axis, the moments of the ghost nodes
// besides the five populations crossing each face (Mei-Luo-Shyy reads the moments of a
// ghost node, whole_ghost_axes), over `steps` calls of map_and_refill.
struct HaloCounts {
  long long steps = 0;
  std::array<long long, 3> moments{0, 0, 0};
};

// Owns the particle-dependent state of one rank's lattice (the mapping and the links) and
// the hydrodynamic loads of the last step. The FluidSolver stays the caller's.
//
// The host drives one fluid step every N_DEM DEM substeps:
//   coupling.step(view);                    // positions and velocities at time t
//   for each DEM substep: coupling.add_forces(view_forces)  // or read force(p)/torque(p)
// The loads of a step act unchanged over the next N_DEM substeps (paper Sec. II.D); they are
// indexed like the view passed to step(), so the host reads them before re-sorting atoms.
class SphereCoupling {
 public:
  SphereCoupling(lbm::FluidSolver& solver, const SphereCouplingOptions& options = {});

  // Maps the spheres, refills uncovered nodes, runs the fluid step with the moving walls
  // and stores the hydrodynamic force and torque on every particle of the view.
  void step(const ParticleView& view);

  // The stages, public so a host can time or reorder them; step() calls them in order.
  void map_and_refill(const ParticleView& view);
  // The populations crossing each face, and on the axes map_and_refill marked the moments
  // of the ghost nodes (four values each instead of the other 14 populations, the same
  // result: lbm::moving_wall::exchange_ghost_moments), which the next
  // apply_moving_walls reads.
  void exchange_halo();
  // The links of the spheres and their returning populations with the link mass correction
  // (or, by default, their hand-over to the next collide_stream), and the push of the fluid
  // beyond the open faces, before the open boundaries.
  void apply_moving_walls(const ParticleView& view);
  // After the collide_stream: the step's hydrodynamic loads (momentum exchange, paper Eq. 2,
  // and the open faces' pushes), the link defect and the surface mass.
  void exchange_momentum();
  // How far (cells) beyond this rank's owned box the views passed to step() hold every
  // particle, and a bound of every particle's radius (cells). When the first is at least
  // the second plus kGhostMomentMargin, every rank knows the spheres whose links read a
  // ghost's moments, and exchange_halo computes and reads the moments only near the spheres
  // (ghost_moment_cells.h); otherwise (the default, nothing known) on the whole planes. The
  // result is the same either way.
  void set_particle_reach(double view_reach, double radius_bound);

  const Vec3& force(std::size_t p) const { return loads_.force[p]; }
  const Vec3& torque(std::size_t p) const { return loads_.torque[p]; }
  const HydrodynamicLoads& loads() const { return loads_; }
  // Adds the stored loads to 3-per-particle arrays (e.g. atom->f[0]); torque may be null.
  void add_loads(std::size_t count, double* force, double* torque = nullptr) const;

  const MassChange& last_mass_change() const { return mass_; }
  // Mass the moving surfaces gave the fluid in the last step (this rank's links): the
  // moving-wall terms (lbm::moving_wall::moving_surface_mass), plus the link defect where the
  // correction is off.
  double last_surface_mass() const { return surface_mass_; }
  // Mass the moving-wall links of the last step created, measured before the correction
  // (removed again when options().conserve_link_mass).
  const lbm::moving_wall::LinkMassDefect& last_link_defect() const { return link_defect_; }
  const SphereLinks& links() const { return links_; }
  const SphereMapping& mapping() const { return mapping_; }
  const StageTimes& times() const { return times_; }
  // The axes along which the step's exchange sends the ghost nodes' moments, as the last
  // map_and_refill decided (all ranks alike).
  const std::array<bool, 3>& ghost_moment_axes() const { return ghost_moment_axes_; }
  const HaloCounts& halo_counts() const { return halo_counts_; }
  const LinkCounts& link_counts() const { return link_counts_; }
  const SphereCouplingOptions& options() const { return options_; }
  // Whether the last step's links were applied in the collide-stream's pass (else the sweep).
  bool links_in_kernel() const { return links_in_kernel_; }
  lbm::FluidSolver& solver() { return solver_; }
  const lbm::FluidSolver& solver() const { return solver_; }

 private:
  lbm::FluidSolver& solver_;
  SphereCouplingOptions options_;
  // Whether a step's links go to the collide-stream's pass, given the moment field
  // Mei-Luo-Shyy would read (none: the sweep).
  bool moving_walls_in_kernel(const lbm::NodeMomentField* field) const;
  SphereMapping mapping_;
  MappingChange change_;                     // reused every step
  SphereLinks links_;
  std::vector<SphereLinks> link_scratch_;    // per-thread links, reused every step
  lbm::moving_wall::MomentCache moment_cache_;  // reused every step
  lbm::moving_wall::LinkSweep link_sweep_;      // reused every step
  lbm::moving_wall::KernelLinks kernel_links_;  // what the kernel's pass reads, every step
  bool links_in_kernel_ = false;                // this step's links left to the kernel
  std::vector<OpenFacePush> open_face_pushes_;  // this step's, added after the kernel
  std::size_t num_particles_ = 0;               // the view of this step's links
  HydrodynamicLoads loads_;
  MassChange mass_;
  lbm::moving_wall::LinkMassDefect link_defect_;
  double surface_mass_ = 0.0;
  std::vector<lbm::LinkPopulations> link_populations_;  // per link, from the moving walls
  std::vector<double> defect_per_link_;  // reused every step
  // The refill's ghost densities, one per lattice cell (8 B per node), allocated on the
  // first step whose refill reads a ghost (FluidSolver::exchange_ghost_densities).
  std::vector<double> ghost_density_;
  // The ghosts' moments (32 B per node), allocated on the first step that sends them, and
  // whether the last exchange_halo filled them for the moving walls still to come.
  std::array<bool, 3> ghost_moment_axes_{false, false, false};
  lbm::moving_wall::GhostMoments ghost_moments_;
  bool ghost_moments_fresh_ = false;
  bool own_exchange_ = false;  // exchange_halo ran since the last moving walls
  bool ghost_moments_near_spheres_ = false;  // set_particle_reach
  GhostMomentCells ghost_moment_cells_;      // this step's, where near spheres; reused
  StageTimes times_;
  HaloCounts halo_counts_;
  LinkCounts link_counts_;
};

}  // namespace coupling
