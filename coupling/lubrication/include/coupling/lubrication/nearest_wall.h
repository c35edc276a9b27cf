#pragma once
// The nearest wall of a particle, found on the voxel surface once per fluid step (a voxel
// search costs a sizeable part of a step) and followed along its normal within the DEM
// substeps: within a fluid step a particle moves less than half a cell, so its distance to
// that wall is the found distance plus its displacement along the normal.
#include <vector>

#include "contact/voxel_surface.h"
#include "coupling/particle_view.h"

namespace coupling {

struct NearestWall {
  bool known = false;              // a wall was within reach at the search
  double distance = 0.0;           // centre-to-surface distance then (host units)
  Vec3 normal{0.0, 0.0, 0.0};      // unit, from the wall into the fluid
  Vec3 searched_from{0.0, 0.0, 0.0};  // the particle centre at the search

  // Centre-to-surface distance of a particle now at x.
  double distance_from(const Vec3& x) const {
    double d = distance;
    for (int a = 0; a < 3; ++a) d += normal[a] * (x[a] - searched_from[a]);
    return d;
  }
};

// The nearest surface feature within `reach` of the centre x (reach = radius plus how far a
// wall force can act plus how far the particle may move in a fluid step); known = false
// when there is none. `scratch` is reused between calls (no allocation per search).
NearestWall find_nearest_wall(const contact::VoxelSurface& surface, const Vec3& x, double reach,
                              std::vector<contact::SurfacePoint>& scratch);

}  // namespace coupling
