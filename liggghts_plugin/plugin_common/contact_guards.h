#pragma once
// The stability guards of pair_style lbm/dashdot and fix wall/voxel (doc/stability.md), one
// implementation for both: the time step against the contact time t_c, checked at init and
// whenever the global atom count changes (insertion), and the largest overlap of a step
// (a warning once per run, a stop when the bodies pass through each other). The limits are
// physics and live in coupling/contact (contact/stability_limits.h); this class finds the
// lightest particle over the ranks and speaks through LIGGGHTS: error->all, warnings, the
// screen and the log file. Each style passes its own wording, so the messages name its
// keywords.
#include <optional>
#include <string>

#include "contact/stability_limits.h"
#include "lmptype.h"
#include "pointers.h"

namespace lbm_pore {

// How a style names things in its guard messages (fixed for the style).
struct GuardWording {
  const char* style = "";              // "pair_style lbm/dashdot"
  const char* contact = "";            // "contact time", "wall contact time"
  const char* lightest = "";           // "the lightest particles", "the lightest particle"
  const char* overlap_reference = "";  // overlap / R with R "the smaller radius", "its radius"
  const char* passing_through = "";  // "they pass through each other", "it passes through the wall"
  const char* overlap_stiffness = "";  // the keyword to raise: "kn", "kw"
};

// What a time step check found.
struct TimeStepFinding {
  const char* stiffness_name = "";  // the keyword that sets the limit: "kn", "kw", "kt"
  double stiffness = 0.0;
  double lightest_mass = 0.0;
  contact::TimeStepLimit limit;
};

class ContactGuards : protected LAMMPS_NS::Pointers {
 public:
  ContactGuards(LAMMPS_NS::LAMMPS* lmp, const GuardWording& wording)
      : Pointers(lmp), wording_(wording) {}

  // True when the global atom count changed since the last lightest_mass() (particles were
  // inserted or removed). natoms is the same on every rank, so all ranks agree; it costs
  // nothing on other steps.
  bool atom_count_changed() const;

  // Collective: the smallest rmass of the atoms in the group `groupbit` on all ranks; none
  // when there are no such atoms yet. Remembers the atom count for atom_count_changed().
  std::optional<double> lightest_mass(int groupbit);

  // error->all when the timestep is above found.limit.max_time_step (with the n_dem factor
  // to use when fix lbm/pore sets the fluid step); otherwise prints the limit the first time
  // and whenever lighter particles lower it.
  void check_time_step(const TimeStepFinding& found);

  // The last limit, 0 before there were particles. Stays at this address (extract()).
  const double& time_step_limit() const { return time_step_limit_; }

  // The overlap warning comes once per run.
  void start_run() { overlap_warned_ = false; }

  // True when report_overlap() has something to say about this overlap / R: a stop, or the
  // run's first warning. Lets a style describe the overlap only then.
  bool overlap_needs_report(double overlap_ratio) const;

  // Stops the run on this rank (screen and log flushed) when the bodies pass through each
  // other; otherwise warns, once per run. `subject` names the bodies and the verb:
  // "particles 1 and 2 overlap", "particle 3 at (x y z) overlaps the wall".
  void report_overlap(double overlap_ratio, const std::string& subject);

 private:
  GuardWording wording_;
  LAMMPS_NS::bigint checked_natoms_ = -1;  // atom->natoms at the last lightest_mass()
  double time_step_limit_ = 0.0;
  bool overlap_warned_ = false;
};

}  // namespace lbm_pore
