#pragma once
// What fix lbm/pore reads from LIGGGHTS's other objects: the group's pairs of a neighbour
// list and the acceleration of the script's fix gravity.
#include <optional>
#include <vector>

#include "coupling/diagnostics/bonds.h"
#include "coupling/particle_view.h"

namespace LAMMPS_NS {
class Modify;
class NeighList;
}  // namespace LAMMPS_NS

namespace lbm_pore {

// The pairs (i, j) of the list whose atoms are both in the group (mask & groupbit).
std::vector<coupling::ParticlePair> group_pairs(const LAMMPS_NS::NeighList& list, const int* mask, int groupbit);

// The sum of the accelerations of the script's fix gravity instances; none without one.
std::optional<coupling::Vec3> script_gravity(const LAMMPS_NS::Modify& modify);

}  // namespace lbm_pore
