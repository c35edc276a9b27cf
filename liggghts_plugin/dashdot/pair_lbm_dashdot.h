#pragma once
// pair_style lbm/dashdot [kn value] [kc value] [damping value]
// pair_coeff I J [kn value] [kc value] [damping value]
//
// Particle-particle contact of the paper (Jaeger et al., Eqs. 1-3): dash-dot repulsion while
// two spheres overlap and short-range cohesion while their gap is within 0.03 (Ri+Rj). A
// "bond" is a pair within that range: it forms when two particles come that close and breaks
// when they are pulled further apart; the current count is extract("bonds") and
// `compute lbm/bonds`. The force law itself is contact::pair_normal_force (coupling/contact).
//
// Stability guards (doc/stability.md; lbm_pore::ContactGuards, shared with fix wall/voxel):
// the time step against the contact time of the lightest particles, re-checked whenever the
// global atom count changes (insertion); the largest overlap per step (warning above 5 % of
// the smaller radius, stop above 50 %); NaN in a position or a pair force stops the run with
// the atom ID and the step.
#include <vector>

#include "lmptype.h"

#include "contact/pair_contact.h"
#include "pair.h"
#include "plugin_common/contact_guards.h"

namespace LAMMPS_NS {

class PairLbmDashdot : public Pair {
 public:
  explicit PairLbmDashdot(class LAMMPS* lmp);
  ~PairLbmDashdot() override;

  void compute(int eflag, int vflag) override;
  void settings(int narg, char** arg) override;
  void coeff(int narg, char** arg) override;
  void init_style() override;
  double init_one(int i, int j) override;
  void* extract(const char* name, int& dim) override;

  // Bonds counted by the last compute(), this rank's share (pairs with a ghost count half
  // under newton off); compute lbm/bonds sums them over ranks.
  double local_bond_count() const { return bond_count_local_; }

 private:
  void allocate();
  // Parses "kn v kc v damping v" from arg[first..narg) into params; names the keyword on error.
  void parse_coefficients(int first, int narg, char** arg, contact::PairContactParams& params,
                          const char* command);
  void find_max_radius_per_type();
  // Collective: recomputes the limit from the lightest particle present; error->all above it.
  void check_time_step();

  contact::PairContactParams defaults_;
  std::vector<std::vector<contact::PairContactParams>> params_;  // [type][type], 1-based
  std::vector<double> max_radius_;                                // [type]
  double distance_factor_ = 1.0;  // neighbour cutoff = (Ri + Rj) * factor (+ skin)
  double bond_count_local_ = 0.0;
  lbm_pore::ContactGuards guards_;  // t_c / 10 of the lightest particles is extract("dt_max")
  double max_overlap_ratio_ = 0.0;  // largest overlap / smaller radius of the last step, this rank
};

}  // namespace LAMMPS_NS
