#pragma once
// Refill of nodes a moving sphere uncovers (waLBerla's reconstruction/ stage).
#include "coupling/mapping/sphere_mapping.h"
#include "lbm/fluid_solver.h"

namespace coupling {

enum class RefillScheme {
  // f = f^eq(rho_avg, u_w): rho_avg the mean density of the node's fluid neighbours (rho0 if
  // none), u_w = v + omega x r the sphere's surface velocity at the node (Aidun, Lu & Ding
  // 1998 use the same idea with rho0; the averaged density keeps the local pressure).
  kEquilibriumAveragedDensity,
  // f = f^eq(rho0, u_w): the simplest variant (Aidun et al. 1998).
  kEquilibriumReferenceDensity,
};

// Mass bookkeeping of one step: what the fluid lost to newly covered nodes and gained from
// refilled ones (owned nodes only, summed over this rank).
struct MassChange {
  double covered = 0.0;    // sum rho of nodes that left the fluid
  double refilled = 0.0;   // sum rho of refilled nodes
  long long num_covered = 0, num_refilled = 0;
  double net() const { return refilled - covered; }
  // What the step added to the fluid beyond the reference density rho0 per node: a covered
  // node takes its own density out of the fluid (the budget books rho0 of it as displaced
  // by the particle), a refilled one brings its refill density back (rho0 booked).
  double net_over(double rho0) const {
    return net() - rho0 * double(num_refilled - num_covered);
  }
};

// Writes the refill into the owned uncovered nodes (ghosts get theirs from the halo
// exchange) and accounts the covered ones; call before SphereMapping::commit so the
// neighbours' old types are still in place. `ghost_density`: the densities of the ghosts
// the halo exchange fills (FluidSolver::exchange_ghost_densities), read there instead of
// the ghosts' stale populations; nullptr when no refilled node has such a neighbour.
MassChange refill_uncovered(const MappingChange& change, const SphereMapping& mapping,
                            const ParticleView& view, RefillScheme scheme, lbm::FluidSolver& solver,
                            const std::vector<double>* ghost_density);

}  // namespace coupling
