#include "lbm/voxel_geometry.h"

#include <algorithm>
#include <string>

#include "lbm/input_error.h"
#include "lbm/memory_estimate.h"

namespace lbm {

VoxelGeometry::VoxelGeometry(std::array<int, 3> dims, double spacing, std::array<double, 3> origin)
    : dims_(dims), spacing_(spacing), origin_(origin) {
  for (int d = 0; d < 3; ++d)
    if (dims[d] <= 0)
      throw InputError("voxel geometry: dimension " + std::to_string(d) + " is " +
                       std::to_string(dims[d]) + ", must be >= 1");
  if (!(spacing > 0.0)) throw InputError("voxel geometry: spacing must be > 0");
  // The last line of defence against std::bad_alloc: hosts check sooner, naming their keyword.
  check_fits_in_memory(geometry_bytes(dims), "voxel geometry: " + std::to_string(dims[0]) + " x " +
                                                 std::to_string(dims[1]) + " x " +
                                                 std::to_string(dims[2]) +
                                                 " voxels (one byte each)");
  solid_.assign(static_cast<std::size_t>(dims[0]) * dims[1] * dims[2], 0);
}

std::size_t VoxelGeometry::count_solid() const {
  return static_cast<std::size_t>(std::count_if(solid_.begin(), solid_.end(),
                                                [](std::uint8_t v) { return v != 0; }));
}

}  // namespace lbm
