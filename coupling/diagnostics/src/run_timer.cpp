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
  char text[1600];
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
  int used = n + m;
  if (halo.steps > 0)
    used += std::snprintf(text + used, sizeof text - used,
                          "fix lbm/pore: halo exchange of the coupled steps: the 5 populations "
                          "crossing each face, and the ghost nodes' moments (for Mei-Luo-Shyy) "
                          "along x, y, z in %lld, %lld, %lld of %lld steps\n",
                          halo.moments[0], halo.moments[1], halo.moments[2], halo.steps);
  const LinkCounts& links = coupling.link_counts();
  const double cells = double(coupling.solver().updated_cells());
  if (links.steps > 0 && links.links > 0 && t.collide_stream > 0.0 && cells > 0.0) {
    // The coupling's cost per link in the unit of the fluid's own work: a link costs as
    // much as this many cell updates of the same run's collide-stream.
    const double per_link = stages / double(links.links);
    const double per_update = t.collide_stream / (double(links.steps) * cells);
    std::snprintf(text + used, sizeof text - used,
                  "fix lbm/pore: links of the moving surfaces on this rank: %.0f per fluid step; "
                  "mapping, refill, moving walls and force %.1f ns per link, %.2f fluid-cell "
                  "updates per link (collide-stream %.2f ns per update of %.0f cells)\n",
                  double(links.links) / double(links.steps), 1e9 * per_link,
                  per_link / per_update, 1e9 * per_update, cells);
  }
  return text;
}

std::string RunTimer::balance_report(const SphereCoupling& coupling, const lbm::Communicator& comm) const {
  const int ranks = comm.size();
  if (ranks <= 1) return "";
  const StageTimes& t = coupling.times();
  const LinkCounts& links = coupling.link_counts();
  const double total = clock_() - start_;
  const double* s = seconds_;
  // This rank's links per fluid step, coupling stages and DEM and the rest.
  double mean[3] = {links.steps > 0 ? double(links.links) / double(links.steps) : 0.0,
                    t.mapping + t.refill + t.moving_walls + t.force,
                    total - s[kFluid] - s[kLubrication] - s[kDiagnostics]};
  double most[3] = {mean[0], mean[1], mean[2]};
  comm.sum(mean, 3);
  comm.max(most, 3);
  if (fluid_steps_ == 0 || mean[0] <= 0.0) return "";
  for (double& m : mean) m /= ranks;
  char text[400];
  std::snprintf(text, sizeof text,
                "fix lbm/pore: balance over %d ranks (mean, busiest rank): links per fluid step "
                "%.0f, %.0f; mapping, refill, moving walls and force %.3f s, %.3f s; DEM and the "
                "rest %.3f s, %.3f s\n",
                ranks, mean[0], most[0], mean[1], most[1], mean[2], most[2]);
  return text;
}

}  // namespace coupling
