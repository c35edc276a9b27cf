#pragma once
#include <string>

#include "lbm/voxel_geometry.h"

namespace lbm {

// Voxel geometry files. Two formats, chosen by extension:
//
// 1. Raw (any extension but .vti): a text header of three lines, then the voxels as bytes.
//      LBMPORE_VOXELS 1
//      <nx> <ny> <nz>
//      <spacing> <origin_x> <origin_y> <origin_z>
//    followed, after the newline ending the third line, by exactly nx*ny*nz bytes,
//    x fastest then y then z; 0 = fluid, any other value = solid.
// 2. VTK XML image (.vti, needs VTK): a point- or cell-data array named "solid"
//    (any scalar type; nonzero = solid); dimensions, spacing (must be equal on all axes)
//    and origin are taken from the image.
//
// Errors (missing file, bad magic, truncated data, non-positive sizes) throw InputError
// naming the file and what is wrong.
VoxelGeometry load_voxel_file(const std::string& path);
void save_voxel_file_raw(const VoxelGeometry& geometry, const std::string& path);

}  // namespace lbm
