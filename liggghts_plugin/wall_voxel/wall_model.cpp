#include "wall_model.h"

#include "smooth_wall_model.h"
#include "voxel_sum_wall_model.h"

namespace lbm_pore {

const char* wall_model_name(WallModelKind kind) {
  return kind == WallModelKind::kVoxelSum ? "voxel_sum" : "smooth";
}

std::unique_ptr<WallModel> make_wall_model(WallModelKind kind,
                                           const contact::WallContactParams& params,
                                           std::shared_ptr<const lbm::VoxelGeometry> geometry) {
  if (kind == WallModelKind::kVoxelSum)
    return std::make_unique<VoxelSumWallModel>(params, std::move(geometry));
  return std::make_unique<SmoothWallModel>(params, std::move(geometry));
}

}  // namespace lbm_pore
