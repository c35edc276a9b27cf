#pragma once
// What fix lbm/pore reads from LIGGGHTS's other objects: the group's pairs of a neighbour
// list, the acceleration of the script's fix gravity, the wall fixes' forces and the atoms' own.
#include <optional>
#include <vector>

#include "coupling/diagnostics/bonds.h"
#include "coupling/particle_view.h"

namespace LAMMPS_NS {
class Modify;
class NeighList;
}  // namespace LAMMPS_NS

namespace lbm_pore {

class LatticeParticles;

// The pairs (i, j) of the list whose atoms are both in the group (mask & groupbit).
std::vector<coupling::ParticlePair> group_pairs(const LAMMPS_NS::NeighList& list, const int* mask, int groupbit);

// The sum of the accelerations of the script's fix gravity instances; none without one.
std::optional<coupling::Vec3> script_gravity(const LAMMPS_NS::Modify& modify);

// The wall fixes' force along x on this rank's atoms (fix wall/voxel's "local_force"), summed
// into `total`, and per particle p of `particles` (its atom particles.atom(p), the owned
// first) into `per_particle` ("atom_wall_force_x", in the atom order of their post_force of
// this DEM step); `per_particle` stays empty without such a fix.
void wall_forces_along_x(const LAMMPS_NS::Modify& modify, const LatticeParticles& particles, double& total,
                         std::vector<double>& per_particle);

// Every force along x on each owned particle p of `particles` (the atoms' f, read at the
// end of a DEM step: the contact laws', the walls' and the fluid's of that step), into
// `per_particle` (indexed like the particles).
void total_forces_along_x(const double* const* f, const LatticeParticles& particles, std::vector<double>& per_particle);

}  // namespace lbm_pore
