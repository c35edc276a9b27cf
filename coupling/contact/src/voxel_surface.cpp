#include "contact/voxel_surface.h"

#include <cmath>
#include <limits>

namespace contact {

namespace {

// -1 / 0 / +1: where u lies relative to the half-open cube extent [cell, cell + 1).
int side_of(double u, int cell) {
  if (u < cell) return -1;
  if (u >= cell + 1) return 1;
  return 0;
}

// True when a solid neighbour shares the feature of cube `cell` that the offsets `side`
// describe: every non-zero offset t with t_a in {0, side_a}.
bool feature_covered(const lbm::VoxelGeometry& geometry, const int cell[3], const int side[3]) {
  for (int tx = 0; tx <= (side[0] != 0 ? 1 : 0); ++tx)
    for (int ty = 0; ty <= (side[1] != 0 ? 1 : 0); ++ty)
      for (int tz = 0; tz <= (side[2] != 0 ? 1 : 0); ++tz) {
        if (tx == 0 && ty == 0 && tz == 0) continue;
        if (geometry.is_solid(cell[0] + tx * side[0], cell[1] + ty * side[1],
                              cell[2] + tz * side[2]))
          return true;
      }
  return false;
}

// The centre lies inside solid cube `cell`: contact on its nearest exposed face (any face if
// none is exposed, which only happens deep inside a solid block).
SurfacePoint inside_point(const lbm::VoxelGeometry& geometry, const int cell[3],
                          const double u[3], double spacing, Vec3 origin_shift) {
  double best_depth = std::numeric_limits<double>::max();
  int best_axis = 0, best_dir = 1;
  bool best_exposed = false;
  for (int axis = 0; axis < 3; ++axis)
    for (int dir = -1; dir <= 1; dir += 2) {
      int neighbour[3] = {cell[0], cell[1], cell[2]};
      neighbour[axis] += dir;
      const bool exposed = !geometry.is_solid(neighbour[0], neighbour[1], neighbour[2]);
      const double depth = dir > 0 ? cell[axis] + 1 - u[axis] : u[axis] - cell[axis];
      if ((exposed && !best_exposed) || (exposed == best_exposed && depth < best_depth)) {
        best_depth = depth;
        best_axis = axis;
        best_dir = dir;
        best_exposed = exposed;
      }
    }
  SurfacePoint p;
  double on_face[3] = {u[0], u[1], u[2]};
  on_face[best_axis] = best_dir > 0 ? cell[best_axis] + 1 : cell[best_axis];
  p.point = origin_shift + spacing * Vec3{on_face[0], on_face[1], on_face[2]};
  p.normal[best_axis] = best_dir;
  p.distance = -best_depth * spacing;
  return p;
}

}  // namespace

void find_surface_points(const lbm::VoxelGeometry& geometry, Vec3 centre, double reach,
                         std::vector<SurfacePoint>& out) {
  out.clear();
  const double spacing = geometry.spacing();
  const auto& origin = geometry.origin();
  // Lattice coordinates: voxel i spans [i, i + 1) in u.
  const double u[3] = {(centre.x - origin[0]) / spacing + 0.5,
                       (centre.y - origin[1]) / spacing + 0.5,
                       (centre.z - origin[2]) / spacing + 0.5};
  // Physical position of u = 0.
  const Vec3 origin_shift{origin[0] - 0.5 * spacing, origin[1] - 0.5 * spacing,
                          origin[2] - 0.5 * spacing};
  const double reach_u = reach / spacing;
  const double reach_u2 = reach_u * reach_u;
  int lo[3], hi[3];
  for (int a = 0; a < 3; ++a) {
    lo[a] = static_cast<int>(std::floor(u[a] - reach_u));
    hi[a] = static_cast<int>(std::floor(u[a] + reach_u));
  }
  const auto& dims = geometry.dims();
  for (int a = 0; a < 3; ++a) {
    if (lo[a] < 0) lo[a] = 0;
    if (hi[a] > dims[a] - 1) hi[a] = dims[a] - 1;
  }

  for (int k = lo[2]; k <= hi[2]; ++k)
    for (int j = lo[1]; j <= hi[1]; ++j)
      for (int i = lo[0]; i <= hi[0]; ++i) {
        if (!geometry.is_solid(i, j, k)) continue;
        const int cell[3] = {i, j, k};
        int side[3];
        double closest[3];
        double dist2 = 0.0;
        for (int a = 0; a < 3; ++a) {
          side[a] = side_of(u[a], cell[a]);
          closest[a] = side[a] < 0 ? cell[a] : (side[a] > 0 ? cell[a] + 1 : u[a]);
          const double d = u[a] - closest[a];
          dist2 += d * d;
        }
        if (side[0] == 0 && side[1] == 0 && side[2] == 0) {
          out.push_back(inside_point(geometry, cell, u, spacing, origin_shift));
          continue;
        }
        if (dist2 > reach_u2) continue;
        if (feature_covered(geometry, cell, side)) continue;
        const double dist = std::sqrt(dist2);
        SurfacePoint p;
        p.point = origin_shift + spacing * Vec3{closest[0], closest[1], closest[2]};
        if (dist > 0.0) {
          p.normal = (1.0 / dist) * Vec3{u[0] - closest[0], u[1] - closest[1], u[2] - closest[2]};
        } else {
          // Centre exactly on the surface: the outward direction of the feature.
          p.normal = Vec3{double(side[0]), double(side[1]), double(side[2])};
          p.normal = (1.0 / norm(p.normal)) * p.normal;
        }
        p.distance = dist * spacing;
        out.push_back(p);
      }
}

}  // namespace contact
