#pragma once
// Where fix wall/voxel gets its voxel geometry from: a voxel file (lbm::load_voxel_file) or
// the paper's pore scene built from keywords (lbm::make_pore_scene). Kept apart from the fix
// so another fix (fix lbm/pore, which owns the fluid's geometry) can hand its geometry over
// instead, through FixWallVoxel::use_geometry().
#include <array>
#include <memory>
#include <string>

#include "lbm/pore_scene.h"
#include "lbm/voxel_geometry.h"

namespace lbm_pore {

struct WallGeometrySource {
  enum class Kind { kNone, kFile, kPoreScene };
  Kind kind = Kind::kNone;
  std::string path;              // kFile
  lbm::PoreSceneSpec pore;       // kPoreScene, lengths in voxels
  double spacing = 1.0;          // kPoreScene: voxel size in the script's length unit
  std::array<double, 3> origin{0.0, 0.0, 0.0};  // kPoreScene: centre of voxel (0,0,0)
};

// Throws lbm::InputError naming the file or keyword when the geometry cannot be built.
std::shared_ptr<const lbm::VoxelGeometry> acquire_wall_geometry(const WallGeometrySource& source);

}  // namespace lbm_pore
