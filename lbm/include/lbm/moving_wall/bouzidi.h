#pragma once
// Linear interpolation on a moving wall (Bouzidi, Firdaouss & Lallemand 2001), second order
// for any fraction s of the link, with the wall term scaled by 1/(2 s) for s >= 1/2 (the
// q-dependent form that keeps Couette flow exact):
//   s <  1/2: f_{-q}(x, t+1) = 2 s f*_q(x) + (1 - 2 s) f*_q(x - c_q) - 6 w_q rho0 c_q.u_w
//   s >= 1/2: f_{-q}(x, t+1) = (f*_q(x) + (2 s - 1) f*_{-q}(x) - 6 w_q rho0 c_q.u_w) / (2 s)
// Where the second node x - c_q is not fluid (s < 1/2) it falls back to bounce-back.
#include <cstdint>
#include <vector>

#include "lbm/moving_wall/link_boundary.h"
#include "lbm/moving_wall/moving_wall_scheme.h"

namespace lbm::moving_wall {

struct Bouzidi {
  double rho0 = 1.0;                                     // reference density of the wall term
  const std::vector<std::uint8_t>* node_type = nullptr;  // to tell whether x - c_q is fluid

  double returning_population(const BoundaryLink& link, std::ptrdiff_t offset,
                              const PopulationField& f) const;
};

}  // namespace lbm::moving_wall
