#include "lbm/link_boundary.h"

#include <stdexcept>

#include "lbm/fluid_solver.h"
#include "lbm/moving_wall/bounce_back.h"
#include "lbm/moving_wall/bouzidi.h"
#include "lbm/moving_wall/mei_luo_shyy.h"

namespace lbm {

void apply_links(const std::vector<BoundaryLink>& links, MovingWallScheme scheme,
                 FluidSolver& solver, moving_wall::MomentCache* cache,
                 std::vector<std::array<double, 3>>* momentum) {
  if (scheme != MovingWallScheme::kMeiLuoShyy) {
    apply_links(links, scheme, solver.parameters().rho0, solver.layout(), solver.node_types(),
                solver.populations(), momentum);
    return;
  }
  moving_wall::MomentCache local;
  moving_wall::MomentCache& moments = cache ? *cache : local;
  moments.begin(solver.layout().num_cells());
  const moving_wall::MeiLuoShyy mls{solver.parameters().rho0, 1.0 / solver.trt().omega_plus,
                                    solver.parameters().body_force, &solver.node_types(), &moments};
  moving_wall::apply(links, mls, solver.layout(), solver.populations(), momentum);
}

void apply_links(const std::vector<BoundaryLink>& links, MovingWallScheme scheme, double rho0,
                 const BlockLayout& layout, const std::vector<std::uint8_t>& node_type,
                 PopulationField& f, std::vector<std::array<double, 3>>* momentum) {
  switch (scheme) {
    case MovingWallScheme::kBounceBack:
      moving_wall::apply(links, moving_wall::BounceBack{rho0}, layout, f, momentum);
      return;
    case MovingWallScheme::kBouzidi:
      moving_wall::apply(links, moving_wall::Bouzidi{rho0, &node_type}, layout, f, momentum);
      return;
    case MovingWallScheme::kMeiLuoShyy:
      break;
  }
  throw std::invalid_argument(
      std::string("apply_links: the ") + moving_wall::label(scheme) +
      " scheme needs the solver's tau and body force; pass the FluidSolver");
}

}  // namespace lbm
