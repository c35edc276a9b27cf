#include "coupling/diagnostics/run_guards.h"

#include <cstdio>

#include "coupling/diagnostics/particle_probes.h"
#include "coupling/periodic_box.h"
#include "lbm/stability.h"

namespace coupling {

GuardVerdict particle_speed_guard(const ParticleView& view, long long dem_step, const lbm::Communicator& comm) {
  const ParticleProbe fastest = fastest_particle(view);
  const lbm::Communicator::Location global = comm.max_location(fastest.value);
  GuardVerdict verdict;
  verdict.value = global.value;
  verdict.stop = global.value > kMaxShiftPerFluidStep;
  verdict.found_here = verdict.stop && global.rank == comm.rank();
  if (verdict.found_here) verdict.message = fast_particle_message(fastest, dem_step);
  return verdict;
}

GuardVerdict fluid_state_guard(const lbm::FluidSolver& solver, const ParticleView& view, long long dem_step,
                               long long fluid_step) {
  const lbm::FluidStateProblem problem = lbm::check_fluid_state(solver, kRunawayFluidSpeed);
  double any = problem.found ? 1.0 : 0.0;
  solver.decomposition().comm.max(&any, 1);
  GuardVerdict verdict;
  verdict.stop = any > 0.0;
  verdict.found_here = problem.found;
  if (!problem.found) return verdict;
  const Vec3 node{double(problem.node[0]), double(problem.node[1]), double(problem.node[2])};
  const ParticleProbe nearest = nearest_particle_surface(view, PeriodicBox::from(solver.decomposition()), node);
  verdict.message = "fluid became unstable at DEM step " + std::to_string(dem_step) + " (fluid step " +
                    std::to_string(fluid_step) + "), " + problem.describe() + instability_cause(nearest);
  return verdict;
}

std::string fast_flow_warning(double lattice_mach, long long fluid_step) {
  if (!(lattice_mach > kAccurateLatticeMach)) return "";
  char text[400];
  std::snprintf(text, sizeof text,
                "fix lbm/pore: the lattice Mach number reached %.2f at fluid step %lld (above %.1f "
                "the lattice's compressibility error passes 10 %%; said once): the flow "
                "there, typically a jet through the gaps of a clogged pore, is not resolved "
                "faithfully; a lower inlet velocity (u_lattice) or a finer lattice lowers it",
                lattice_mach, fluid_step, kAccurateLatticeMach);
  return text;
}

}  // namespace coupling
