#pragma once
// Half-way bounce-back on a moving wall (Ladd 1994): the wall is taken half-way along every
// link whatever the fraction, so it is first order on curved walls.
//   f_{-q}(x, t+1) = f*_q(x) - 6 w_q rho0 c_q.u_w
#include "lbm/moving_wall/link_boundary.h"
#include "lbm/moving_wall/moving_wall_scheme.h"

namespace lbm::moving_wall {

struct BounceBack {
  double rho0 = 1.0;  // reference density of the wall term

  double returning_population(const BoundaryLink& link, std::ptrdiff_t offset,
                              const PopulationField& f) const;
};

}  // namespace lbm::moving_wall
