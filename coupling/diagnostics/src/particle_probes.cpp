#include "coupling/diagnostics/particle_probes.h"

#include <cmath>

namespace coupling {

ParticleProbe fastest_particle(const ParticleView& view) {
  ParticleProbe fastest;
  for (std::size_t p = 0; p < view.num_owned; ++p) {
    const Vec3 u = view.v(p);
    double speed = std::sqrt(dot(u, u));
    if (!std::isfinite(speed)) speed = std::numeric_limits<double>::infinity();
    if (speed > fastest.value) {
      fastest.value = speed;
      fastest.id = view.identifier(p);
    }
  }
  return fastest;
}

ParticleProbe nearest_particle_surface(const ParticleView& view, const PeriodicBox& box, const Vec3& point) {
  ParticleProbe nearest;
  nearest.value = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < view.num_total; ++p) {
    const Vec3 d = box.displacement(view.x(p), point);
    const double gap = std::sqrt(dot(d, d)) - view.r(p);
    if (gap < nearest.value) {
      nearest.value = gap;
      nearest.id = view.identifier(p);
    }
  }
  return nearest;
}

}  // namespace coupling
