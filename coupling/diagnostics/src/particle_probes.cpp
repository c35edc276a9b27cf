#include "coupling/diagnostics/particle_probes.h"

#include <cmath>
#include <cstdio>

#include "lbm/stability.h"

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

std::array<ParticleProbe, 2> nearest_particle_surfaces(const ParticleView& view, const PeriodicBox& box,
                                                       const Vec3& point) {
  std::array<ParticleProbe, 2> nearest;
  for (ParticleProbe& probe : nearest) probe.value = std::numeric_limits<double>::infinity();
  for (std::size_t p = 0; p < view.num_total; ++p) {
    const Vec3 d = box.displacement(view.x(p), point);
    const double gap = std::sqrt(dot(d, d)) - view.r(p);
    const ParticleProbe probe{view.identifier(p), gap};
    if (gap < nearest[0].value) {
      nearest[1] = nearest[0];
      nearest[0] = probe;
    } else if (gap < nearest[1].value) {
      nearest[1] = probe;
    }
  }
  return nearest;
}

ParticleProbe nearest_particle_surface(const ParticleView& view, const PeriodicBox& box, const Vec3& point) {
  return nearest_particle_surfaces(view, box, point)[0];
}

std::string instability_cause(const ParticleProbe& nearest) {
  char near[200] = "";
  if (nearest.id >= 0)
    std::snprintf(near, sizeof near, "; nearest particle %d, its surface %.2f cells away", nearest.id, nearest.value);
  char cause[400];
  if (nearest.value < 1.0)
    std::snprintf(cause, sizeof cause,
                  "the flow is squeezed through a gap of less than a cell next to a particle: "
                  "with 'velocity' the inlet flux must pass however tightly the pore clogs. "
                  "Lower 'velocity' (gap speeds scale with it), drive by 'pressure_loss' "
                  "(bounded gap speeds), or refine dx");
  else
    std::snprintf(cause, sizeof cause,
                  "the drive or a particle is too fast for the lattice (keep speeds below "
                  "%.2f in lattice units: lower 'velocity' or 'pressure_loss', refine dx or "
                  "lower n_dem) or tau too close to 0.5",
                  lbm::kMaxLatticeSpeed);
  return std::string(near) + ". Likely cause: " + cause;
}

std::string fast_particle_message(const ParticleProbe& fastest, long long dem_step) {
  char text[600];
  std::snprintf(text, sizeof text,
                "particle %d moves %.3g cells per fluid step at DEM step %lld (limit %.2f): "
                "the fluid cannot follow it. Likely cause: a contact too stiff for the DEM step, or "
                "n_dem too large for this speed; lower n_dem or the time step",
                fastest.id, fastest.value, dem_step, kMaxShiftPerFluidStep);
  return text;
}

}  // namespace coupling
