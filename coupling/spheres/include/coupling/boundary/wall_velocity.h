#pragma once
// The velocity a sphere's moving-wall links see it move with at a fluid step: its mean
// velocity over the last two fluid steps, (x(t) - x(t-2)) / (2 dt), from the means of the
// two steps, (x(t) - x(t-1)) / dt and (x(t-1) - x(t-2)) / dt.
//
// Why two steps: a fluid node in a gap narrower than a cell along a lattice axis (every link
// with a component along it ends on a surface) holds a momentum along that axis that each
// step reverses (bounce-back returns it, and Mei-Luo-Shyy's links alike) and that no
// collision damps. Its alternating push on the two surfaces moves the particles in step
// with it, and with the one-step mean velocity the moving-wall term (2 rho0 u_w a step,
// summed over those links) fed that back and pumped the mode until the fluid guard stopped
// the run: the clogged pore's nodes between deposited particles. The two-step mean has no
// component that alternates every step, so the mode stays at whatever it was born with
// (tests/coupling/test_gap_mode.cpp). Smooth motion sees the velocity half a step later
// than with the one-step mean, an error of order the acceleration times dt.
#include "coupling/particle_view.h"  // Vec3

namespace coupling {

// last: the mean velocity over the step just ended; before: over the step before it, or
// null where the particle has no such step yet (just inserted: then `last`).
inline Vec3 wall_velocity_of_steps(const Vec3& last, const Vec3* before) {
  if (!before) return last;
  return {0.5 * (last[0] + (*before)[0]), 0.5 * (last[1] + (*before)[1]), 0.5 * (last[2] + (*before)[2])};
}

}  // namespace coupling
