#pragma once
// fix ID group wall/voxel (lbm <fix-ID> | file <path> | pore [pore keywords])
//                         [model smooth|voxel_sum] [kw v] [ka v] [damping v] [mu v] [kt v]
//                         [tangential_damping v]
//
// Particle-wall contact of the paper (Jaeger et al., Eqs. 4-6) against a static voxel
// geometry: dash-dot repulsion, adhesion within 0.03 R, Coulomb friction (tangential springs
// kept per atom). Two models (wall_model.h, doc/wall_models.md): `smooth` (default) merges
// the voxels into faces, edges and corners so a flat voxel wall acts as a flat wall;
// `voxel_sum` is the paper's sum over every solid voxel in reach, each with its own spring.
// Particles do not rotate in the paper's model: the contact uses translational velocities
// and applies no torque. Global vector: [1] active contacts, [2..4] total wall force on the
// group, [5] timestep limit t_c/10 of the lightest particle, [6] largest overlap/R of the last
// step, [7] contacts that found no room for their spring since the fix was defined.
//
// The springs travel with their atoms (exchange) and are written to restart files; a fix of
// the same ID, style and model after read_restart continues with them.
//
// Stability guards (doc/stability.md; lbm_pore::ContactGuards, shared with pair_style
// lbm/dashdot): the time step against the wall contact time of the lightest particle (for
// voxel_sum with the stiffness of a particle resting on 9 voxels), re-checked whenever the
// global atom count changes (insertion); the largest overlap per step (warning above 5 % of
// R, stop above 50 %); NaN in a position or force stops the run with the atom ID and the
// step; a spring store that overflows is warned about once per run, with the count.
#include <memory>
#include <vector>

#include "contact/wall_contact.h"
#include "fix.h"
#include "lbm/voxel_geometry.h"
#include "lmptype.h"
#include "plugin_common/contact_guards.h"
#include "wall_model.h"

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
  // "local_force": this rank's total wall force on the group at the last step (3 doubles,
  // dim 1), for fix lbm/pore's burst records (the wall's hold at a pressure peak) without
  // another reduction; nothing else.
  void* extract(const char* name, int& dim) override;

  // Per-atom tangential springs travel with their atoms and go to restart files
  // (fix_wall_voxel_peratom.cpp).
  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  int pack_exchange(int i, double* buf) override;
  int unpack_exchange(int nlocal, double* buf) override;
  int pack_restart(int i, double* buf) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int nlocal) override;
  int maxsize_restart() override;

  // For a fix that owns the geometry (fix lbm/pore): use it instead of the keywords' one.
  // Builds the wall model on it; springs start from zero.
  void use_geometry(std::shared_ptr<const lbm::VoxelGeometry> geometry);

 private:
  std::shared_ptr<const lbm::VoxelGeometry> geometry_of_lbm_fix(const char* fix_id);
  // Collective: recomputes the limit from the lightest particle in the group; error->all above it.
  void check_time_step();
  void stop_on_non_finite(int i, const char* what);
  void report_dropped_springs(int i, int dropped);

  lbm_pore::WallModelKind model_kind_ = lbm_pore::WallModelKind::kSmooth;
  std::unique_ptr<lbm_pore::WallModel> model_;
  contact::WallContactParams params_;
  double local_stats_[5] = {0, 0, 0, 0, 0};   // contacts, force (3), largest overlap/R
  // The wall's force along x on each local atom at the last post_force (0 off the wall):
  // extract("atom_wall_force_x"), the deposit's own hold for fix lbm/pore's monitor.
  std::vector<double> atom_force_x_;
  double global_stats_[5] = {0, 0, 0, 0, 0};
  double local_springs_dropped_ = 0.0;         // since the fix was defined, this rank
  double global_springs_dropped_ = 0.0;
  bool springs_warned_ = false;                // once per run
  lbm_pore::ContactGuards guards_;  // t_c / 10 of the lightest particle is f_ID[5]
  bool stats_reduced_ = false;
};

}  // namespace LAMMPS_NS
