#pragma once
// Where the wall-clock time of a coupled run went, for the report a host prints at the end
// of a run: the fluid steps, the lubrication, the diagnostics and the rest (the DEM), and
// within the fluid steps the coupling's own stages (SphereCoupling::times). One clock for
// all of them (coupling/stage_clock.h): the host opens a Scope around each part and the
// report reads the coupling's stage times itself, so a host keeps no clock of its own.
#include <string>

#include "coupling/sphere_coupling.h"
#include "coupling/stage_clock.h"
#include "lbm/communicator.h"

namespace coupling {

class RunTimer {
 public:
  enum Part { kFluid, kLubrication, kDiagnostics, kParts };
  using Clock = double (*)();  // seconds; a test passes its own

  explicit RunTimer(Clock clock = clock_seconds) : clock_(clock) {}

  // Charges the seconds from its construction to its end to one part. Scopes nest: time in
  // an inner scope goes to the inner part only (the walls a fluid step searches for the
  // lubrication are lubrication time, not fluid time); time outside every scope is the rest.
  class Scope {
   public:
    Scope(RunTimer& timer, Part part) : timer_(timer), outer_(timer.switch_to(part)) {}
    ~Scope() { timer_.switch_to(outer_); }
    Scope(const Scope&) = delete;
    Scope& operator=(const Scope&) = delete;

   private:
    RunTimer& timer_;
    int outer_;
  };

  // A run starts: the times and fluid steps of the last one are forgotten.
  void start();
  void count_fluid_step() { ++fluid_steps_; }
  long long fluid_steps() const { return fluid_steps_; }
  double seconds(Part part) const { return seconds_[part]; }

  // Two lines ending in newlines, or "" when no fluid step was run: the run's parts with
  // the seconds per fluid step, and the coupling's stage times since the lattice was built;
  // a third line says how often the coupled steps' halo exchange sent the ghost nodes'
  // moments per axis, once a step was counted there; a fourth, once links were applied,
  // gives the links per step and the coupling stages' cost per link, in ns and in
  // fluid-cell updates of the same run's collide-stream (this rank's figures).
  std::string report(const SphereCoupling& coupling) const;
  // On more than one rank, once links were applied: one line comparing the ranks, the mean
  // and the busiest rank's links per fluid step, coupling stages (mapping, refill, moving
  // walls and force) and DEM and the rest. A stage's time on one rank includes its waits for
  // the others at the step's collective calls, so the stage figures of report() alone do
  // not show which rank holds the work. Collective over `comm` (every rank calls it; all get
  // the line); "" on one rank.
  std::string balance_report(const SphereCoupling& coupling, const lbm::Communicator& comm) const;

 private:
  static constexpr int kRest = -1;  // outside every scope
  int switch_to(int part);          // returns the part it leaves

  Clock clock_;
  double start_ = 0.0;
  double mark_ = 0.0;  // when the current part began
  int current_ = kRest;
  double seconds_[kParts] = {0.0, 0.0, 0.0};
  long long fluid_steps_ = 0;
};

}  // namespace coupling
