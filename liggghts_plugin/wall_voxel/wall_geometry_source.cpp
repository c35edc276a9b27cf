#include "wall_geometry_source.h"

#include "lbm/input_error.h"
#include "lbm/voxel_file.h"

namespace lbm_pore {

std::shared_ptr<const lbm::VoxelGeometry> acquire_wall_geometry(const WallGeometrySource& source) {
  switch (source.kind) {
    case WallGeometrySource::Kind::kFile:
      return std::make_shared<const lbm::VoxelGeometry>(lbm::load_voxel_file(source.path));
    case WallGeometrySource::Kind::kPoreScene:
      lbm::validate(source.pore);
      return std::make_shared<const lbm::VoxelGeometry>(
          lbm::make_pore_scene(source.pore, source.spacing, source.origin));
    case WallGeometrySource::Kind::kNone:
      break;
  }
  throw lbm::InputError("no geometry given: use keyword 'file <path>' or 'pore'");
}

}  // namespace lbm_pore
