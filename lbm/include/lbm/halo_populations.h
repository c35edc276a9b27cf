#pragma once
#include <array>

namespace lbm {

// Which populations a halo exchange (HaloExchange::exchange) carries along each axis.
//
// The pull stream at an owned node x reads f_q(x - c_q): from a ghost beyond the low face of
// axis a only the five q with c_q[a] = +1, beyond the high face the five with c_q[a] = -1
// (D3Q19: one axis direction and four diagonals). The open faces, static bounce-back,
// Bouzidi and the link mass correction read or write no other ghost slot. Mei-Luo-Shyy is
// the one stage that reads a whole ghost node (all 19 populations, for its moments): its
// second fluid node x - c_q of a link from an owned x on a face plane into a sphere node on
// the second plane from that face. Only the coupling knows where its spheres are, so it
// raises `all` for the axes where that can happen (coupling/boundary/whole_ghost_axes.h);
// lbm/ never needs it by itself. Every rank must pass the same value for an axis: the
// message sizes depend on it.
struct HaloPopulations {
  // Per axis: all 19 populations of every exchanged ghost (true) or the five crossing
  // each face into the block (false).
  std::array<bool, 3> all{true, true, true};

  static HaloPopulations crossing() { return HaloPopulations{{false, false, false}}; }
  static HaloPopulations every() { return HaloPopulations{{true, true, true}}; }
};

}  // namespace lbm
