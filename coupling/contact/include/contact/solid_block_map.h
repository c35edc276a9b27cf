#pragma once
// Which blocks of kBlock^3 voxels hold any solid voxel: the coarse map that lets a wall model
// skip particles in open fluid (most of them) without scanning the voxels around each, and
// scan only the blocks that hold solid near a wall. Both wall models use it: the smooth
// surface search (voxel_surface.h) and the paper's voxel sum (voxel_sum_wall.h). It also keeps
// the solid voxels of every row along x as runs, so the voxel sum visits only solid voxels of
// a row instead of testing each (a particle at a flat wall has a few hundred fluid voxels in
// reach for every solid one). Keeps a reference to the geometry, which must outlive it.
#include <algorithm>
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

  // Calls visit(i) for every solid voxel (i, j, k) with first <= i <= last, in increasing i.
  template <class Visit>
  void for_each_solid_in_row(int j, int k, int first, int last, Visit&& visit) const {
    const std::size_t r = row(j, k);
    for (std::size_t run = row_first_run_[r]; run < row_first_run_[r + 1]; ++run) {
      if (runs_[run].begin > last) return;
      for (int i = std::max(first, runs_[run].begin); i <= std::min(last, runs_[run].end - 1); ++i)
        visit(i);
    }
  }

  const lbm::VoxelGeometry& geometry() const { return *geometry_; }

 private:
  std::size_t row(int j, int k) const {
    return static_cast<std::size_t>(k) * geometry_->dims()[1] + j;
  }

  const lbm::VoxelGeometry* geometry_;
  int blocks_[3] = {0, 0, 0};
  std::vector<unsigned char> block_has_solid_;
  // Solid voxels begin ... end - 1 of a row along x, in increasing order of i.
  struct Run {
    int begin = 0, end = 0;
  };
  std::vector<Run> runs_;
  std::vector<std::size_t> row_first_run_;  // per row, then one past the last row
};

// Squared gap, in cells, from lattice coordinate u to the extent [cell, cell + 1) of a voxel
// along one axis (0 inside it): summed over the axes, a lower bound of the squared distance
// to the voxel's cube that wall searches use to skip voxels out of reach cheaply.
inline double squared_gap_to_cell(double u, int cell) {
  const double gap = u < cell ? cell - u : u - (cell + 1);
  return gap > 0.0 ? gap * gap : 0.0;
}

}  // namespace contact
