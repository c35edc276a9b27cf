#pragma once
// Which particles are bonded, the first criterion of a deposit (paper Sec. III): within the
// attraction range of another particle (cohesion, gap <= 0.03 (Ri + Rj), Eq. 3) or of the
// wall (adhesion, gap <= 0.03 R, Eq. 4).
#include <vector>

#include "contact/voxel_surface.h"
#include "coupling/lubrication/nearest_wall.h"
#include "coupling/particle_view.h"

namespace coupling {

// Sets bonded[i] and bonded[j] for every pair of `pairs` within the cohesion range; `view`
// and `bonded` indexed alike, any units.
void mark_cohesive_bonds(const ParticleView& view, const std::vector<ParticlePair>& pairs,
                         std::vector<char>& bonded);

// A particle of radius R whose centre is `distance` from the wall surface adheres to it.
bool within_adhesion_range(double distance, double radius);

// The same from the voxel surface (a search within the adhesion range), for hosts that keep
// no nearest wall.
bool adheres_to_wall(const contact::VoxelSurface& surface, const Vec3& x, double radius,
                     std::vector<contact::SurfacePoint>& scratch);

// Either of the two: from the particle's nearest wall where the host searched it this fluid
// step over at least the adhesion range (`followed`, e.g. for the lubrication), else by a
// search of the voxel surface (`followed` null).
bool touches_wall(const NearestWall* followed, const contact::VoxelSurface& surface, const Vec3& x,
                  double radius, std::vector<contact::SurfacePoint>& scratch);

}  // namespace coupling
