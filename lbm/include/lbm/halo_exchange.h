#pragma once
#include <array>
#include <vector>

#include "lbm/d3q19.h"
#include "lbm/decomposition.h"
#include "lbm/halo_populations.h"
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
// entirely) is skipped.
//
// What is sent (doc/fluid.md, "Halo exchange"): per axis either the five
// populations crossing each face into the receiving block (c_q[a] = +1 upwards, -1
// downwards: 5/19 of the bytes) or all 19, as HaloPopulations says. exchange(field) sends
// all 19. FluidSolver::step() sends the five on every axis; so does the sphere coupling,
// and on the axes where Mei-Luo-Shyy may read a whole ghost node (coupling/boundary/
// whole_ghost_axes.h, decided by all ranks together) it sends that node's moments, the only
// thing the scheme reads of it, four values per cell (computed on sent_planes(), carried by
// exchange_scalars() through FluidSolver::exchange_ghost_fields). The refill, which reads only ghost
// densities, gets them with one value per cell (sent_cells(), exchange_scalar()).
//
// Audit of the readers of ghost populations. In a step the exchange is
// followed by static bounce-back (writes the solid ghost slots fluid nodes pull, reads owned
// nodes), the moving walls (write a slot at the non-fluid x + c_q of an owned fluid x; read
// x; Bouzidi reads f_q(x - c_q), crossing; Mei-Luo-Shyy reads the moments of x - c_q, the
// whole ghost node the flags are for, sent as moments), the link mass correction (read-modify-write of f_p(x - c_p),
// crossing), the open faces (read and write f_q(x - c_q) of owned face nodes, crossing) and
// collide-stream (pulls f_q(x - c_q), crossing, for every owned node). Collide-stream also
// computes the x-padding ghosts inside a run, from any population of the ghosts around
// them, and stores fluid-mask 0 times the result there: a zero whose sign alone can depend
// on a stale ghost value. Such a zero can only travel on as a zero (an owned non-fluid node
// that pulls it stores mask 0 times its result too); nothing reads a non-fluid node's
// populations (the schemes and the refill test the type first; a refill or an uncovering
// overwrites them) except the checkpoint, which may then differ in the sign bit of a zero
// of a solid node. Between steps nothing reads ghost populations: the
// diagnostics, VTK output (it exchanges its macroscopic fields), checkpoints, the stability
// guard and plane fluxes read owned nodes; the mapping, link building and lubrication read
// node types and particles; the refill reads owned densities, the exchanged ghost
// densities (exchange_scalar) and ghost populations only at ghosts no exchange writes
// (non-periodic edges). The densities it sends from ghost cells of sent_cells() (padded
// planes) are overwritten by an earlier sweep before they travel on, or belong to ghosts no
// exchange writes, so they do not depend on what was sent. Hence the five populations give
// bit-identical runs wherever Mei-Luo-Shyy does not read a whole ghost node.
class HaloExchange {
 public:
  HaloExchange(const Decomposition& decomposition, const BlockLayout& layout);
  // All 19 populations along every axis.
  void exchange(PopulationField& field);
  // The populations `which` names, per axis (HaloPopulations). Collective: every rank of
  // the decomposition must pass the same `which`.
  void exchange(PopulationField& field, const HaloPopulations& which);
  // Same for one scalar value per cell (e.g. particle ids on the lattice); doubles.
  void exchange_scalar(std::vector<double>& values);
  // The same for `count` fields of num_cells() doubles at once, swept only along the axes
  // marked in `axes`, in x, y, z order: the ghosts of the other axes keep what they held.
  void exchange_scalars(double* const* fields, int count, const std::array<bool, 3>& axes);
  // The same for one field of `width` doubles per cell side by side, value k of cell c at
  // values[width c + k] (NodeMomentField), carried in place as `width` fields would be.
  void exchange_interleaved(double* values, int width, const std::array<bool, 3>& axes);
  // The cells of the padded planes that a sweep along `axis` sends (planes 0 and n - 1,
  // where that side has a neighbour), and those it fills (the ghost planes -1 and n).
  const std::vector<std::size_t>& sent_planes(int axis) const { return sent_planes_[axis]; }
  const std::vector<std::size_t>& ghost_planes(int axis) const { return ghost_planes_[axis]; }
  // Whether the owned cell `cell` has a D3Q19 neighbour in a ghost that exchange() fills
  // (it lies on a face plane towards a neighbour rank or a periodic image); false for
  // ghost cells and for faces at a non-periodic domain edge, whose ghosts exchange() leaves.
  bool borders_exchanged_ghost(std::size_t cell) const;
  // Whether `cell` is a ghost that exchange() fills: on a ghost plane towards a neighbour
  // rank or periodic image (edges and corners included); false for owned cells.
  bool is_exchanged_ghost(std::size_t cell) const;
  // Whether exchange() fills the ghost plane on `side` (0 low, 1 high) of `axis`: there is a
  // neighbour rank or a periodic image there.
  bool exchanges_face(int axis, int side) const;
  // The cells an exchange sends, every sweep counted: the padded planes 0 and n - 1 of each
  // axis that have a neighbour on that side (each cell once, in increasing order). The
  // sweeps move values along the same paths whatever they carry, so a scalar field that
  // holds g(populations) on these cells holds, after exchange_scalar(), at every exchanged
  // ghost the g of the populations exchange() would have put there: the refill sends one
  // density per cell instead of 19 populations (FluidSolver::exchange_ghost_densities).
  const std::vector<std::size_t>& sent_cells() const { return sent_cells_; }

 private:
  // One sweep along `axis`: num_up arrays of num_cells() values each travel up, num_down
  // down. An array is a pointer, value of cell c at [c], or anything indexed the same way
  // (the interleaved fields' Interleaved, halo_exchange.cpp).
  template <class Array>
  void sweep(int axis, const Array* up, int num_up, const Array* down, int num_down);
  void check_neighbours() const;
  void collect_sent_cells();
  void collect_crossing();

  Decomposition decomposition_;  // a copy: callers may pass a temporary
  BlockLayout layout_;
  std::vector<double> send_low_, send_high_, recv_low_, recv_high_;
  std::vector<std::size_t> sent_cells_;
  std::array<std::vector<std::size_t>, 3> sent_planes_, ghost_planes_;
  // Per axis, the populations crossing a face upwards (c_q[a] = +1) and downwards (-1).
  int crossing_up_[3][D3Q19::Q] = {}, crossing_down_[3][D3Q19::Q] = {};
  int num_crossing_[3] = {0, 0, 0};
};

}  // namespace lbm
