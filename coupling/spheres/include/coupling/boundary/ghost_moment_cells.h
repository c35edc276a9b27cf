#pragma once
// Which cells of the halo planes carry ghost moments in a step (SphereCoupling::exchange_halo,
// lbm::moving_wall::exchange_ghost_moments). Mei-Luo-Shyy reads the moments of the ghost node
// x - c_q only for a link (x, q) of fraction below 1/2: its sphere's surface lies within
// |c_q|/2 of x, so that node lies within R + 3/sqrt(2) (2.13 cells) of the sphere's centre
// (minimum image). Of the planes a sweep along a marked axis sends, only the cells within
// R + kGhostMomentMargin of a sphere then need their moments computed, and of the ghost
// planes it fills only those are read: a few hundred cells instead of whole planes. A sender
// must know every such sphere: the caller uses these lists only when its particle view
// reaches far enough beyond the rank (SphereCoupling::set_particle_reach).
#include <array>
#include <cstddef>
#include <vector>

#include "coupling/mapping/sphere_mapping.h"
#include "coupling/particle_view.h"
#include "lbm/fluid_solver.h"

namespace coupling {

constexpr double kGhostMomentMargin = 2.5;  // cells beyond R; above 3 / sqrt(2)

struct GhostMomentCells {
  std::vector<std::size_t> sent;      // cells of the sent planes near a sphere (may repeat)
  std::vector<std::size_t> received;  // cells of the ghost planes near a sphere (may repeat)
};

// The cells of the planes exchanged along the axes marked in `axes` (padded planes 0 and
// n - 1 sent, -1 and n filled, where that side has a neighbour) within R + kGhostMomentMargin
// of a sphere of `view`, every periodic image counted. `out`'s storage is reused.
void ghost_moment_cells(const SphereMapping& mapping, const ParticleView& view,
                        const lbm::FluidSolver& solver, const std::array<bool, 3>& axes,
                        GhostMomentCells& out);

}  // namespace coupling
