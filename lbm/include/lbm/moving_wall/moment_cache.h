#pragma once
// Density and velocity of fluid nodes, computed at most once per node per call. A node next
// to a sphere has several links (about five) and each Mei-Luo-Shyy link reads the moments of
// one or two nodes: 19 loads from 19 arrays each, the scheme's main cost. Reused between
// calls so its arrays are allocated once; a generation counter invalidates it in O(1).
// A call that splits its links over OpenMP threads begins as many tables, one per thread,
// so that no two threads write one entry (the values do not depend on which table holds
// them: the result is the same for any number of threads).
#include <array>
#include <cstdint>
#include <vector>

#include "lbm/macroscopic.h"
#include "lbm/moving_wall/ghost_moments.h"

namespace lbm::moving_wall {

class MomentCache {
 public:
  // Starts a new call with `tables` tables (threads): every cached value is stale.
  void begin(std::size_t num_cells, int tables = 1);
  // After begin(): the ghosts' received moments stand in every table, as if read there.
  void preset(const GhostMoments& ghosts);
  // lbm::node_moments at `cell`, from the first read since begin() in table `table`.
  const NodeMoments& moments(const PopulationField& f, std::size_t cell,
                             const std::array<double, 3>& body_force, int table = 0) {
    Table& t = tables_[std::size_t(table)];
    NodeMoments& v = t.value[cell];
    if (t.stamp[cell] != generation_) {
      t.stamp[cell] = generation_;
      v = node_moments(f, cell, body_force);
    }
    return v;
  }

 private:
  struct Table {
    std::vector<std::uint32_t> stamp;
    std::vector<NodeMoments> value;
  };
  std::vector<Table> tables_;
  std::uint32_t generation_ = 0;
};

}  // namespace lbm::moving_wall
