#pragma once
// The moving walls (Mei-Luo-Shyy reading the kernel's moment field) and their link mass
// correction done in the collide-stream kernel's own pass, a little ahead of it
// (lbm::KernelAhead), instead of in a sweep of their own before it: the populations a node's
// links return and the 19 slots its correction changes are pulled by that node alone, so
// they are written just before the kernel pulls them, and reach it from the cache rather than
// from memory.
//
// A node x's work reads f*_q(x) (pulled by the covered node x + c_q, which the kernel
// overwrites), and the field's moments at x and x - c_q (which the kernel rewrites); it
// writes only slots x pulls. All lie within `reach` cells of x (the longest cell-index step of
// a D3Q19 direction), so x is done before the kernel computes any cell from x - reach on.
// A thread's nodes within reach of the ends of its cells are done before any thread starts
// (KernelAhead::begin); nodes in the first and last local planes along an axis can be done
// before the kernel starts (nodes_in_end_planes: the open faces read what they pull).
//
// The same values, bit for bit, as moving_wall::sweep: per node the same scheme calls on the
// same inputs, the correction's roundings in link order.
#include <memory>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/collide_stream.h"
#include "lbm/moving_wall/link_mass.h"
#include "lbm/moving_wall/link_sweep.h"
#include "lbm/moving_wall/mei_luo_shyy.h"

namespace lbm::moving_wall {

class LinksAhead : public KernelAhead {
 public:
  // `order` sorted for `links`; `populations` and `per_link` are sized here and filled as
  // apply_links_and_restore_mass fills them. The scheme must read the moments from a field.
  ~LinksAhead() override;
  LinksAhead(const std::vector<BoundaryLink>& links, const LinkSweep& order, const MeiLuoShyy& scheme,
             const BlockLayout& layout, double rho0, PopulationField& f,
             const std::vector<std::uint8_t>& node_type, std::vector<LinkPopulations>& populations,
             std::vector<double>& per_link);

  // Now, before the kernel: every node in the first or last local plane along `axis`.
  void nodes_in_end_planes(int axis);
  void begin(int t, int threads, std::size_t first, std::size_t last) override;
  void before(int t, std::size_t cell) override;

  // Every node done (after the kernel): their defects' sum in link order.
  LinkMassDefect defect() const;
  // Seconds thread 0 spent in the nodes' work during the kernel (to book it as the moving
  // walls' rather than the kernel's).
  double seconds_in_kernel() const { return seconds_; }

 private:
  // The node at sorted position i (its first link), unless done; returns the position after it.
  std::size_t node(std::size_t i);
  // Every node with its cell in [from, to) at positions [i, end), in order; returns the
  // position of the first node at or after `to`.
  std::size_t nodes_below(std::size_t i, std::size_t end, std::size_t to);
  std::size_t position_of(std::size_t cell) const;

  const LinkSweep& order_;
  MeiLuoShyy scheme_;
  const BlockLayout& layout_;
  double rho0_;
  PopulationField& f_;
  LinkMassRestorer restorer_;
  LinkPopulations* pops_;
  double* defect_;
  std::vector<std::uint8_t> done_;  // per sorted position of a node's first link
  std::size_t reach_;
  struct Share {
    std::size_t next = 0, stop = 0;  // the middle positions still to do
  };
  std::vector<Share> shares_;
  double seconds_ = 0.0;
  const std::vector<double>* per_link_;
  struct Slots;  // the slots' addresses, taken once (link_loop.h)
  std::unique_ptr<Slots> slots_;
};

}  // namespace lbm::moving_wall
