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
  nodes_ = 0;
  for (std::size_t i = 0; i < n; ++i) {
    sorted_[i] = links[ids_[i]];
    nodes_ += i == 0 || sorted_[i].fluid_cell != sorted_[i - 1].fluid_cell;
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

void DeferredLinkMass::arm(const LinkSweep& order, const LinkMassRestorer& restorer,
                           const double* defect) {
  order_ = &order;
  restorer_.emplace(restorer);
  defect_ = defect;
  expected_ = order.num_nodes();
  visited_.store(0, std::memory_order_relaxed);
}

void DeferredLinkMass::before(std::size_t first, std::size_t last) const {
  if (!order_ || order_->num_links() == 0) return;
  const BoundaryLink* const link = order_->sorted_links();
  const std::size_t n = order_->num_links();
  // The links are in cell order: start at first's block, skip the cells before first.
  const std::size_t block = first >> LinkSweep::kBlockShift;
  if (block >= order_->num_blocks()) return;
  std::size_t i = order_->first(block);
  while (i != n && link[i].fluid_cell < first) ++i;
  std::size_t nodes = 0;
  while (i != n && link[i].fluid_cell < last) {
    const std::size_t x = link[i].fluid_cell;
    std::size_t node_end = i + 1;
    while (node_end != n && link[node_end].fluid_cell == x) ++node_end;
    if (!restorer_->next_to_open(x))  // the face nodes were corrected in the moving walls' sweep
      restorer_->remove_node(x, defect_, order_->ids() + i, order_->ids() + node_end);
    ++nodes;
    i = node_end;
  }
  if (nodes) visited_.fetch_add(nodes, std::memory_order_relaxed);
}

LinkMassDefect apply_links_and_restore_mass(const std::vector<BoundaryLink>& links,
                                            MovingWallScheme scheme, FluidSolver& solver,
                                            MomentCache& cache, LinkSweep& order,
                                            std::vector<LinkPopulations>& populations,
                                            std::vector<double>& per_link,
                                            const GhostMoments* ghosts,
                                            const std::array<std::vector<double>, 4>* field,
                                            DeferredLinkMass* deferred) {
  const double rho0 = solver.parameters().rho0;
  const BlockLayout& layout = solver.layout();
  PopulationField& f = solver.populations();
  const int threads = link_threads(links.size());
  order.sort(links, layout);
  const LinkMassRestorer restorer(layout, solver.node_types(), f);
  const bool defer = deferred != nullptr;
  switch (scheme) {
    case MovingWallScheme::kBounceBack:
      sweep(links, order, BounceBack{rho0}, layout, rho0, restorer, f, populations, per_link, threads, defer);
      break;
    case MovingWallScheme::kBouzidi:
      sweep(links, order, Bouzidi{rho0, &solver.node_types()}, layout, rho0, restorer, f,
            populations, per_link, threads, defer);
      break;
    case MovingWallScheme::kMeiLuoShyy: {
      if (!field) {
        cache.begin(layout.num_cells(), threads);
        if (ghosts) cache.preset(*ghosts);
      }
      const MeiLuoShyy mls{rho0, 1.0 / solver.trt().omega_plus, solver.parameters().body_force,
                           &solver.node_types(), &cache, 0, field};
      sweep(links, order, mls, layout, rho0, restorer, f, populations, per_link, threads, defer);
      break;
    }
  }
  if (deferred) deferred->arm(order, restorer, per_link.data());
  LinkMassDefect total;
  for (const double d : per_link) total.add(d);
  return total;
}

}  // namespace lbm::moving_wall
