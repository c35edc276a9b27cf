#include "liggghts_queries.h"

#include <cstring>

#include "fix_gravity.h"
#include "modify.h"
#include "neigh_list.h"
#include "neighbor.h"

namespace lbm_pore {

std::vector<coupling::ParticlePair> group_pairs(const LAMMPS_NS::NeighList& list, const int* mask, int groupbit) {
  std::vector<coupling::ParticlePair> pairs;
  for (int ii = 0; ii < list.inum; ++ii) {
    const int i = list.ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    for (int jj = 0; jj < list.numneigh[i]; ++jj) {
      const int j = list.firstneigh[i][jj] & NEIGHMASK;
      if (mask[j] & groupbit) pairs.push_back({i, j});
    }
  }
  return pairs;
}

std::optional<coupling::Vec3> script_gravity(const LAMMPS_NS::Modify& modify) {
  std::optional<coupling::Vec3> gravity;
  for (int i = 0; i < modify.nfix; ++i) {
    if (std::strcmp(modify.fix[i]->style, "gravity") != 0) continue;
    double g[3];
    static_cast<LAMMPS_NS::FixGravity*>(modify.fix[i])->get_gravity(g);
    if (!gravity) gravity = coupling::Vec3{0.0, 0.0, 0.0};
    for (int a = 0; a < 3; ++a) (*gravity)[a] += g[a];
  }
  return gravity;
}

}  // namespace lbm_pore
