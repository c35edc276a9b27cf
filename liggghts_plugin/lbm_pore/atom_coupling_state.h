#pragma once
// What fix lbm/pore keeps per atom between fluid steps, as one struct: the substep load
// model's state, the position and velocity the fluid saw at the last fluid step, the
// nearest wall found then, and the tag of the atom the slot belongs to. LIGGGHTS moves
// per-atom data as flat doubles (exchange, restart, communication): pack/unpack are the
// only place the layout of that buffer is known.
#include "coupling/force/substep_load.h"
#include "coupling/lubrication/nearest_wall.h"

namespace lbm_pore {

struct AtomCouplingState {
  coupling::SubstepLoadState load;
  coupling::Vec3 step_position{0.0, 0.0, 0.0};  // at the last fluid step
  bool has_step_position = false;
  coupling::Vec3 fluid_velocity{0.0, 0.0, 0.0};  // the velocity the fluid sees (owned and ghosts)
  double tag = 0.0;                              // the atom the slot belongs to
  coupling::NearestWall wall;                    // found at the last fluid step
  // The mean velocity over the fluid step before the last, (x(t-1) - x(t-2)) / dt: the
  // fluid sees the mean over the last two (fix_lbm_pore.cpp, gather_particles, says why).
  coupling::Vec3 last_step_velocity{0.0, 0.0, 0.0};
  bool has_last_step_velocity = false;

  static constexpr int kDoubles = 36;
  // The layout before last_step_velocity (restart files of the previous version): its
  // first kDoubles1 doubles, the rest defaulted.
  static constexpr int kDoubles1 = 32;
  // The fluid step's force, torque and link coefficient: summed from ghost images.
  static constexpr int kSummed = 7;

  void pack(double* buf) const;
  void unpack(const double* buf, int count = kDoubles);  // count: kDoubles or kDoubles1
  void pack_summed(double* buf) const;
  void add_summed(const double* buf);
};

}  // namespace lbm_pore
