#pragma once
// Where the wall-clock time of a coupled run went: the fluid steps (with the coupling
// stages), the lubrication, the diagnostics and the rest (the DEM), for the report a host
// prints at the end of a run.
#include <string>

#include "coupling/sphere_coupling.h"

namespace coupling {

class RunTimer {
 public:
  enum Part { kFluid, kLubrication, kDiagnostics, kParts };

  void start(double now);
  void add(Part part, double seconds) { seconds_[part] += seconds; }
  void count_fluid_step() { ++fluid_steps_; }
  long long fluid_steps() const { return fluid_steps_; }

  // Two lines ending in newlines, or "" when no fluid step was run. `stages` are the
  // coupling's stage times since the lattice was built; a third line says how often the
  // coupled steps' halo exchange sent the ghost nodes' moments per axis, where `halo` is
  // given and counted a step.
  std::string report(double now, const StageTimes& stages, const HaloCounts* halo = nullptr) const;

 private:
  double start_ = 0.0;
  double seconds_[kParts] = {0.0, 0.0, 0.0};
  long long fluid_steps_ = 0;
};

}  // namespace coupling
