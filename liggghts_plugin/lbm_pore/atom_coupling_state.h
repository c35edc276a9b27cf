#pragma once
// What fix lbm/pore keeps per atom between fluid steps, as one struct: the substep load
// model's state, the position and velocity the fluid saw at the last fluid step, the
// nearest wall found then, and the tag of the atom the slot belongs to. LIGGGHTS moves
// per-atom data as flat doubles (exchange, restart, communication): pack/unpack are the
// only place the layout of that buffer is known.
#include "coupling/boundary/step_motion.h"
#include "coupling/force/substep_load.h"
#include "coupling/lubrication/nearest_wall.h"

namespace lbm_pore {

struct AtomCouplingState {
  coupling::SubstepLoadState load;
  coupling::StepMotion motion;                   // where it was at the last fluid steps
  coupling::Vec3 fluid_velocity{0.0, 0.0, 0.0};  // the velocity the fluid sees (owned and ghosts)
  double tag = 0.0;                              // the atom the slot belongs to
  coupling::NearestWall wall;                    // found at the last fluid step

  static constexpr int kDoubles = 36;
  // The layout before motion.last_velocity (restart files of the previous version): its
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
