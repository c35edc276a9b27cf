#pragma once
// fix ID group wall/voxel (lbm <fix-ID> | file <path> | pore [pore keywords]) [kw v] [ka v] [damping v]
//                          [mu v] [kt v] [tangential_damping v]
//
// Particle-wall contact of the paper (Jaeger et al., Eqs. 4-6) against a static voxel
// geometry: dash-dot repulsion, adhesion within 0.03 R, Coulomb friction (tangential spring,
// kept per contact in per-atom history). The voxels are merged into faces, edges and corners
// (contact::find_surface_points) so a flat voxel wall acts as a flat wall. Particles do not
// rotate in the paper's model: the contact uses translational velocities and applies no
// torque. Global vector: [1] active contacts, [2..4] total wall force on the group,
// [5] timestep limit t_c/10 of the lightest particle, [6] largest overlap/R of the last step.
//
// Stability guards (doc/stability.md; lbm_pore::ContactGuards, shared with pair_style
// lbm/dashdot): the time step against the wall contact time of the lightest particle, re-checked whenever the global atom count changes (insertion); the
// largest overlap per step (warning above 5 % of R, stop above 50 %); NaN in a position or
// force stops the run with the atom ID and the step.
#include <memory>
#include <vector>

#include "contact/voxel_surface.h"
#include "contact/wall_contact.h"
#include "fix.h"
#include "lbm/voxel_geometry.h"
#include "lmptype.h"
#include "plugin_common/contact_guards.h"

namespace LAMMPS_NS {

class FixWallVoxel : public Fix {
 public:
  FixWallVoxel(class LAMMPS* lmp, int narg, char** arg);
  ~FixWallVoxel() override;

  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void post_force(int vflag) override;
  double compute_vector(int index) override;

  // Per-atom tangential springs travel with their atoms.
  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  int pack_exchange(int i, double* buf) override;
  int unpack_exchange(int nlocal, double* buf) override;

  // For a fix that owns the geometry (fix lbm/pore): use it instead of the keywords' one.
  void use_geometry(std::shared_ptr<const lbm::VoxelGeometry> geometry);

  // Contacts remembered per atom (a box corner has 3; staircases of a voxelised curve a few).
  static constexpr int kMaxContacts = 6;
  static constexpr int kHistoryPerContact = 6;  // normal (3), tangential spring (3)

 private:
  std::shared_ptr<const lbm::VoxelGeometry> geometry_of_lbm_fix(const char* fix_id);
  // Collective: recomputes the limit from the lightest particle in the group; error->all above it.
  void check_time_step();
  void stop_on_non_finite(int i, const char* what);

  std::shared_ptr<const lbm::VoxelGeometry> geometry_;
  std::unique_ptr<contact::VoxelSurface> surface_;  // search structure over *geometry_
  contact::WallContactParams params_;
  std::vector<double> history_;  // [atom][kMaxContacts][kHistoryPerContact]
  std::vector<contact::SurfacePoint> points_;  // scratch, reused
  double local_stats_[5] = {0, 0, 0, 0, 0};   // contacts, force (3), largest overlap/R
  double global_stats_[5] = {0, 0, 0, 0, 0};
  lbm_pore::ContactGuards guards_;  // t_c / 10 of the lightest particle is f_ID[5]
  bool stats_reduced_ = false;
};

}  // namespace LAMMPS_NS
