#pragma once
// The two particle-wall models of fix wall/voxel (doc/wall_models.md), behind one interface:
// each owns its per-atom tangential springs (grown, copied, packed and unpacked with the atoms
// by the fix's LIGGGHTS callbacks) and computes one particle's wall force with the shared
// contact law contact::wall_contact_force. The fix parses, loops over its atoms, applies the
// force and runs the stability guards.
//   model smooth    (SmoothWallModel):   the voxels merged into faces, edges and corners,
//                                        one contact per feature (contact/voxel_surface.h);
//   model voxel_sum (VoxelSumWallModel): the paper's sum over every solid voxel in reach
//                                        (Jaeger et al., Eq. 6; contact/voxel_sum_wall.h).
#include <memory>

#include "contact/vec3.h"
#include "contact/wall_contact.h"
#include "lbm/voxel_geometry.h"
#include "plugin_common/contact_guards.h"

namespace lbm_pore {

enum class WallModelKind { kSmooth = 1, kVoxelSum = 2 };  // the codes written to restart files

// "smooth" or "voxel_sum", as the keyword 'model' takes them.
const char* wall_model_name(WallModelKind kind);

// One particle as the fix hands it over (the wall is at rest).
struct WallParticle {
  contact::Vec3 centre, velocity;
  double radius = 0.0, mass = 0.0, dt = 0.0;
};

struct WallForce {
  bool touching = false;           // any wall voxel or feature within reach
  contact::Vec3 force;             // on the particle
  int contacts = 0;                // active (overlapping or adhering)
  double max_overlap_ratio = 0.0;  // largest overlap / R, 0 when none overlaps
  int springs_dropped = 0;         // active contacts that found no room for their spring
};

class WallModel {
 public:
  virtual ~WallModel() = default;
  virtual WallModelKind kind() const = 0;
  // Springs each atom can keep (contacts beyond it act but keep no spring).
  virtual int spring_capacity() const = 0;

  // The force on atom i, whose springs the model reads and replaces.
  virtual WallForce apply(int i, const WallParticle& particle) = 0;

  // The time step check of the lightest particle in the group.
  virtual TimeStepFinding time_step(double mass, double radius) const = 0;

  // Per-atom springs: LIGGGHTS's grow/copy callbacks, and a flat buffer of packed_size()
  // doubles for atom migration and restart files. unpack() returns false (the atom's springs
  // cleared) when the buffer is not a packed set of this model's springs.
  virtual void grow(int nmax) = 0;
  virtual void copy(int from, int to) = 0;
  virtual int packed_size() const = 0;
  virtual void pack(int i, double* buffer) const = 0;
  virtual bool unpack(int i, const double* buffer) = 0;
};

std::unique_ptr<WallModel> make_wall_model(WallModelKind kind,
                                           const contact::WallContactParams& params,
                                           std::shared_ptr<const lbm::VoxelGeometry> geometry);

}  // namespace lbm_pore
