#pragma once
#include <cstdint>

namespace lbm {

// What occupies a lattice node. Only kFluid nodes are collided; the others hold, in the
// slots that fluid nodes pull from, values written by the boundary stages before each step.
enum NodeType : std::uint8_t {
  kFluid = 0,
  kSolid = 1,   // static wall voxel (or a ghost beyond a non-periodic, closed domain face)
  kMoving = 2,  // covered by a moving particle (set by coupling/)
  kOpen = 3,    // ghost beyond an inlet or outlet face (filled by the open boundary stage)
};

}  // namespace lbm
