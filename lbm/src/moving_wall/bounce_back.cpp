#include "lbm/moving_wall/bounce_back.h"

#include "link_loop.h"

namespace lbm::moving_wall {

double BounceBack::returning_population(const BoundaryLink& link, std::ptrdiff_t /*offset*/,
                                        const PopulationField& f) const {
  const double wall = wall_term(link.q, rho0, link.wall_velocity);
  const double out = f.at(link.q, link.fluid_cell);  // f*_q(x): travelling into the wall
  return out - wall;
}

LBM_MOVING_WALL_INSTANTIATE_LOOPS(BounceBack);

}  // namespace lbm::moving_wall
