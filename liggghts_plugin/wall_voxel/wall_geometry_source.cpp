#include "wall_geometry_source.h"

#include "lbm/input_error.h"
#include "lbm/memory_estimate.h"
#include "lbm/voxel_file.h"

namespace lbm_pore {

std::shared_ptr<const lbm::VoxelGeometry> acquire_wall_geometry(const WallGeometrySource& source) {
  switch (source.kind) {
    case WallGeometrySource::Kind::kFile:
      return std::make_shared<const lbm::VoxelGeometry>(lbm::load_voxel_file(source.path));
    case WallGeometrySource::Kind::kPoreScene: {
      lbm::validate(source.pore);
      const lbm::PoreSceneSpec& s = source.pore;
      const double length =
          double(s.inlet_length) + s.free_length + s.pore_length + s.outlet_length;
      lbm::check_fits_in_memory(
          length * s.width * s.width,
          "pore: inlet_length + free_length + pore_length + outlet_length = " +
              std::to_string(static_cast<long long>(length)) + " by width " +
              std::to_string(s.width) + " squared voxels (a byte each)",
          "shorten the scene or use a coarser spacing");
      return std::make_shared<const lbm::VoxelGeometry>(
          lbm::make_pore_scene(s, source.spacing, source.origin));
    }
    case WallGeometrySource::Kind::kNone:
      break;
  }
  throw lbm::InputError("no geometry given: use keyword 'file <path>' or 'pore'");
}

}  // namespace lbm_pore
