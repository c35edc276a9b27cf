#pragma once
// Which blocks of kBlock^3 voxels hold any solid voxel: the coarse map that lets a wall model
// skip particles in open fluid (most of them) without scanning the voxels around each, and
// scan only the blocks that hold solid near a wall. Both wall models use it: the smooth
// surface search (voxel_surface.h) and the paper's voxel sum (voxel_sum_wall.h).
// Keeps a reference to the geometry, which must outlive it.
#include <vector>

#include "lbm/voxel_geometry.h"

namespace contact {

class SolidBlockMap {
 public:
  static constexpr int kBlock = 4;

  explicit SolidBlockMap(const lbm::VoxelGeometry& geometry);

  // Block (bi,bj,bk) holds voxels bi*kBlock ... bi*kBlock + kBlock - 1 (and so on).
  bool has_solid(int bi, int bj, int bk) const {
    return block_has_solid_[(static_cast<std::size_t>(bk) * blocks_[1] + bj) * blocks_[0] + bi] != 0;
  }
  // True when any solid voxel may lie in the index box lo..hi (inclusive, within the
  // geometry): false only when every block the box touches is all fluid.
  bool any_solid(const int lo[3], const int hi[3]) const;

  const lbm::VoxelGeometry& geometry() const { return *geometry_; }

 private:
  const lbm::VoxelGeometry* geometry_;
  int blocks_[3] = {0, 0, 0};
  std::vector<unsigned char> block_has_solid_;
};

}  // namespace contact
