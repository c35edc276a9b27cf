#pragma once
#include <vector>

#include "lbm/decomposition.h"
#include "lbm/population_field.h"

namespace lbm {

// Fills the ghost layer of a PopulationField from the face neighbours (or from the
// opposite side of this block for a periodic axis owned by this rank alone). Three sweeps,
// x then y then z, each sending the full padded extent of the other axes, so edge ghosts
// arrive too with only six messages. Ghosts at non-periodic domain edges are left alone
// (boundary conditions own them). Buffers are allocated once. Along an axis this rank owns
// entirely, the neighbours follow `periodic` (this rank, or none) whatever `neighbor` says;
// the constructor checks with the face neighbours that their boxes touch and share the
// extent of the other two axes (InputError otherwise). A side without a neighbour packs
// and receives nothing, and an axis without one on either side (non-periodic, owned
// entirely) is skipped. All 19 populations are sent: the pull stream needs only the five
// crossing a face, but Mei-Luo-Shyy reads the moments of a second fluid node that can be a
// ghost (README, "halo exchange"). The refill, which reads only ghost densities, gets them
// with one value per cell (sent_cells(), exchange_scalar()).
class HaloExchange {
 public:
  HaloExchange(const Decomposition& decomposition, const BlockLayout& layout);
  void exchange(PopulationField& field);
  // Same for one scalar value per cell (e.g. particle ids on the lattice); doubles.
  void exchange_scalar(std::vector<double>& values);
  // Whether the owned cell `cell` has a D3Q19 neighbour in a ghost that exchange() fills
  // (it lies on a face plane towards a neighbour rank or a periodic image); false for
  // ghost cells and for faces at a non-periodic domain edge, whose ghosts exchange() leaves.
  bool borders_exchanged_ghost(std::size_t cell) const;
  // Whether `cell` is a ghost that exchange() fills: on a ghost plane towards a neighbour
  // rank or periodic image (edges and corners included); false for owned cells.
  bool is_exchanged_ghost(std::size_t cell) const;
  // The cells an exchange sends, every sweep counted: the padded planes 0 and n - 1 of each
  // axis that have a neighbour on that side (each cell once, in increasing order). The
  // sweeps move values along the same paths whatever they carry, so a scalar field that
  // holds g(populations) on these cells holds, after exchange_scalar(), at every exchanged
  // ghost the g of the populations exchange() would have put there: the refill sends one
  // density per cell instead of 19 populations (FluidSolver::exchange_ghost_densities).
  const std::vector<std::size_t>& sent_cells() const { return sent_cells_; }

 private:
  // One sweep along `axis` over `components` arrays of num_cells() values each.
  template <class T>
  void sweep(int axis, T* const* arrays, int components);
  template <class T>
  void exchange_arrays(T* const* arrays, int components);
  void check_neighbours() const;
  void collect_sent_cells();

  Decomposition decomposition_;  // a copy: callers may pass a temporary
  BlockLayout layout_;
  std::vector<double> send_low_, send_high_, recv_low_, recv_high_;
  std::vector<std::size_t> sent_cells_;
};

}  // namespace lbm
