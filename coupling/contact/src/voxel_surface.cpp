#include "contact/voxel_surface.h"

#include <algorithm>
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


// Lattice coordinates of a query: voxel i spans [i, i + 1) in u.
struct Query {
  double u[3];
  Vec3 origin_shift;  // physical position of u = 0
  double spacing;
  double reach_u2;
  int lo[3], hi[3];   // voxel range within reach, clamped to the geometry
  bool empty;

  bool contains(const int cell[3]) const {
    for (int a = 0; a < 3; ++a)
      if (cell[a] < lo[a] || cell[a] > hi[a]) return false;
    return true;
  }
};

Query make_query(const lbm::VoxelGeometry& geometry, Vec3 centre, double reach) {
  Query q;
  q.spacing = geometry.spacing();
  const auto& origin = geometry.origin();
  const auto& dims = geometry.dims();
  const double c[3] = {centre.x, centre.y, centre.z};
  const double reach_u = reach / q.spacing;
  q.reach_u2 = reach_u * reach_u;
  q.origin_shift = {origin[0] - 0.5 * q.spacing, origin[1] - 0.5 * q.spacing,
                    origin[2] - 0.5 * q.spacing};
  q.empty = false;
  for (int a = 0; a < 3; ++a) {
    q.u[a] = (c[a] - origin[a]) / q.spacing + 0.5;
    q.lo[a] = std::max(0, static_cast<int>(std::floor(q.u[a] - reach_u)));
    q.hi[a] = std::min(dims[a] - 1, static_cast<int>(std::floor(q.u[a] + reach_u)));
    if (q.lo[a] > q.hi[a]) q.empty = true;
  }
  return q;
}

// The candidate of solid voxel `cell`, if it is a feature of the union within reach.
void consider_voxel(const lbm::VoxelGeometry& geometry, const Query& q, const int cell[3],
                    std::vector<SurfacePoint>& out) {
  int side[3];
  double closest[3];
  double dist2 = 0.0;
  for (int a = 0; a < 3; ++a) {
    side[a] = side_of(q.u[a], cell[a]);
    closest[a] = side[a] < 0 ? cell[a] : (side[a] > 0 ? cell[a] + 1 : q.u[a]);
    const double d = q.u[a] - closest[a];
    dist2 += d * d;
  }
  if (side[0] == 0 && side[1] == 0 && side[2] == 0) {
    out.push_back(inside_point(geometry, cell, q.u, q.spacing, q.origin_shift));
    return;
  }
  if (dist2 > q.reach_u2) return;
  if (feature_covered(geometry, cell, side)) return;
  const double dist = std::sqrt(dist2);
  SurfacePoint p;
  p.point = q.origin_shift + q.spacing * Vec3{closest[0], closest[1], closest[2]};
  if (dist > 0.0) {
    p.normal = (1.0 / dist) * Vec3{q.u[0] - closest[0], q.u[1] - closest[1], q.u[2] - closest[2]};
  } else {
    // Centre exactly on the surface: the outward direction of the feature.
    p.normal = Vec3{double(side[0]), double(side[1]), double(side[2])};
    p.normal = (1.0 / norm(p.normal)) * p.normal;
  }
  p.distance = dist * q.spacing;
  out.push_back(p);
}

// Calls visit(cell) for every solid voxel that may lie within the query's reach, block by
// block: each voxel once, in the same order as find_surface_points within a block (the order
// of the contacts does not matter), and in an order that does not depend on the query.
template <class Visit>
void for_each_solid_voxel_near(const SolidBlockMap& blocks, const Query& q, Visit&& visit) {
  constexpr int kBlock = SolidBlockMap::kBlock;
  if (q.empty) return;
  const double culled_beyond = q.reach_u2 * (1.0 + 1e-9);
  for (int bk = q.lo[2] / kBlock; bk <= q.hi[2] / kBlock; ++bk)
    for (int bj = q.lo[1] / kBlock; bj <= q.hi[1] / kBlock; ++bj)
      for (int bi = q.lo[0] / kBlock; bi <= q.hi[0] / kBlock; ++bi) {
        if (!blocks.has_solid(bi, bj, bk)) continue;
        const int k_end = std::min(q.hi[2], bk * kBlock + kBlock - 1);
        const int j_end = std::min(q.hi[1], bj * kBlock + kBlock - 1);
        const int i_end = std::min(q.hi[0], bi * kBlock + kBlock - 1);
        // Only the solid voxels of each row, and only rows and voxels whose per-axis gaps
        // leave them within reach: consider_voxel rejects the others without a trace, and
        // the margin is far above rounding, so the points found are the same.
        for (int k = std::max(q.lo[2], bk * kBlock); k <= k_end; ++k) {
          const double gap_z = squared_gap_to_cell(q.u[2], k);
          if (gap_z > culled_beyond) continue;
          for (int j = std::max(q.lo[1], bj * kBlock); j <= j_end; ++j) {
            const double gap_yz = gap_z + squared_gap_to_cell(q.u[1], j);
            if (gap_yz > culled_beyond) continue;
            blocks.for_each_solid_in_row(j, k, std::max(q.lo[0], bi * kBlock), i_end, [&](int i) {
              if (gap_yz + squared_gap_to_cell(q.u[0], i) > culled_beyond) return;
              const int cell[3] = {i, j, k};
              visit(cell);
            });
          }
        }
      }
}

}  // namespace

void find_surface_points(const lbm::VoxelGeometry& geometry, Vec3 centre, double reach,
                         std::vector<SurfacePoint>& out) {
  out.clear();
  const Query q = make_query(geometry, centre, reach);
  if (q.empty) return;
  for (int k = q.lo[2]; k <= q.hi[2]; ++k)
    for (int j = q.lo[1]; j <= q.hi[1]; ++j)
      for (int i = q.lo[0]; i <= q.hi[0]; ++i) {
        if (!geometry.is_solid(i, j, k)) continue;
        const int cell[3] = {i, j, k};
        consider_voxel(geometry, q, cell, out);
      }
}

void VoxelSurface::find(Vec3 centre, double reach, std::vector<SurfacePoint>& out) const {
  out.clear();
  const Query q = make_query(geometry(), centre, reach);
  for_each_solid_voxel_near(blocks_, q,
                            [&](const int cell[3]) { consider_voxel(geometry(), q, cell, out); });
}

void VoxelSurface::find(Vec3 centre, double reach, std::vector<SurfacePoint>& out,
                        WallCandidates& candidates) const {
  out.clear();
  if (!candidates.covers(centre, reach)) {
    candidates.restart(centre, reach + kWallCandidateSkin * geometry().spacing());
    const Query wide = make_query(geometry(), centre, candidates.reach);
    for_each_solid_voxel_near(blocks_, wide, [&](const int cell[3]) {
      candidates.voxels.push_back({cell[0], cell[1], cell[2]});
    });
  }
  const Query q = make_query(geometry(), centre, reach);
  if (q.empty) return;
  // The voxels of this query's own box, as the scan would see them.
  for (const auto& cell : candidates.voxels)
    if (q.contains(cell.data())) consider_voxel(geometry(), q, cell.data(), out);
}

}  // namespace contact
