#include "coupling/lubrication/nearest_wall.h"

#include <algorithm>

namespace coupling {

NearestWall find_nearest_wall(const contact::VoxelSurface& surface, const Vec3& x, double reach,
                              std::vector<contact::SurfacePoint>& scratch) {
  NearestWall wall;
  wall.searched_from = x;
  surface.find({x[0], x[1], x[2]}, reach, scratch);
  if (scratch.empty()) return wall;
  const auto nearest = std::min_element(scratch.begin(), scratch.end(),
                                         [](const auto& a, const auto& b) { return a.distance < b.distance; });
  wall.known = true;
  wall.distance = nearest->distance;
  for (int a = 0; a < 3; ++a) wall.normal[a] = nearest->normal[a];
  return wall;
}

}  // namespace coupling
