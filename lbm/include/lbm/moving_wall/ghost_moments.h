#pragma once
// The moments of ghost nodes as their owners computed them: four values per node travel
// instead of the 14 populations that the crossing five leave out. Mei-Luo-Shyy reads only
// the moments of a whole ghost node (MomentCache::preset puts them where it reads), and
// node_moments of the owner's populations is exactly what the receiver would compute from
// all 19 received, so the result does not change.
#include <array>
#include <cstddef>
#include <vector>

namespace lbm {
class FluidSolver;
}

namespace lbm::moving_wall {

struct GhostMoments {
  std::array<std::vector<double>, 4> component;  // rho, u_x, u_y, u_z; num_cells() each
  std::vector<std::size_t> cells;                // the ghosts whose components were received
};

// The moments (node_moments, with the body force) that solver.exchange_halo() with all 19
// populations along the axes marked in `axes` would let a reader compute at the ghosts of
// those axes, into `ghosts` (components sized num_cells() on first use), carried by
// FluidSolver::exchange_ghost_fields. Only the ghosts of a marked axis are filled (edge
// ghosts when both their axes are marked, as the population exchange fills them).
// `sent`: the cells of the sent planes whose moments are computed (every cell of those
// planes when null; a ghost then holds its owner's moments where the owner computed them);
// `ghosts.cells` is set to `received`, the ghosts the reader will read (every cell of the
// filled planes when null). Collective; every rank must pass the same `axes`.
void exchange_ghost_moments(FluidSolver& solver, const std::array<bool, 3>& axes,
                            GhostMoments& ghosts, const std::vector<std::size_t>* sent = nullptr,
                            const std::vector<std::size_t>* received = nullptr);

}  // namespace lbm::moving_wall
