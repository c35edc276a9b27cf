#include "lbm/moving_wall/bouzidi.h"

#include "lbm/node_type.h"
#include "link_loop.h"

namespace lbm::moving_wall {

double Bouzidi::returning_population(const BoundaryLink& link, std::ptrdiff_t offset,
                                     const PopulationField& f) const {
  const int q = link.q, qo = D3Q19::opposite(q);
  const std::size_t x = link.fluid_cell;
  const double wall = wall_term(q, rho0, link.wall_velocity);
  const double out = f.at(q, x);  // f*_q(x): travelling into the wall
  const double s = link.fraction;
  if (s < 0.5 && (*node_type)[x - offset] == kFluid)
    return 2.0 * s * out + (1.0 - 2.0 * s) * f.at(q, x - offset) - wall;
  if (s >= 0.5) return (out + (2.0 * s - 1.0) * f.at(qo, x) - wall) / (2.0 * s);
  return out - wall;
}

LBM_MOVING_WALL_INSTANTIATE_LOOPS(Bouzidi);

}  // namespace lbm::moving_wall
