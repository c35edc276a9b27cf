#pragma once
// model smooth of fix wall/voxel: the voxels merged into the faces, edges and corners of the
// union of solid cubes (contact::VoxelSurface), one contact per surface feature, so a flat
// voxel wall acts as one flat wall. Each contact keeps its tangential spring per atom, found
// again next step by its normal (the stored normal within 25 degrees).
#include <memory>
#include <vector>

#include "contact/voxel_surface.h"
#include "wall_model.h"

namespace lbm_pore {

class SmoothWallModel : public WallModel {
 public:
  SmoothWallModel(const contact::WallContactParams& params,
                  std::shared_ptr<const lbm::VoxelGeometry> geometry);

  WallModelKind kind() const override { return WallModelKind::kSmooth; }
  int spring_capacity() const override { return kMaxContacts; }
  WallForce apply(int i, const WallParticle& particle) override;
  TimeStepFinding time_step(double mass, double radius) const override;

  void grow(int nmax) override;
  void copy(int from, int to) override;
  int packed_size() const override { return kStride; }
  void pack(int i, double* buffer) const override;
  bool unpack(int i, const double* buffer) override;

  // Contacts remembered per atom (a box corner has 3; staircases of a voxelised curve a few).
  static constexpr int kMaxContacts = 6;
  static constexpr int kHistoryPerContact = 6;  // normal (3), tangential spring (3)
  static constexpr int kStride = kMaxContacts * kHistoryPerContact;

 private:
  contact::WallContactParams params_;
  std::shared_ptr<const lbm::VoxelGeometry> geometry_;
  contact::VoxelSurface surface_;  // search structure over *geometry_
  std::vector<double> history_;    // [atom][kMaxContacts][kHistoryPerContact]
  std::vector<contact::SurfacePoint> points_;  // scratch, reused
  // Per atom slot: the voxels its wall search needs (contact/wall_candidates.h). The lists
  // check themselves against the centre they were built for, so an atom that moved to another
  // slot (sorting, migration) at worst rebuilds them; copy() need not move them.
  std::vector<contact::WallCandidates> candidates_;
};

}  // namespace lbm_pore
