#include "lbm/moving_wall/link_boundary.h"

#include <algorithm>
#include <stdexcept>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "lbm/fluid_solver.h"
#include "lbm/moving_wall/bounce_back.h"
#include "lbm/moving_wall/bouzidi.h"
#include "lbm/moving_wall/mei_luo_shyy.h"

namespace lbm {

namespace {
// Below this many links per thread the start of a parallel region costs more than it saves.
constexpr std::size_t kMinLinksPerThread = 256;

// Bounce-back or Bouzidi.
void apply_without_moments(const std::vector<BoundaryLink>& links, MovingWallScheme scheme,
                           double rho0, const BlockLayout& layout,
                           const std::vector<std::uint8_t>& node_type, PopulationField& f,
                           std::vector<std::array<double, 3>>* momentum, int threads,
                           std::vector<LinkPopulations>* populations) {
  switch (scheme) {
    case MovingWallScheme::kBounceBack:
      moving_wall::apply(links, moving_wall::BounceBack{rho0}, layout, f, momentum, threads,
                         populations);
      return;
    case MovingWallScheme::kBouzidi:
      moving_wall::apply(links, moving_wall::Bouzidi{rho0, &node_type}, layout, f, momentum, threads,
                         populations);
      return;
    case MovingWallScheme::kMeiLuoShyy:
      break;
  }
  throw std::invalid_argument(
      std::string("apply_links: the ") + moving_wall::label(scheme) +
      " scheme needs the solver's tau and body force; pass the FluidSolver");
}
}  // namespace

int link_threads(std::size_t num_links) {
#ifdef _OPENMP
  return std::max(1, std::min(omp_get_max_threads(), int(num_links / kMinLinksPerThread)));
#else
  (void)num_links;
  return 1;
#endif
}

void apply_links(const std::vector<BoundaryLink>& links, MovingWallScheme scheme,
                 FluidSolver& solver, moving_wall::MomentCache* cache,
                 std::vector<std::array<double, 3>>* momentum,
                 std::vector<LinkPopulations>* populations,
                 const moving_wall::GhostMoments* ghosts) {
  // The links of spheres and walls are distinct and leave fluid nodes: they may be split over
  // threads (moving_wall::apply).
  const int threads = link_threads(links.size());
  if (scheme != MovingWallScheme::kMeiLuoShyy) {
    apply_without_moments(links, scheme, solver.parameters().rho0, solver.layout(),
                          solver.node_types(), solver.populations(), momentum, threads, populations);
    return;
  }
  moving_wall::MomentCache local;
  moving_wall::MomentCache& moments = cache ? *cache : local;
  moments.begin(solver.layout().num_cells(), threads);
  if (ghosts) moments.preset(*ghosts);
  const moving_wall::MeiLuoShyy mls{solver.parameters().rho0, 1.0 / solver.trt().omega_plus,
                                    solver.parameters().body_force, &solver.node_types(), &moments};
  moving_wall::apply(links, mls, solver.layout(), solver.populations(), momentum, threads,
                     populations);
}

void apply_links(const std::vector<BoundaryLink>& links, MovingWallScheme scheme, double rho0,
                 const BlockLayout& layout, const std::vector<std::uint8_t>& node_type,
                 PopulationField& f, std::vector<std::array<double, 3>>* momentum) {
  apply_without_moments(links, scheme, rho0, layout, node_type, f, momentum, 1, nullptr);
}

}  // namespace lbm
