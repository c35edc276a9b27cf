#include "liggghts_queries.h"

#include <cstring>

#include "fix.h"
#include "fix_gravity.h"
#include "lattice_particles.h"
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

void wall_forces_along_x(const LAMMPS_NS::Modify& modify, const LatticeParticles& particles, double& total,
                         std::vector<double>& per_particle) {
  for (int f = 0; f < modify.nfix; ++f) {
    int dim = 0;
    const auto* wall = static_cast<const double*>(modify.fix[f]->extract("local_force", dim));
    if (wall && dim == 1) total += wall[0];
    const auto* per_atom = static_cast<const double*>(modify.fix[f]->extract("atom_wall_force_x", dim));
    if (!per_atom || dim != 1) continue;
    per_particle.resize(particles.size(), 0.0);
    for (std::size_t p = 0; p < particles.num_owned(); ++p) per_particle[p] += per_atom[particles.atom(p)];
  }
}

void total_forces_along_x(const double* const* f, const LatticeParticles& particles, std::vector<double>& per_particle) {
  per_particle.assign(particles.size(), 0.0);
  for (std::size_t p = 0; p < particles.num_owned(); ++p) per_particle[p] = f[particles.atom(p)][0];
}

}  // namespace lbm_pore
