#pragma once
// Density and velocity of fluid nodes, computed at most once per node per call. A node next
// to a sphere has several links (about five) and each Mei-Luo-Shyy link reads the moments of
// one or two nodes: 19 loads from 19 arrays each, the scheme's main cost. Reused between
// calls so its arrays are allocated once; a generation counter invalidates it in O(1).
#include <cstdint>
#include <vector>

#include "lbm/macroscopic.h"

namespace lbm::moving_wall {

class MomentCache {
 public:
  // Starts a new call: every cached value is stale.
  void begin(std::size_t num_cells);
  // lbm::node_moments at `cell`, from the first read since begin().
  const NodeMoments& moments(const PopulationField& f, std::size_t cell,
                             const std::array<double, 3>& body_force);

 private:
  std::vector<std::uint32_t> stamp_;
  std::vector<NodeMoments> value_;
  std::uint32_t generation_ = 0;
};

}  // namespace lbm::moving_wall
