#include "lbm/moving_wall/moment_cache.h"

namespace lbm::moving_wall {

void MomentCache::begin(std::size_t num_cells) {
  if (stamp_.size() != num_cells || generation_ == UINT32_MAX) {
    stamp_.assign(num_cells, 0);
    value_.resize(num_cells);
    generation_ = 0;
  }
  ++generation_;
}

const NodeMoments& MomentCache::moments(const PopulationField& f, std::size_t cell,
                                        const std::array<double, 3>& body_force) {
  NodeMoments& v = value_[cell];
  if (stamp_[cell] != generation_) {
    stamp_[cell] = generation_;
    v = node_moments(f, cell, body_force);
  }
  return v;
}

}  // namespace lbm::moving_wall
