#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/population_field.h"

namespace lbm {

// A lattice link cut by a wall: it leaves fluid node `fluid_cell` in direction q and meets
// the wall at x + fraction * c_q (0 < fraction <= 1). The wall moves with wall_velocity
// at the cut point. Used for static curved walls and for moving spheres (coupling/).
struct BoundaryLink {
  std::size_t fluid_cell = 0;
  int q = 0;
  double fraction = 0.5;
  std::array<double, 3> wall_velocity{0.0, 0.0, 0.0};
};

// How the population returning to the fluid node is reconstructed.
enum class LinkScheme {
  kBounceBack,  // half-way bounce-back (Ladd 1994): ignores the fraction, first order on curves
  kBouzidi,     // linear interpolation (Bouzidi, Firdaouss & Lallemand 2001), second order
};

// Writes, for every link, the population f_{-q}(x, t+1) into the slot it is pulled from
// (direction -q at node x + c_q, a non-fluid node), from the post-collision state f*(t).
// Moving walls add the momentum term -6 w_q rho0 c_q.u_w (scaled by 1/(2 fraction) in the
// Bouzidi branch with fraction >= 1/2, the q-dependent form that keeps Couette flow exact).
// Bouzidi falls back to bounce-back where the second fluid node x - c_q is not fluid.
// If `momentum` is non-null it receives, per link, the momentum the fluid gives the wall
// during the step: c_q (f*_q(x) + f_{-q}(x, t+1)) (momentum exchange, Ladd 1994; Mei et
// al. 2002, paper Eq. 2).
void apply_links(const std::vector<BoundaryLink>& links, LinkScheme scheme, double rho0,
                 const BlockLayout& layout, const std::vector<std::uint8_t>& node_type,
                 PopulationField& f, std::vector<std::array<double, 3>>* momentum = nullptr);

}  // namespace lbm
