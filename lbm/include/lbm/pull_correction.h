#pragma once
// Densities taken off the populations some nodes pull, in the collide-stream's own pass
// (CollideStreamArgs::pull_corrections): the moving walls' link mass correction
// (lbm/moving_wall/link_mass.h) left to the kernel, which reads each boundary node's 19
// incoming slots anyway, instead of a separate pass that writes them before.
//
// Entry e takes defect[e] w_p from each population node cell[e] pulls; a node's entries are
// consecutive and taken in their order, population by population, each product rounded
// before its subtraction: the operations LinkMassRestorer::remove_node performs on the slots,
// so the node collides the same bits as when the sweep writes the correction.
#include <cstddef>
#include <cstdint>

#include "lbm/real.h"

namespace lbm {

struct PullCorrections {
  const std::uint32_t* cell = nullptr;  // ascending; a node's entries consecutive
  const double* defect = nullptr;       // one per entry
  std::size_t count = 0;                // none where 0
};

// The entries of the nodes x in [first, last) taken off what they pull, pulled[p][x - first]
// (the slot f_p(x - c_p)). Built without contraction (lbm/CMakeLists.txt), as
// link_mass_restorer.cpp is.
void apply_pull_corrections(const PullCorrections& corrections, std::size_t first,
                            std::size_t last, Real* const* pulled);

}  // namespace lbm
