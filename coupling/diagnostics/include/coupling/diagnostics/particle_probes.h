#pragma once
// What the run-time guards look at in the particles: the fastest one (the mapping uncovers
// at most one node layer per fluid step, so a particle may move at most half a cell per
// step) and the one nearest to a node where the fluid became unstable (most blow-ups start
// in a gap next to a particle). Local to a rank: the host reduces.
#include <array>
#include <limits>
#include <string>

#include "coupling/particle_view.h"
#include "coupling/periodic_box.h"

namespace coupling {

// A particle may move at most this many cells per fluid step: the mapping uncovers at most
// one layer of nodes per step, and the refill assumes so (doc/stability.md).
constexpr double kMaxShiftPerFluidStep = 0.5;

struct ParticleProbe {
  int id = -1;         // the particle's identifier, -1 when the view holds none
  double value = 0.0;  // its speed (cells per fluid step), or its surface's distance
};

// The fastest owned particle; a non-finite speed counts as infinite, so NaN stops the run.
ParticleProbe fastest_particle(const ParticleView& view);

// The particle (owned or ghost) whose surface is nearest to `point` (lattice units).
ParticleProbe nearest_particle_surface(const ParticleView& view, const PeriodicBox& box, const Vec3& point);

// The two particles whose surfaces are nearest to `point`, nearest first (id -1 where the view
// holds fewer): a node in the gap between two of them has both within a cell.
std::array<ParticleProbe, 2> nearest_particle_surfaces(const ParticleView& view, const PeriodicBox& box,
                                                       const Vec3& point);

// The end of the message when the fluid became unstable at a node: which particle is
// nearest ("; nearest particle 12, its surface 0.40 cells away") and the likely cause. A gap
// of less than a cell next to a particle points at a clog squeezing the flux (velocity
// drive); otherwise at a drive or particle too fast for the lattice.
std::string instability_cause(const ParticleProbe& nearest);

// The message when a particle moves faster than kMaxShiftPerFluidStep cells per fluid step.
std::string fast_particle_message(const ParticleProbe& fastest, long long dem_step);

}  // namespace coupling
