#pragma once
// The run-time guards a host runs at its fluid steps, collective over the solver's ranks: a
// particle faster than the lattice can follow, and a fluid node that is not finite or runs
// away. A verdict is the same on every rank (stop or go on); the rank that found the problem
// also holds the message, so the host can let that rank write it before every rank stops
// (one message, from where the problem is, instead of a hang or one message per rank).
#include <array>
#include <string>

#include "coupling/diagnostics/particle_probes.h"
#include "coupling/particle_view.h"
#include "lbm/communicator.h"
#include "lbm/fluid_solver.h"

namespace coupling {

struct GuardVerdict {
  bool stop = false;        // alike on every rank
  bool found_here = false;  // this rank found the problem and holds the message
  std::string message;      // what, where and the likely cause (the host adds its name)
  double value = 0.0;       // the particle guard's largest shift over the ranks (cells per step)
};

// The fastest owned particle of every rank's view (lattice units, the view of the fluid step)
// against kMaxShiftPerFluidStep (particle_probes.h).
GuardVerdict particle_speed_guard(const ParticleView& view, long long dem_step, const lbm::Communicator& comm);

// A fluid faster than this (lattice units) has run away: far above what a drive may ask
// (lbm::kMaxLatticeSpeed) and close to the speed of sound, 0.577, where the scheme fails.
constexpr double kRunawayFluidSpeed = 0.5;

// A node of any rank that is not finite, has a non-positive density or a speed above
// kRunawayFluidSpeed (lbm::check_fluid_state); the message names the DEM and fluid steps,
// the node, the particle of `view` nearest to it and the likely cause.
GuardVerdict fluid_state_guard(const lbm::FluidSolver& solver, const ParticleView& view, long long dem_step,
                               long long fluid_step);

// Above this lattice Mach number the scheme's compressibility error (of the order of Ma^2)
// passes 10 %: the flow is still computed, but not faithfully. Jets through the gaps of a
// clogged pore reach it between the fluid guard's checks (doc/calibration.md).
constexpr double kAccurateLatticeMach = 0.3;

// Where the fastest flow of all ranks is: its node (global lattice indices), speed, how many
// of its 18 directions end on the static wall, and the two particle surfaces nearest to it
// (cells; id -1 where there are fewer). Alike on every rank (collective).
struct FastFlowSite {
  std::array<int, 3> node{0, 0, 0};
  double speed = 0.0;
  int wall_links = 0;
  std::array<ParticleProbe, 2> nearest;
};
FastFlowSite locate_fastest_flow(const lbm::FluidSolver& solver, const ParticleView& view);

// A warning, or "" at or below kAccurateLatticeMach: the largest lattice Mach number seen
// (f_pore[10]), the fluid step and where (`site`: a node in a gap narrower than a cell has a
// surface on either side within a cell), what it means and what lowers it. The host says it
// once, the first time.
std::string fast_flow_warning(double lattice_mach, long long fluid_step, const FastFlowSite& site);

}  // namespace coupling
