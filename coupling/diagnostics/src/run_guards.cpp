#include "coupling/diagnostics/run_guards.h"

#include <algorithm>
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

FastFlowSite locate_fastest_flow(const lbm::FluidSolver& solver, const ParticleView& view) {
  const lbm::FluidStateProblem fastest = lbm::fastest_node(solver);
  const lbm::Communicator& comm = solver.decomposition().comm;
  const lbm::Communicator::Location where = comm.max_location(fastest.found ? fastest.speed : -1.0);
  // The rank that holds the node fills the record, the others add zeros.
  double record[9] = {0, 0, 0, 0, 0, 0, 0, 0, 0};
  if (where.rank == comm.rank() && fastest.found) {
    const Vec3 node{double(fastest.node[0]), double(fastest.node[1]), double(fastest.node[2])};
    const auto nearest = nearest_particle_surfaces(view, PeriodicBox::from(solver.decomposition()), node);
    const double values[9] = {node[0], node[1], node[2], fastest.speed, double(fastest.wall_links),
                              double(nearest[0].id), nearest[0].value, double(nearest[1].id), nearest[1].value};
    std::copy(values, values + 9, record);
  }
  comm.sum(record, 9);
  FastFlowSite site;
  for (int a = 0; a < 3; ++a) site.node[std::size_t(a)] = int(record[a]);
  site.speed = record[3];
  site.wall_links = int(record[4]);
  for (int n = 0; n < 2; ++n) site.nearest[std::size_t(n)] = {int(record[5 + 2 * n]), record[6 + 2 * n]};
  return site;
}

std::string fast_flow_warning(double lattice_mach, long long fluid_step, const FastFlowSite& site) {
  if (!(lattice_mach > kAccurateLatticeMach)) return "";
  char where[300];
  int length = std::snprintf(where, sizeof where, "node (%d,%d,%d), speed %.3g", site.node[0],
                             site.node[1], site.node[2], site.speed);
  for (const ParticleProbe& p : site.nearest)
    if (p.id >= 0 && length < int(sizeof where))
      length += std::snprintf(where + length, sizeof where - std::size_t(length),
                              ", %.2f cells from particle %d", p.value, p.id);
  if (length < int(sizeof where))
    std::snprintf(where + length, sizeof where - std::size_t(length), ", %d of its links on the wall",
                  site.wall_links);
  char text[800];
  std::snprintf(text, sizeof text,
                "fix lbm/pore: the lattice Mach number reached %.2f at fluid step %lld, at %s "
                "(above %.1f the lattice's compressibility error passes 10 %%; said once): the flow "
                "there, typically a jet through a gap narrower than a cell, is not resolved "
                "faithfully; a lower inlet velocity (u_lattice) or a finer lattice lowers it",
                lattice_mach, fluid_step, where, kAccurateLatticeMach);
  return text;
}

}  // namespace coupling
