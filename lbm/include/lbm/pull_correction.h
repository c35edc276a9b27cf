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

// Work the kernel has done for it in its own pass, just before it pulls: the entries of the
// nodes in [from, to) written (`defect`), and the slots those nodes pull prepared (the moving
// walls' returning populations: lbm/moving_wall/link_sweep.h, KernelLinks), while the kernel
// streams through their neighbourhood. What prepare reads of a node x lies within `reach`
// cells of x and must be what the kernel had not yet written in this pass; so the kernel
// prepares x before it computes any cell in [x - reach, x + reach): on each thread a
// reach ahead of the block it is about to compute, and the nodes within a reach of a thread's
// ends before any thread computes (the threads' ranges are disjoint; prepare is called with
// disjoint ranges from several threads at once).
struct PullPreparation {
  void (*prepare)(const void* context, std::size_t from, std::size_t to) = nullptr;
  const void* context = nullptr;
  std::size_t reach = 0;  // in cells
};

struct PullCorrections {
  const std::uint32_t* cell = nullptr;  // ascending; a node's entries consecutive
  const double* defect = nullptr;       // one per entry
  std::size_t count = 0;                // none where 0
  PullPreparation preparation;          // where prepare is null, the entries are written
};

// The entries of the nodes x in [first, last) taken off what they pull, pulled[p][x - first]
// (the slot f_p(x - c_p)). Built without contraction (lbm/CMakeLists.txt), as
// link_mass_restorer.cpp is.
void apply_pull_corrections(const PullCorrections& corrections, std::size_t first,
                            std::size_t last, Real* const* pulled);

}  // namespace lbm
