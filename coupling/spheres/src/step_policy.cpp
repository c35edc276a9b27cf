#include "coupling/step_policy.h"

#include <algorithm>

namespace coupling {

FluidStep choose_fluid_step(const SphereCoupling& coupling, const ParticleView& view,
                            const lbm::Communicator& comm) {
  long long count = static_cast<long long>(view.num_owned) +
                    static_cast<long long>(coupling.mapping().moving_cells().size());
  comm.sum(&count, 1);
  return count > 0 ? FluidStep::kCoupled : FluidStep::kPure;
}

ParticleReach particle_reach(const ParticleView& view, const double* ghost_cutoff,
                             double dx, const lbm::Communicator& comm) {
  double largest = 0.0;
  for (std::size_t p = 0; p < view.num_owned; ++p) largest = std::max(largest, view.r(p));
  comm.max(&largest, 1);
  const double cutoff = std::min({ghost_cutoff[0], ghost_cutoff[1], ghost_cutoff[2]});
  return {cutoff / dx, largest};
}

FluidStep advance_fluid(SphereCoupling& coupling, const ParticleView& view,
                        const double* ghost_cutoff, double dx, const lbm::Communicator& comm) {
  const FluidStep step = choose_fluid_step(coupling, view, comm);
  if (step == FluidStep::kPure) {
    coupling.solver().step();
    return step;
  }
  const ParticleReach reach = particle_reach(view, ghost_cutoff, dx, comm);
  coupling.set_particle_reach(reach.view_reach, reach.radius_bound);
  coupling.step(view);
  return step;
}

}  // namespace coupling
