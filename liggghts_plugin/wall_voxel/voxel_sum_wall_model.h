#pragma once
// model voxel_sum of fix wall/voxel: the paper's sum over every solid voxel within reach,
// each a static cube with its own contact, adhesion and tangential spring
// (contact::voxel_sum_wall_force, Jaeger et al. Eq. 6). Each atom keeps a
// contact::VoxelSpringStore (64 springs keyed by the voxel's index); migration and restart
// files carry it packed by contact::pack_spring_store. Particles whose voxel box touches no
// solid block (open fluid) skip the voxel scan (contact::SolidBlockMap), and each keeps the
// list of voxels in its reach between steps (contact::WallCandidates).
#include <memory>
#include <vector>

#include "contact/solid_block_map.h"
#include "contact/voxel_sum_wall.h"
#include "wall_model.h"

namespace lbm_pore {

class VoxelSumWallModel : public WallModel {
 public:
  VoxelSumWallModel(const contact::WallContactParams& params,
                    std::shared_ptr<const lbm::VoxelGeometry> geometry);

  WallModelKind kind() const override { return WallModelKind::kVoxelSum; }
  int spring_capacity() const override { return contact::kVoxelSpringCapacity; }
  WallForce apply(int i, const WallParticle& particle) override;
  TimeStepFinding time_step(double mass, double radius) const override;

  void grow(int nmax) override {
    springs_.resize(nmax);
    candidates_.resize(nmax);
  }
  void copy(int from, int to) override { springs_[to] = springs_[from]; }
  int packed_size() const override { return contact::kPackedSpringStoreSize; }
  void pack(int i, double* buffer) const override;
  bool unpack(int i, const double* buffer) override;

 private:
  contact::WallContactParams params_;
  std::shared_ptr<const lbm::VoxelGeometry> geometry_;
  contact::SolidBlockMap blocks_;
  std::vector<contact::VoxelSpringStore> springs_;  // per atom
  // Per atom slot: the voxels its voxel sum needs (contact/wall_candidates.h). The lists check
  // themselves against the centre they were built for, so an atom that moved to another slot
  // (sorting, migration) at worst rebuilds them; copy() need not move them.
  std::vector<contact::WallCandidates> candidates_;
  // Scratch, reused by every apply(): a result holds a 64-slot spring store (2 KiB) that is
  // cheaper kept than made for each particle and step.
  contact::VoxelSumResult result_;
};

}  // namespace lbm_pore
