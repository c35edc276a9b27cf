#include "voxel_sum_wall_model.h"

namespace lbm_pore {

VoxelSumWallModel::VoxelSumWallModel(const contact::WallContactParams& params,
                                     std::shared_ptr<const lbm::VoxelGeometry> geometry)
    : params_(params), geometry_(std::move(geometry)), blocks_(*geometry_) {}

WallForce VoxelSumWallModel::apply(int i, const WallParticle& particle) {
  contact::VoxelSumInput in(*geometry_);
  in.centre = particle.centre;
  in.radius = particle.radius;
  in.mass = particle.mass;
  in.velocity = particle.velocity;
  in.dt = particle.dt;
  in.springs = &springs_[i];
  in.blocks = &blocks_;
  in.candidates = &candidates_[i];
  contact::VoxelSumResult& result = result_;
  contact::voxel_sum_wall_force(params_, in, result);
  // The springs in use replace the atom's (a store copies only those; none out of reach).
  springs_[i] = result.springs;
  WallForce out;
  out.touching = result.contacts > 0;
  out.force = result.force;
  out.contacts = result.contacts;
  out.max_overlap_ratio = result.max_overlap_ratio;
  out.springs_dropped = result.springs_dropped;
  return out;
}

TimeStepFinding VoxelSumWallModel::time_step(double mass, double radius) const {
  TimeStepFinding found;
  const double resting = contact::voxel_sum_resting_stiffness(params_, radius);
  const bool tangential = params_.friction.k_t > resting;
  found.stiffness_name = tangential ? "kt" : "kw + 8 ka R";
  found.stiffness = tangential ? params_.friction.k_t : resting;
  found.lightest_mass = mass;
  found.limit = contact::voxel_sum_time_step_limit(params_, radius, mass);
  return found;
}

void VoxelSumWallModel::pack(int i, double* buffer) const {
  contact::pack_spring_store(springs_[i], buffer);
}

bool VoxelSumWallModel::unpack(int i, const double* buffer) {
  return contact::unpack_spring_store(buffer, springs_[i]);
}

}  // namespace lbm_pore
