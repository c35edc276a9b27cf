#include "contact/solid_block_map.h"

namespace contact {

SolidBlockMap::SolidBlockMap(const lbm::VoxelGeometry& geometry) : geometry_(&geometry) {
  const auto& dims = geometry.dims();
  for (int a = 0; a < 3; ++a) blocks_[a] = (dims[a] + kBlock - 1) / kBlock;
  block_has_solid_.assign(static_cast<std::size_t>(blocks_[0]) * blocks_[1] * blocks_[2], 0);
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i)
        if (geometry.is_solid(i, j, k))
          block_has_solid_[(static_cast<std::size_t>(k / kBlock) * blocks_[1] + j / kBlock) *
                               blocks_[0] + i / kBlock] = 1;
  row_first_run_.reserve(static_cast<std::size_t>(dims[1]) * dims[2] + 1);
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j) {
      row_first_run_.push_back(runs_.size());
      for (int i = 0; i < dims[0]; ++i) {
        if (!geometry.is_solid(i, j, k)) continue;
        if (runs_.size() > row_first_run_.back() && runs_.back().end == i)
          ++runs_.back().end;
        else
          runs_.push_back({i, i + 1});
      }
    }
  row_first_run_.push_back(runs_.size());
}

bool SolidBlockMap::any_solid(const int lo[3], const int hi[3]) const {
  for (int bk = lo[2] / kBlock; bk <= hi[2] / kBlock; ++bk)
    for (int bj = lo[1] / kBlock; bj <= hi[1] / kBlock; ++bj)
      for (int bi = lo[0] / kBlock; bi <= hi[0] / kBlock; ++bi)
        if (has_solid(bi, bj, bk)) return true;
  return false;
}

}  // namespace contact
