#pragma once
#include <array>

#include "lbm/block_layout.h"
#include "lbm/decomposition.h"

namespace coupling {

// Where the lattice sits in the script's coordinates: node (i,j,k) is at
// origin + (i,j,k) * dx, for 0 <= i < dims[0] etc.
struct LatticeFrame {
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  double dx = 1.0;
  std::array<int, 3> dims{1, 1, 1};

  // Lattice coordinates of a point (node i at integer i).
  std::array<double, 3> to_lattice(const double* x) const {
    return {(x[0] - origin[0]) / dx, (x[1] - origin[1]) / dx, (x[2] - origin[2]) / dx};
  }

  // The nodes owned by a rank whose LIGGGHTS subdomain is [sublo, subhi): those whose
  // position lies inside it. Ranks whose subdomains tile the box get boxes that tile the
  // lattice exactly (a node on a shared face belongs to the upper rank). The first/last
  // ranks along an axis (at_lower/at_upper) extend to the lattice's ends.
  lbm::Box owned_box(const double* sublo, const double* subhi, const bool* at_lower,
                     const bool* at_upper) const;

  // Throws lbm::InputError when the lattice does not fill the box [box_lo, box_hi] (every
  // node's cell inside it, to half a cell), naming the axis and both extents. On a periodic
  // axis (periodic[a] != 0, may be null) the box's length must be the lattice's period,
  // dims * dx, to round-off: the host shifts its periodic images by the box length and the
  // mapping by the lattice's period, so any difference puts one sphere at two places, and
  // two ranks that share a periodic face then disagree on which nodes it covers (the owner
  // of a covered node sends it as empty, the neighbour streams and reads it as fluid).
  void check_fills_box(const double* box_lo, const double* box_hi, const int* periodic = nullptr) const;
};

// A host's processor grid as the lattice needs it (LIGGGHTS: comm->myloc, procgrid,
// procneigh and domain->sublo/subhi).
struct SubdomainGrid {
  const double* sublo = nullptr;
  const double* subhi = nullptr;
  const int* location = nullptr;         // this rank's position in the grid, per axis
  const int* procs = nullptr;            // ranks per axis
  const int (*neighbors)[2] = nullptr;   // rank below/above per axis
};

// This rank's share of the lattice: the nodes inside its subdomain, its face neighbours
// (-1 at a non-periodic edge of the box). Throws lbm::InputError when a rank would own no
// node along an axis (too many ranks for the lattice).
lbm::Decomposition subdomain_decomposition(const LatticeFrame& frame, const SubdomainGrid& grid,
                                           const std::array<bool, 3>& periodic, const lbm::Communicator& comm,
                                           int rank);

}  // namespace coupling
