#pragma once
// pair_style lbm/dashdot [kn value] [kc value] [damping value]
// pair_coeff I J [kn value] [kc value] [damping value]
//
// Particle-particle contact of the paper (Jaeger et al., Eqs. 1-3): dash-dot repulsion while
// two spheres overlap and short-range cohesion while their gap is within 0.03 (Ri+Rj). A
// "bond" is a pair within that range: it forms when two particles come that close and breaks
// when they are pulled further apart; the current count is extract("bonds") and
// `compute lbm/bonds`. The force law itself is contact::pair_normal_force (coupling/contact).
#include <vector>

#include "contact/pair_contact.h"
#include "pair.h"

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
  void check_time_step();

  contact::PairContactParams defaults_;
  std::vector<std::vector<contact::PairContactParams>> params_;  // [type][type], 1-based
  std::vector<double> max_radius_;                                // [type]
  double distance_factor_ = 1.0;  // neighbour cutoff = (Ri + Rj) * factor (+ skin)
  double bond_count_local_ = 0.0;
};

}  // namespace LAMMPS_NS
