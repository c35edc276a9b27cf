#pragma once
// Which axes the step's halo exchange must send more than the crossing five on: where the
// moving-wall links may read a whole ghost node. Only its moments are read, so the exchange
// sends those (SphereCoupling::exchange_halo, moving_wall::exchange_ghost_moments: four
// values per ghost instead of the other 14 populations); all 19 would give the same result.
#include <array>

#include "coupling/mapping/sphere_mapping.h"
#include "lbm/fluid_solver.h"
#include "lbm/moving_wall/moving_wall_scheme.h"

namespace coupling {

// Per axis 1 if this rank's links may read the moments of a ghost node that the exchange
// fills along that axis, else 0 (to be summed over the ranks: every rank must send the
// same).
//
// Only Mei-Luo-Shyy reads a whole node besides the link's own (owned) fluid node x: the
// moments of its second node x - c_q (delta < 1/2, lbm/moving_wall/mei_luo_shyy.cpp). That
// node is a ghost beyond the low face of axis a exactly when x is on plane 0 and c_q[a] = +1,
// i.e. when the link's sphere node x + c_q is on plane 1; beyond the high face when it is on
// plane n_a - 2. An edge ghost is beyond the faces of two axes, and the same sphere node is
// then on the second plane of both, so both are raised (an edge ghost needs all 19 in both
// sweeps to arrive whole). Links point only into covered nodes of the mapping, so a covered
// node anywhere on the padded plane 1 (or n_a - 2) of a face the exchange fills raises the
// axis; conservative (the link's fraction and the ghost's type are not known before the
// exchange), never missing one. `mapping` as update() left it for this step.
std::array<long long, 3> whole_ghost_axes(const SphereMapping& mapping, lbm::MovingWallScheme scheme,
                                          const lbm::FluidSolver& solver);

}  // namespace coupling
