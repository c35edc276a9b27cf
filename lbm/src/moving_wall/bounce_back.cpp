#include "lbm/moving_wall/bounce_back.h"

#include "link_loop.h"

namespace lbm::moving_wall {

double BounceBack::returning_population(const BoundaryLink& link, std::ptrdiff_t /*offset*/,
                                        const PopulationField& f) const {
  const double wall = wall_term(link.q, rho0, link.wall_velocity);
  const double out = f.at(link.q, link.fluid_cell);  // f*_q(x): travelling into the wall
  return out - wall;
}

template void apply<BounceBack>(const std::vector<BoundaryLink>&, const BounceBack&,
                                const BlockLayout&, PopulationField&,
                                std::vector<std::array<double, 3>>*, int,
                                std::vector<LinkPopulations>*);

template void sweep<BounceBack>(const std::vector<BoundaryLink>&, const LinkSweep&, const BounceBack&,
                                const BlockLayout&, double, const LinkMassRestorer&, PopulationField&,
                                std::vector<LinkPopulations>&, std::vector<double>&, int);

}  // namespace lbm::moving_wall
