#pragma once
// The parallel tests compare a rank's block with a serial run of the whole lattice node by
// node: this visits the pairs.
#include <cstddef>

#include "lbm/fluid_solver.h"

namespace lbm_parallel_test {

// visit(a, b) for every owned node of `parallel`: a its cell, b the cell of the same global
// node in `serial`, which holds the whole lattice.
template <class Visit>
void for_owned_pairs(const lbm::FluidSolver& parallel, const lbm::FluidSolver& serial, Visit visit) {
  const lbm::BlockLayout& p = parallel.layout();
  const lbm::BlockLayout& s = serial.layout();
  for (int k = 0; k < p.size(2); ++k)
    for (int j = 0; j < p.size(1); ++j)
      for (int i = 0; i < p.size(0); ++i) {
        const auto g = p.to_global(i, j, k);
        visit(p.cell(i, j, k), s.cell(g[0], g[1], g[2]));
      }
}

}  // namespace lbm_parallel_test
