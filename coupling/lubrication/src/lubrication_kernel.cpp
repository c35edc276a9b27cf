#include "coupling/lubrication/lubrication_kernel.h"

#include <algorithm>
#include <cmath>

namespace coupling {

LubricationKernel::LubricationKernel(const LubricationParameters& lattice_parameters,
                                     const LubricationScales& scales)
    : law_(lattice_parameters), scales_(scales), cutoff_(lattice_parameters.cutoff * scales.dx) {}

Vec3 LubricationKernel::to_lattice_velocity(const Vec3& v) const {
  const double scale = scales_.dt_fluid / scales_.dx;
  return {v[0] * scale, v[1] * scale, v[2] * scale};
}

void LubricationKernel::add_pair_forces(const ParticleView& view, const std::vector<ParticlePair>& pairs,
                                        double* force) const {
  const double dx = scales_.dx;
  for (const ParticlePair& pair : pairs) {
    const Vec3 xi = view.x(pair.i), xj = view.x(pair.j);
    const Vec3 d{(xj[0] - xi[0]) / dx, (xj[1] - xi[1]) / dx, (xj[2] - xi[2]) / dx};
    const double dist = std::sqrt(dot(d, d));  // in cells
    const double gap = dist * dx - view.r(pair.i) - view.r(pair.j);
    if (gap >= cutoff_) continue;
    const Vec3 F = law_.pair_force(view.r(pair.i) / dx, view.r(pair.j) / dx, d, dist,
                                   to_lattice_velocity(view.v(pair.i)), to_lattice_velocity(view.v(pair.j)));
    for (int a = 0; a < 3; ++a) force[3 * pair.i + a] += F[a] * scales_.force_unit;
    if (view.is_owned(std::size_t(pair.j)))
      for (int a = 0; a < 3; ++a) force[3 * pair.j + a] -= F[a] * scales_.force_unit;
  }
}

void LubricationKernel::add_wall_force(const NearestWall& nearest, const Vec3& x, const Vec3& v,
                                       double radius, double* force) const {
  const double distance = nearest.distance_from(x);
  if (distance - radius >= cutoff_) return;
  WallDistance wall;
  wall.distance = std::max(distance, 0.0) / scales_.dx;
  wall.normal = nearest.normal;
  const Vec3 F = law_.wall_force(radius / scales_.dx, to_lattice_velocity(v), wall);
  for (int a = 0; a < 3; ++a) force[a] += F[a] * scales_.force_unit;
}

}  // namespace coupling
