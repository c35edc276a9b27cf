#pragma once
// How a particle moved between fluid steps, as its moving-wall links see it. A host keeps
// one StepMotion per particle and calls step() at every fluid step; the velocity it returns
// is what the fluid sees the particle move with (wall_velocity_of_steps: the mean over the
// last two fluid steps, which says why two).
//
// Why displacements and not the particle's velocity: the mean velocity over a fluid step is
// its displacement over the step's time, (x - x_previous) / dt_fluid, the velocity of the
// mapping's motion. The instantaneous velocity of a particle in a stiff contact oscillates
// within the DEM substeps, and sampling it once per fluid step feeds that noise into the
// fluid.
#include "coupling/boundary/wall_velocity.h"
#include "coupling/particle_view.h"  // Vec3

namespace coupling {

struct StepMotion {
  Vec3 position{0.0, 0.0, 0.0};  // at the last fluid step
  bool has_position = false;
  Vec3 last_velocity{0.0, 0.0, 0.0};  // the mean velocity over the last fluid step
  bool has_last_velocity = false;

  // At a fluid step, for the particle now at x[3] with velocity v[3] (host units): the
  // velocity the fluid sees, and the position is remembered for the next step.
  // minimum_image(double d[3]) wraps a displacement through periodic faces (the host's own
  // rule). Without a displacement, at a run's start (`advance` false: no step has passed) or
  // for a particle with no position yet (just inserted), the fluid sees v.
  template <class MinimumImage>
  Vec3 step(const double* x, const double* v, double dt_fluid, bool advance, MinimumImage&& minimum_image) {
    Vec3 seen{v[0], v[1], v[2]};
    if (advance && has_position) {
      double d[3] = {x[0] - position[0], x[1] - position[1], x[2] - position[2]};
      minimum_image(d);
      const Vec3 mean{d[0] / dt_fluid, d[1] / dt_fluid, d[2] / dt_fluid};
      seen = wall_velocity_of_steps(mean, has_last_velocity ? &last_velocity : nullptr);
      last_velocity = mean;
      has_last_velocity = true;
    }
    position = {x[0], x[1], x[2]};
    has_position = true;
    return seen;
  }
};

}  // namespace coupling
