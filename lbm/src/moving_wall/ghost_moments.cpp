#include "lbm/moving_wall/ghost_moments.h"

#include "lbm/fluid_solver.h"
#include "lbm/macroscopic.h"

namespace lbm::moving_wall {

// The owned planes' moments, then the solver's scalar sweeps along the marked axes carry
// them as exchange_halo() would carry the populations they come from.
void exchange_ghost_moments(FluidSolver& solver, const std::array<bool, 3>& axes,
                            GhostMoments& ghosts, const std::vector<std::size_t>* sent,
                            const std::vector<std::size_t>* received) {
  auto& c = ghosts.component;
  for (auto& component : c) component.resize(solver.layout().num_cells());
  const PopulationField& f = solver.populations();
  const std::array<double, 3>& body_force = solver.parameters().body_force;
  const auto compute = [&](const std::vector<std::size_t>& cells) {
    for (const std::size_t cell : cells) {
      const NodeMoments m = node_moments(f, cell, body_force);
      c[0][cell] = m.rho;
      for (int b = 0; b < 3; ++b) c[1 + b][cell] = m.u[b];
    }
  };
  ghosts.cells.clear();
  for (int a = 0; a < 3; ++a) {
    if (!axes[a]) continue;
    if (!sent) compute(solver.halo_sent_planes(a));
    const std::vector<std::size_t>& filled = solver.halo_ghost_planes(a);
    if (!received) ghosts.cells.insert(ghosts.cells.end(), filled.begin(), filled.end());
  }
  if (sent) compute(*sent);
  if (received) ghosts.cells.assign(received->begin(), received->end());
  double* fields[4] = {c[0].data(), c[1].data(), c[2].data(), c[3].data()};
  solver.exchange_ghost_fields(fields, 4, axes);
}

}  // namespace lbm::moving_wall
