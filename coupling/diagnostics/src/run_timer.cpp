#include "coupling/diagnostics/run_timer.h"

#include <cstdio>

namespace coupling {

void RunTimer::start() {
  *this = RunTimer(clock_);
  start_ = mark_ = clock_();
}

int RunTimer::switch_to(int part) {
  const double now = clock_();
  if (current_ != kRest) seconds_[current_] += now - mark_;
  mark_ = now;
  const int left = current_;
  current_ = part;
  return left;
}

std::string RunTimer::report(const SphereCoupling& coupling) const {
  if (fluid_steps_ == 0) return "";
  const StageTimes& t = coupling.times();
  const HaloCounts& halo = coupling.halo_counts();
  const double total = clock_() - start_;
  const double stages = t.mapping + t.refill + t.moving_walls + t.force;
  const double* s = seconds_;
  char text[1000];
  const int n = std::snprintf(
      text, sizeof text,
      "fix lbm/pore: %lld fluid steps in %.3f s: fluid %.3f s (of which mapping, refill, "
      "moving walls and force %.3f s since the lattice was built), lubrication %.3f s, "
      "diagnostics %.3f s, DEM and the rest %.3f s; %.3g s per fluid step\n",
      fluid_steps_, total, s[kFluid], stages, s[kLubrication], s[kDiagnostics],
      total - s[kFluid] - s[kLubrication] - s[kDiagnostics], total / double(fluid_steps_));
  const int m = std::snprintf(
      text + n, sizeof text - n,
      "fix lbm/pore: coupling stages since the lattice was built: mapping %.3f s, refill "
      "%.3f s, halo %.3f s, static walls %.3f s, moving walls %.3f s, force %.3f s, open "
      "faces %.3f s, collide-stream %.3f s\n",
      t.mapping, t.refill, t.halo, t.static_walls, t.moving_walls, t.force, t.open_boundaries,
      t.collide_stream);
  if (halo.steps > 0)
    std::snprintf(text + n + m, sizeof text - n - m,
                  "fix lbm/pore: halo exchange of the coupled steps: the 5 populations crossing "
                  "each face, and the ghost nodes' moments (for Mei-Luo-Shyy) along x, y, z in "
                  "%lld, %lld, %lld of %lld steps\n",
                  halo.moments[0], halo.moments[1], halo.moments[2], halo.steps);
  return text;
}

}  // namespace coupling
