#pragma once
#include <array>

#include "lbm/block_layout.h"
#include "lbm/communicator.h"

namespace lbm {

// How the global lattice is split: this rank's box, its six face neighbours and which
// axes are periodic. Any Cartesian processor grid with any cut positions is accepted (the
// boxes of face neighbours must share their extent in the other two axes, as LIGGGHTS's
// subdomains do), because the host (LIGGGHTS) dictates the split.
struct Decomposition {
  Box global;                                // the whole lattice
  Box owned;                                 // this rank's nodes
  std::array<bool, 3> periodic{false, false, false};
  // neighbor[axis][0] is the rank below (lower index), [1] above; -1 at a non-periodic
  // domain edge. On one rank with a periodic axis both are this rank.
  std::array<std::array<int, 2>, 3> neighbor{{{-1, -1}, {-1, -1}, {-1, -1}}};
  Communicator comm;

  // A single rank owning everything.
  static Decomposition serial(const Box& global, std::array<bool, 3> periodic);
  // A regular processor grid (procs[0]*procs[1]*procs[2] == comm.size()), rank order x
  // fastest; cuts at floor(global_size * p / procs) unless `cuts` gives them explicitly.
  static Decomposition grid(const Box& global, std::array<bool, 3> periodic,
                            std::array<int, 3> procs, const Communicator& comm);
};

}  // namespace lbm
