#include "lbm/moving_wall/moment_cache.h"

#include <algorithm>

namespace lbm::moving_wall {

void MomentCache::begin(std::size_t num_cells, int tables) {
  if (tables_.size() < std::size_t(std::max(tables, 1))) tables_.resize(std::size_t(std::max(tables, 1)));
  const bool wrap = generation_ == UINT32_MAX;
  for (Table& t : tables_)
    if (t.stamp.size() != num_cells || wrap) {
      t.stamp.assign(num_cells, 0);
      t.value.resize(num_cells);
    }
  if (wrap) generation_ = 0;
  ++generation_;
}

void MomentCache::preset(const GhostMoments& ghosts) {
  const auto& c = ghosts.component;
  for (Table& t : tables_)
    for (const std::size_t cell : ghosts.cells) {
      t.stamp[cell] = generation_;
      t.value[cell] = NodeMoments{c[0][cell], {c[1][cell], c[2][cell], c[3][cell]}};
    }
}

}  // namespace lbm::moving_wall
