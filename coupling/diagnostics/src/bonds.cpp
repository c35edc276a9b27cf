#include "coupling/diagnostics/bonds.h"

#include <cmath>

#include "contact/short_range_attraction.h"

namespace coupling {

void mark_cohesive_bonds(const ParticleView& view, const std::vector<ParticlePair>& pairs,
                         std::vector<char>& bonded) {
  for (const ParticlePair& pair : pairs) {
    const Vec3 xi = view.x(pair.i), xj = view.x(pair.j);
    const double d[3] = {xj[0] - xi[0], xj[1] - xi[1], xj[2] - xi[2]};
    const double Ri = view.r(pair.i), Rj = view.r(pair.j);
    const double gap = std::sqrt(d[0] * d[0] + d[1] * d[1] + d[2] * d[2]) - Ri - Rj;
    if (gap <= contact::kAttractionRangeFactor * (Ri + Rj)) {
      bonded[pair.i] = 1;
      bonded[pair.j] = 1;
    }
  }
}

namespace {
// Centre-to-surface distance within which a particle of radius R adheres (Eq. 4's range).
double adhesion_reach(double radius) { return radius * (1.0 + contact::kAttractionRangeFactor); }
}  // namespace

bool within_adhesion_range(double distance, double radius) { return distance <= adhesion_reach(radius); }

bool adheres_to_wall(const contact::VoxelSurface& surface, const Vec3& x, double radius,
                     std::vector<contact::SurfacePoint>& scratch) {
  surface.find({x[0], x[1], x[2]}, adhesion_reach(radius), scratch);
  return !scratch.empty();
}

bool touches_wall(const NearestWall* followed, const contact::VoxelSurface& surface, const Vec3& x,
                  double radius, std::vector<contact::SurfacePoint>& scratch) {
  if (followed) return followed->known && within_adhesion_range(followed->distance, radius);
  return adheres_to_wall(surface, x, radius, scratch);
}

}  // namespace coupling
