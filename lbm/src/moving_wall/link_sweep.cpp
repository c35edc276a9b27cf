#include "lbm/moving_wall/link_sweep.h"

#include <algorithm>
#include <cstdlib>

#include "lbm/fluid_solver.h"
#include "lbm/moving_wall/link_boundary.h"
#include "lbm/moving_wall/bounce_back.h"
#include "lbm/moving_wall/bouzidi.h"
#include "lbm/moving_wall/mei_luo_shyy.h"

namespace lbm::moving_wall {

void LinkSweep::sort(const std::vector<BoundaryLink>& links, const BlockLayout& layout) {
  const std::size_t blocks = (layout.num_cells() >> kBlockShift) + 1;
  begin_.assign(blocks + 1, 0);
  for (const BoundaryLink& link : links) ++begin_[(link.fluid_cell >> kBlockShift) + 1];
  for (std::size_t b = 0; b < blocks; ++b) begin_[b + 1] += begin_[b];
  next_.assign(begin_.begin(), begin_.end() - 1);
  ids_.resize(links.size());
  for (std::size_t l = 0; l < links.size(); ++l)
    ids_[next_[links[l].fluid_cell >> kBlockShift]++] = std::uint32_t(l);
  // Cells one link apart (the scheme's reads x - c_q, the correction's writes x - c_p) are
  // at most `reach` indices apart, so at most reach / block + 1 blocks.
  std::ptrdiff_t reach = 0;
  for (int q = 0; q < D3Q19::Q; ++q)
    reach = std::max(reach, std::abs(layout.offset(D3Q19::c[q][0], D3Q19::c[q][1], D3Q19::c[q][2])));
  const std::size_t blocks_apart = (std::size_t(reach) >> kBlockShift) + 1;
  lag_ = 2 * blocks_apart + 1;
}

std::size_t LinkSweep::block_of_share(int t, int shares) const {
  const std::size_t blocks = num_blocks();
  if (t <= 0 || blocks == 0) return 0;
  if (t >= shares) return blocks;
  const std::size_t target = std::size_t(begin_[blocks]) * std::size_t(t) / std::size_t(shares);
  // The first block whose links start at or after the target link.
  return std::size_t(std::lower_bound(begin_.begin(), begin_.begin() + long(blocks), std::uint32_t(target)) -
                     begin_.begin());
}

LinkMassDefect apply_links_and_restore_mass(const std::vector<BoundaryLink>& links,
                                            MovingWallScheme scheme, FluidSolver& solver,
                                            MomentCache& cache, LinkSweep& order,
                                            std::vector<LinkPopulations>& populations,
                                            std::vector<double>& per_link,
                                            const GhostMoments* ghosts) {
  const double rho0 = solver.parameters().rho0;
  const BlockLayout& layout = solver.layout();
  PopulationField& f = solver.populations();
  const int threads = link_threads(links.size());
  order.sort(links, layout);
  const LinkMassRestorer restorer(layout, solver.node_types(), f);
  switch (scheme) {
    case MovingWallScheme::kBounceBack:
      sweep(links, order, BounceBack{rho0}, layout, rho0, restorer, f, populations, per_link, threads);
      break;
    case MovingWallScheme::kBouzidi:
      sweep(links, order, Bouzidi{rho0, &solver.node_types()}, layout, rho0, restorer, f,
            populations, per_link, threads);
      break;
    case MovingWallScheme::kMeiLuoShyy: {
      cache.begin(layout.num_cells(), threads);
      if (ghosts) cache.preset(*ghosts);
      const MeiLuoShyy mls{rho0, 1.0 / solver.trt().omega_plus, solver.parameters().body_force,
                           &solver.node_types(), &cache};
      sweep(links, order, mls, layout, rho0, restorer, f, populations, per_link, threads);
      break;
    }
  }
  LinkMassDefect total;
  for (const double d : per_link) total.add(d);
  return total;
}

}  // namespace lbm::moving_wall
