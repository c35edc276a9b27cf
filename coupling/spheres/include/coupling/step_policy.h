#pragma once
// Which fluid step a host runs, and what the coupled step may assume of the host's particle
// views. Collective: every rank must take the same step (the halo exchange pairs them), so
// both choices are made from sums and maxima over the solver's ranks.
#include "coupling/particle_view.h"
#include "coupling/sphere_coupling.h"
#include "lbm/communicator.h"

namespace coupling {

enum class FluidStep { kPure, kCoupled };

// The pure fluid step (FluidSolver::step) when no rank's view holds a particle and no rank
// has a node a sphere covered at the last coupled step (it must be uncovered and refilled
// first): a scene pays only for what it uses. The coupled step (SphereCoupling::step)
// otherwise.
FluidStep choose_fluid_step(const SphereCoupling& coupling, const ParticleView& view,
                            const lbm::Communicator& comm);

// SphereCoupling::set_particle_reach's arguments, in cells: how far beyond its subdomain
// each rank's view holds every particle (the host's ghost cutoff, ghost_cutoff[3] per axis
// in host units of length dx, the smallest of the three: a host such as LIGGGHTS keeps a
// ghost of every particle within it), and the largest radius of any rank's owned particles
// (a view's radii are in cells already).
struct ParticleReach {
  double view_reach = 0.0;
  double radius_bound = 0.0;
};
ParticleReach particle_reach(const ParticleView& view, const double* ghost_cutoff,
                             double dx, const lbm::Communicator& comm);

// One fluid step as chosen above; before a coupled one, the reach is passed on. Returns the
// step taken.
FluidStep advance_fluid(SphereCoupling& coupling, const ParticleView& view,
                        const double* ghost_cutoff, double dx, const lbm::Communicator& comm);

}  // namespace coupling
