#pragma once
#include <istream>
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
// Errors throw InputError naming the file and what is wrong: missing file, bad magic, a
// header line with words missing or left over, sizes outside [1, 100000], sizes whose voxels
// do not fit in the memory available (refused before anything is allocated, with both
// figures: lbm/memory_estimate.h), truncated data or bytes after it, and a geometry that is
// all solid (no fluid to simulate).
VoxelGeometry load_voxel_file(const std::string& path);
// The raw format from a stream (the file reader and the fuzz target tests/fuzz use it);
// `name` is the file name the errors give.
VoxelGeometry read_raw_voxels(std::istream& in, const std::string& name);
void save_voxel_file_raw(const VoxelGeometry& geometry, const std::string& path);

}  // namespace lbm
