#pragma once
// compute ID group lbm/bonds
// Global scalar: the number of particle pairs currently bonded by pair_style lbm/dashdot
// (overlapping or within the cohesion range 0.03 (Ri+Rj)), summed over all ranks. Usable in
// thermo_style custom as c_ID. The group is ignored (all pairs of the pair style count).
#include "compute.h"

namespace LAMMPS_NS {

class ComputeLbmBonds : public Compute {
 public:
  ComputeLbmBonds(class LAMMPS* lmp, int& iarg, int narg, char** arg);
  void init() override;
  double compute_scalar() override;

 private:
  class PairLbmDashdot* pair_ = nullptr;
};

}  // namespace LAMMPS_NS
