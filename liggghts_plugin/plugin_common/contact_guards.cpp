#include "plugin_common/contact_guards.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "modify.h"
#include "plugin_common/stop_run.h"
#include "update.h"

namespace lbm_pore {

namespace {
constexpr double kNoMass = 1e300;
}  // namespace

bool ContactGuards::atom_count_changed() const { return atom->natoms != checked_natoms_; }

std::optional<double> ContactGuards::lightest_mass(int groupbit) {
  checked_natoms_ = atom->natoms;
  double local_min_mass = kNoMass;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit) local_min_mass = std::min(local_min_mass, atom->rmass[i]);
  double min_mass = 0.0;
  MPI_Allreduce(&local_min_mass, &min_mass, 1, MPI_DOUBLE, MPI_MIN, world);
  if (min_mass >= kNoMass) return std::nullopt;
  return min_mass;
}

void ContactGuards::check_time_step(const TimeStepFinding& found) {
  const double dt_max = found.limit.max_time_step;
  const bool first = time_step_limit_ == 0.0;
  const bool dropped = dt_max < time_step_limit_ * (1.0 - 1e-9);
  time_step_limit_ = dt_max;
  if (update->dt > dt_max) {
    // With a fluid, n_dem * dt sets tau: keep it, take more DEM steps per fluid step.
    const int factor = static_cast<int>(std::ceil(update->dt / dt_max));
    char fluid_advice[200] = "";
    if (modify->find_fix_style("lbm/pore", 0))
      std::snprintf(fluid_advice, sizeof fluid_advice,
                    "; with fix lbm/pore, multiply n_dem by %d and divide the timestep by %d "
                    "(the fluid step stays the same)",
                    factor, factor);
    char message[700];
    std::snprintf(message, sizeof message,
                  "%s: timestep %g is too large for %s = %g at step " BIGINT_FORMAT
                  ": the %s of %s (mass %g) is t_c = %g, and a contact needs at least %g steps "
                  "(timestep <= t_c/%g); use timestep <= %g or a smaller %s%s",
                  wording_.style, update->dt, found.stiffness_name, found.stiffness,
                  update->ntimestep, wording_.contact, wording_.lightest, found.lightest_mass,
                  found.limit.contact_time, contact::kMinStepsPerContact,
                  contact::kMinStepsPerContact, dt_max, found.stiffness_name, fluid_advice);
    error->all(FLERR, message);
  }
  if (comm->me == 0 && (first || dropped)) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "%s: %s t_c = %g of %s (mass %g, %s = %g); timestep limit t_c/%g = %g "
                  "(timestep %g)\n",
                  wording_.style, wording_.contact, found.limit.contact_time, wording_.lightest,
                  found.lightest_mass, found.stiffness_name, found.stiffness,
                  contact::kMinStepsPerContact, dt_max, update->dt);
    print_to_screen_and_log(screen, logfile, text);
  }
}

bool ContactGuards::overlap_needs_report(double overlap_ratio) const {
  switch (contact::overlap_severity(overlap_ratio)) {
    case contact::OverlapSeverity::kPassingThrough:
      return true;
    case contact::OverlapSeverity::kTooSoft:
      return !overlap_warned_;
    case contact::OverlapSeverity::kResolved:
      return false;
  }
  return false;
}

// A contact law resolves overlaps of a few percent of the radius; beyond that the stiffness
// is too soft for the forces of the scene, and at half the radius the bodies pass through
// each other.
void ContactGuards::report_overlap(double overlap_ratio, const std::string& subject) {
  const bool stop =
      contact::overlap_severity(overlap_ratio) == contact::OverlapSeverity::kPassingThrough;
  if (!stop && overlap_warned_) return;
  const std::string keyword = wording_.overlap_stiffness;
  char figures[200];
  std::snprintf(figures, sizeof figures, stop ? " by %.0f %% of " : " by %.1f %% of ",
                100.0 * overlap_ratio);
  std::string text = std::string(wording_.style) + ": " + subject + figures +
                     wording_.overlap_reference + " at step " + std::to_string(update->ntimestep);
  if (stop) {
    std::snprintf(figures, sizeof figures,
                  " (limit %.0f %%): ", 100.0 * contact::kStopOverlapRatio);
    text += figures + std::string(wording_.passing_through) + ". " + keyword +
            " is far too soft for the forces in this scene, or the timestep too large: raise " +
            keyword + " (the timestep limit t_c/10 shrinks with it), lower the drive";
    stop_on_this_rank(error, comm->me, screen, logfile, text.c_str());
  }
  overlap_warned_ = true;
  std::snprintf(figures, sizeof figures,
                " (warning above %.0f %%, once per run): ", 100.0 * contact::kWarnOverlapRatio);
  text += figures + keyword + " is too soft for the forces in this scene; raise " + keyword +
          " (the timestep limit t_c/10 shrinks with it)";
  if (screen)
    error->warning(FLERR, text.c_str());
  else
    std::fprintf(stderr, "WARNING on proc %d: %s\n", comm->me, text.c_str());
}

}  // namespace lbm_pore
