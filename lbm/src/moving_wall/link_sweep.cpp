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
  constexpr std::uint32_t kInBlock = (1u << kBlockShift) - 1;
  const std::size_t n = links.size();
  cell_.resize(n);
  for (std::size_t l = 0; l < n; ++l) cell_[l] = std::uint32_t(links[l].fluid_cell);
  // First pass: by the cell within its block (stable).
  std::uint32_t count[kInBlock + 2] = {};
  for (const std::uint32_t cell : cell_) ++count[(cell & kInBlock) + 1];
  for (std::uint32_t i = 0; i <= kInBlock; ++i) count[i + 1] += count[i];
  by_cell_in_block_.resize(n);
  for (std::size_t l = 0; l < n; ++l) by_cell_in_block_[count[cell_[l] & kInBlock]++] = std::uint32_t(l);
  // Second pass: by block, stable, so that within a block the cells ascend and a node's
  // links keep their order.
  const std::size_t blocks = (layout.num_cells() >> kBlockShift) + 1;
  begin_.assign(blocks + 1, 0);
  for (const std::uint32_t cell : cell_) ++begin_[(cell >> kBlockShift) + 1];
  for (std::size_t b = 0; b < blocks; ++b) begin_[b + 1] += begin_[b];
  next_.assign(begin_.begin(), begin_.end() - 1);
  ids_.resize(n);
  for (const std::uint32_t l : by_cell_in_block_) ids_[next_[cell_[l] >> kBlockShift]++] = l;
  sorted_.resize(n);
  sorted_cells_.resize(n);
  for (std::size_t i = 0; i < n; ++i) {
    sorted_[i] = links[ids_[i]];
    sorted_cells_[i] = cell_[ids_[i]];
  }
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
                                            const GhostMoments* ghosts,
                                            const NodeMomentField* field,
                                            bool correct_in_kernel) {
  const double rho0 = solver.parameters().rho0;
  const BlockLayout& layout = solver.layout();
  PopulationField& f = solver.populations();
  const int threads = link_threads(links.size());
  order.sort(links, layout);
  LinkMassRestorer::Deferral deferral;
  if (correct_in_kernel) {
    order.deferred_defects().resize(links.size());
    deferral = {order.ids(), order.deferred_defects().data()};
  }
  const LinkMassRestorer restorer(layout, solver.node_types(), f, deferral);
  switch (scheme) {
    case MovingWallScheme::kBounceBack:
      sweep(links, order, BounceBack{rho0}, layout, rho0, restorer, f, populations, per_link, threads);
      break;
    case MovingWallScheme::kBouzidi:
      sweep(links, order, Bouzidi{rho0, &solver.node_types()}, layout, rho0, restorer, f,
            populations, per_link, threads);
      break;
    case MovingWallScheme::kMeiLuoShyy: {
      if (!field) {
        cache.begin(layout.num_cells(), threads);
        if (ghosts) cache.preset(*ghosts);
      }
      const MeiLuoShyy mls{rho0, 1.0 / solver.trt().omega_plus, solver.parameters().body_force,
                           &solver.node_types(), &cache, 0, field};
      sweep(links, order, mls, layout, rho0, restorer, f, populations, per_link, threads);
      break;
    }
  }
  if (correct_in_kernel)
    solver.correct_pulls_in_next_step(order.sorted_cells(), order.deferred_defects().data(), links.size());
  return sum_link_defects(per_link);
}

}  // namespace lbm::moving_wall
