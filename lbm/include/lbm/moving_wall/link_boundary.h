#pragma once
// Lattice links cut by a wall (static curved walls, moving spheres in coupling/) and the
// stage that rebuilds the populations returning from them with one of the moving-wall
// schemes beside this file (bounce_back.h, bouzidi.h, mei_luo_shyy.h).
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/moving_wall/moment_cache.h"
#include "lbm/moving_wall/moving_wall_scheme.h"
#include "lbm/population_field.h"

namespace lbm {

class FluidSolver;

// A lattice link cut by a wall: it leaves fluid node `fluid_cell` in direction q and meets
// the wall at x + fraction * c_q (0 < fraction <= 1). The wall moves with wall_velocity
// at the cut point.
struct BoundaryLink {
  std::size_t fluid_cell = 0;
  int q = 0;
  double fraction = 0.5;
  std::array<double, 3> wall_velocity{0.0, 0.0, 0.0};
};

// How many OpenMP threads a stage over `num_links` links uses: the available ones, but at
// least 256 links each (below that, starting a parallel region costs more than it saves).
int link_threads(std::size_t num_links);

// Writes, for every link, the population f_{-q}(x, t+1) into the slot it is pulled from
// (direction -q at node x + c_q, a non-fluid node), from the post-collision state f*(t), with
// the scheme chosen once for all links (moving_wall::apply). If `momentum` is non-null it
// receives, per link, the momentum the fluid gives the wall during the step; if
// `populations` is non-null, per link the two populations the later stages read
// (moving_wall::LinkPopulations).
// Any scheme; the solver gives rho0, tau_plus and the body force. `cache` may be null (a
// temporary one is used); pass a long-lived one when calling every step. Long link lists
// are split over the OpenMP threads (moving_wall::apply: same result for any number), so
// the links must be distinct and leave fluid nodes, as those of spheres and walls do.
// With Mei-Luo-Shyy, `ghosts` (if non-null) are the moments of ghost nodes received this
// step (moving_wall::exchange_ghost_moments), read instead of computing them from ghost
// populations that were not exchanged.
void apply_links(const std::vector<BoundaryLink>& links, MovingWallScheme scheme,
                 FluidSolver& solver, moving_wall::MomentCache* cache = nullptr,
                 std::vector<std::array<double, 3>>* momentum = nullptr,
                 std::vector<LinkPopulations>* populations = nullptr,
                 const moving_wall::GhostMoments* ghosts = nullptr);
// Bounce-back or Bouzidi only, on bare arrays (Mei-Luo-Shyy needs the solver's tau and body
// force: std::invalid_argument).
void apply_links(const std::vector<BoundaryLink>& links, MovingWallScheme scheme, double rho0,
                 const BlockLayout& layout, const std::vector<std::uint8_t>& node_type,
                 PopulationField& f, std::vector<std::array<double, 3>>* momentum = nullptr);

}  // namespace lbm
