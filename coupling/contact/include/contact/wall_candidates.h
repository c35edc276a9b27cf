#pragma once
// The solid voxels a wall search may need for one particle, collected with a skin and reused
// while the particle stays inside it: the wall's counterpart of a neighbour list with a skin.
// A wall search scans the voxels of a box around the particle every DEM step; most of them are
// fluid or out of reach, and between fluid steps a particle moves a small fraction of a cell.
// With candidates, the search collects the solid voxels within reach + kWallCandidateSkin once,
// in its own visiting order, and then evaluates only those until the particle has moved (or
// its reach grown) by more than the skin. Every voxel within reach of the particle is within
// reach + skin of where the list was built (the distance to a cube changes at most as fast as
// the centre moves), and the search's exact test drops the others: results are bit-identical
// to scanning the box every step.
#include <array>
#include <vector>

#include "contact/vec3.h"

namespace contact {

// In multiples of the voxel spacing.
constexpr double kWallCandidateSkin = 0.5;

struct WallCandidates {
  Vec3 centre;          // where the list was built
  double reach = -1.0;  // reach it covers from there (skin included); negative: not built
  std::vector<std::array<int, 3>> voxels;  // (i, j, k), in the search's visiting order

  // True when every voxel within `query_reach` of `query_centre` is on the list.
  bool covers(Vec3 query_centre, double query_reach) const {
    return reach >= 0.0 && norm(query_centre - centre) + query_reach <= reach;
  }
  // Empty list, to be filled for `query_centre` with reach `covered_reach`.
  void restart(Vec3 query_centre, double covered_reach) {
    centre = query_centre;
    reach = covered_reach;
    voxels.clear();
  }
};

}  // namespace contact
