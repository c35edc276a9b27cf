#pragma once
// What the run-time guards look at in the particles: the fastest one (the mapping uncovers
// at most one node layer per fluid step, so a particle may move at most half a cell per
// step) and the one nearest to a node where the fluid became unstable (most blow-ups start
// in a gap next to a particle). Local to a rank: the host reduces.
#include <limits>

#include "coupling/particle_view.h"
#include "coupling/periodic_box.h"

namespace coupling {

// A particle may move at most this many cells per fluid step: the mapping uncovers at most
// one layer of nodes per step, and the refill assumes so (DESIGN.md, stability guards).
constexpr double kMaxShiftPerFluidStep = 0.5;

struct ParticleProbe {
  int id = -1;         // the particle's identifier, -1 when the view holds none
  double value = 0.0;  // its speed (cells per fluid step), or its surface's distance
};

// The fastest owned particle; a non-finite speed counts as infinite, so NaN stops the run.
ParticleProbe fastest_particle(const ParticleView& view);

// The particle (owned or ghost) whose surface is nearest to `point` (lattice units).
ParticleProbe nearest_particle_surface(const ParticleView& view, const PeriodicBox& box, const Vec3& point);

}  // namespace coupling
