#pragma once
// Where a sphere meets a voxel geometry: the closest points of the surface of the union of
// solid voxel cubes, one per surface feature (face, edge, corner) near the sphere.
//
// Why not voxel by voxel: summing a contact with every nearby cube gives a bumpy force along
// a flat wall (the sphere also "sees" the edges of the neighbouring cubes of the same wall).
// Here a cube's closest point counts only if it lies on a feature of the *union*: a point on
// a face, edge or corner of cube A is dropped when any neighbour of A that shares that
// feature is solid, because that neighbour then covers the feature and gives a point that is
// at least as close. What remains are the local closest points of the union's surface:
//   flat wall       -> exactly one contact, normal to the wall, whatever the position;
//   inner corner    -> one contact per wall (two for an edge-shaped corner, three in a
//                      box corner);
//   outer edge      -> one contact whose normal points from the edge to the centre.
// Ties between neighbouring cubes are broken by half-open cube extents, computed in lattice
// coordinates so shared faces compare exactly.
//
// Voxel (i,j,k) is the cube of side `spacing` centred at origin + (i,j,k) * spacing
// (lbm::VoxelGeometry); voxels outside the geometry's box count as fluid.
#include <vector>

#include "contact/solid_block_map.h"
#include "contact/vec3.h"
#include "contact/wall_candidates.h"
#include "lbm/voxel_geometry.h"

namespace contact {

struct SurfacePoint {
  Vec3 point;   // on the solid surface
  Vec3 normal;  // unit, from the surface towards the sphere centre (out of the solid)
  // Signed distance from the centre to the surface: positive outside the solid, negative
  // when the centre itself lies inside a solid voxel (then the point is on the nearest
  // exposed face of that voxel and the normal is that face's outward normal).
  double distance = 0.0;
};

// Fills `out` with every surface feature within `reach` of `centre` (reach = radius plus
// the adhesion range for the wall fix). `out` is cleared first; pass the same vector every
// step to avoid allocations. Scans every voxel within reach: use VoxelSurface when calling
// it for many particles.
void find_surface_points(const lbm::VoxelGeometry& geometry, Vec3 centre, double reach,
                         std::vector<SurfacePoint>& out);

// The same query, accelerated for repeated calls: the coarse map of which blocks of voxels
// hold any solid (solid_block_map.h) lets particles in open fluid (most of them) skip the
// voxel scan, and particles near a wall scan only the blocks that hold solid. Same results
// as find_surface_points. Keeps a reference to the geometry, which must outlive it.
class VoxelSurface {
 public:
  explicit VoxelSurface(const lbm::VoxelGeometry& geometry) : blocks_(geometry) {}
  void find(Vec3 centre, double reach, std::vector<SurfacePoint>& out) const;
  // The same, from a particle's list of candidate voxels (wall_candidates.h), rebuilt here
  // when the particle has left its skin: same points, without the scan every step.
  void find(Vec3 centre, double reach, std::vector<SurfacePoint>& out,
            WallCandidates& candidates) const;
  const lbm::VoxelGeometry& geometry() const { return blocks_.geometry(); }
  // The block map, for a wall model that scans the voxels itself (voxel_sum_wall.h).
  const SolidBlockMap& blocks() const { return blocks_; }

  static constexpr int kBlock = SolidBlockMap::kBlock;

 private:
  SolidBlockMap blocks_;
};

}  // namespace contact
