#pragma once
// The moving walls and the link mass correction (link_mass.h) in one sweep over the lattice
// instead of two passes over the links. Each pass gathers 19 populations per fluid node from
// 19 arrays; the nodes next to the spheres of a rank's block span a few MiB of them, more
// than the L2 cache, so the second pass (the correction's 19 read-modify-writes per link)
// fetched them again from L3. The sweep takes the links in the memory order of their fluid
// node, in blocks of kBlockCells cells, and corrects block b - lag right after the moving
// walls of block b: the populations it writes are still in L2, and no link still to come
// reads them (lag covers twice the longest reach of a link, |c_q|'s cell-index step, once
// for the reads of the scheme (x, x - c_q) and once for the writes of the correction
// (x - c_p)).
//
// Bit-identical to apply_links; link_mass_defect; restore_link_mass: every cell the schemes
// read is read before any correction writes it; the correction writes the slots of each node
// in its links' order (the blocks keep link order within them, and a node's slots are pulled
// by that node alone); the defect sum runs in link order.
#include <cstdint>
#include <memory>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/moving_wall/link_boundary.h"
#include "lbm/moving_wall/link_mass.h"
#include "lbm/moving_wall/moment_cache.h"
#include "lbm/node_moment_field.h"

namespace lbm {
class FluidSolver;
}

namespace lbm::moving_wall {

// The links in the memory order of their fluid node, grouped by block of 64 cells (a radix
// sort in two counting passes, by the cell within its block and then by block: stable, so a
// node's links are consecutive and in link order), and the lag of the sweep. Reused between
// calls, so allocated once.
class LinkSweep {
 public:
  static constexpr int kBlockShift = 6;  // blocks of 64 cells

  void sort(const std::vector<BoundaryLink>& links, const BlockLayout& layout);
  std::size_t num_blocks() const { return begin_.empty() ? 0 : begin_.size() - 1; }
  std::size_t lag() const { return lag_; }
  // Block b's links are the sorted positions [first(b), first(b + 1)): position i holds link
  // id(i), a copy of which is link(i) (the sweep reads the links in its own order, from
  // memory in that order, rather than gathering them from the caller's order).
  std::size_t first(std::size_t block) const { return begin_[block]; }
  std::uint32_t id(std::size_t i) const { return ids_[i]; }
  const BoundaryLink& link(std::size_t i) const { return sorted_[i]; }
  const std::uint32_t* ids() const { return ids_.data(); }
  const BoundaryLink* sorted_links() const { return sorted_.data(); }
  // The fluid cell of the link at each sorted position (ascending), and room for one value
  // per position: the defects left to the kernel (LinkMassRestorer::Deferral).
  const std::uint32_t* sorted_cells() const { return sorted_cells_.data(); }
  std::vector<double>& deferred_defects() { return deferred_defects_; }
  // The first block of share t of `shares` (0 <= t <= shares): the blocks [block_of_share(t),
  // block_of_share(t + 1)) hold about 1/shares of the links, whole blocks; share `shares`
  // starts at num_blocks().
  std::size_t block_of_share(int t, int shares) const;

 private:
  std::vector<std::uint32_t> begin_, next_, ids_, by_cell_in_block_, cell_, sorted_cells_;
  std::vector<double> deferred_defects_;
  std::vector<BoundaryLink> sorted_;
  std::size_t lag_ = 0;
};

// The loop of the sweep for one scheme (link_loop.h): fills `populations` (as apply_links)
// and `per_link` (as link_mass_defect) and corrects the mass (as restore_link_mass).
template <class Scheme>
void sweep(const std::vector<BoundaryLink>& links, const LinkSweep& order, const Scheme& scheme,
           const BlockLayout& layout, double rho0, const LinkMassRestorer& restorer,
           PopulationField& f, std::vector<LinkPopulations>& populations,
           std::vector<double>& per_link, int threads);

// apply_links(links, scheme, solver, cache, nullptr, populations), then the link mass defect
// (returned, and per link in `per_link`) and restore_link_mass, as one sweep, split over the
// OpenMP threads by ranges of blocks (sweep in link_loop.h). The same result for any number
// of threads. Mei-Luo-Shyy reads the moments of the nodes from `field` where non-null (the
// solver's node_moment_field, whose ghosts every link may read hold their owners' moments),
// else from `cache`, with `ghosts` (as for apply_links) preset in it. With
// `correct_in_kernel`, the correction of the nodes away from the open faces is left to the
// solver's next collide_stream (FluidSolver::correct_pulls_in_next_step: the same operations
// on the same slots, so the same bits), which must come before anything else reads those
// nodes' populations.
LinkMassDefect apply_links_and_restore_mass(const std::vector<BoundaryLink>& links,
                                            MovingWallScheme scheme, FluidSolver& solver,
                                            MomentCache& cache, LinkSweep& order,
                                            std::vector<LinkPopulations>& populations,
                                            std::vector<double>& per_link,
                                            const GhostMoments* ghosts = nullptr,
                                            const NodeMomentField* field = nullptr,
                                            bool correct_in_kernel = false);

// The moving walls (Mei-Luo-Shyy on the kernel's moments) and the link mass correction in
// the pass of the solver's next collide_stream, which has the boundary nodes' populations in
// cache anyway: apply_links_and_restore_mass with `field` and correct_in_kernel, the same
// operations on the same values in a different order of nodes, so the same bits.
// begin() sorts the links, applies the nodes next to an open face at once (their correction
// cannot wait: lbm/moving_wall/link_mass.h) and hands the others to the solver
// (FluidSolver::correct_pulls_in_next_step with a PullPreparation): the kernel applies each
// node's links and writes its correction's entries a reach of the lattice ahead of the
// cells it computes, before any of them overwrites what the links read (lbm/pull_correction.h).
// `populations` and `per_link` are complete once collide_stream has run; the total defect
// is sum_link_defects(per_link) then. Nothing may read or write the lattice in between but
// the open boundaries, which touch no node that begin() left to the kernel.
class KernelLinks {
 public:
  KernelLinks();
  ~KernelLinks();
  void begin(const std::vector<BoundaryLink>& links, FluidSolver& solver,
             const NodeMomentField& field, LinkSweep& order,
             std::vector<LinkPopulations>& populations, std::vector<double>& per_link);
  // After the collide_stream: the wall-clock seconds the kernel spent applying the links
  // (the longest of its threads), which a host books to the moving walls, not the fluid.
  double prepared_seconds() const;

 private:
  struct State;  // what the kernel's preparation reads (mei_luo_shyy.cpp)
  std::unique_ptr<State> state_;
};

}  // namespace lbm::moving_wall
