#include "lbm/stability.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "lbm/thread_team.h"
#include "plane_moments.h"

namespace lbm {

std::string FluidStateProblem::describe() const {
  char text[200];
  std::snprintf(text, sizeof text, "node (%d,%d,%d): density %g, speed %g (lattice units)",
                node[0], node[1], node[2], density, speed);
  return text;
}

std::string drive_limit_violation(const FlowDrive& drive) {
  char text[300] = "";
  if (drive.kind == FlowDrive::kInletVelocity) {
    if (std::abs(drive.inlet_velocity) > kMaxLatticeSpeed)
      std::snprintf(text, sizeof text, "%.3g in lattice units, above the stable limit %.2f (lattice Mach %.2f)",
                    drive.inlet_velocity, kMaxLatticeSpeed, drive.inlet_velocity / kSoundSpeed);
  } else if (drive.kind == FlowDrive::kPressureLoss) {
    // p = c_s^2 rho: a lattice pressure difference is a density difference divided by 3.
    if (std::abs(drive.pressure_loss) >= kMaxDensityDifference / 3.0)
      std::snprintf(text, sizeof text,
                    "a lattice density difference of %.3g, at or above the limit %g of the equation of state",
                    3.0 * drive.pressure_loss, kMaxDensityDifference);
  }
  return text;
}

std::string drive_accuracy_warning(const FlowDrive& drive) {
  const double density_difference = 3.0 * drive.pressure_loss;
  if (drive.kind != FlowDrive::kPressureLoss || std::abs(density_difference) <= kWeaklyCompressibleDensityDifference)
    return "";
  char text[400];
  std::snprintf(text, sizeof text,
                "a lattice density difference of %.3g, beyond the weakly compressible %g: the fluid "
                "velocity is up to %.0f %% slower than incompressible flow at the same pressure loss "
                "(the mass flux is right within 0.3 %%; doc/stability.md)",
                density_difference, kWeaklyCompressibleDensityDifference,
                100.0 * compressibility_error_estimate(density_difference));
  return text;
}

double compressibility_error_estimate(double density_difference) {
  const double d = std::abs(density_difference);
  return d / (1.0 + d);
}

namespace {
// visit(cell, i, j, k) for the owned fluid nodes of planes k in [k_first, k_last), in k, j, i
// order, until a visit returns false.
template <class Visit>
void for_owned_fluid(const FluidSolver& s, int k_first, int k_last, Visit visit) {
  const BlockLayout& g = s.layout();
  for (int k = k_first; k < k_last; ++k)
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i) {
        const std::size_t cell = g.cell(i, j, k);
        if (s.node_types()[cell] == kFluid && !visit(cell, i, j, k)) return;
      }
}
template <class Visit>
void for_owned_fluid(const FluidSolver& s, Visit visit) {
  for_owned_fluid(s, 0, s.layout().size(2), visit);
}

// Whether the node is fine, and what the guard reports when it is not: the node's own
// density() and velocity(), as the scan has always read them.
bool node_is_fine(const FluidSolver& solver, std::size_t cell, double max_speed, double& rho,
                  double& speed) {
  rho = solver.density(cell);
  const auto u = solver.velocity(cell);
  speed = std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]);
  return std::isfinite(rho) && rho > 0.0 && std::isfinite(speed) && speed <= max_speed;
}

int wall_links(const FluidSolver& solver, std::size_t cell) {
  const BlockLayout& g = solver.layout();
  int n = 0;
  for (int q = 1; q < D3Q19::Q; ++q)
    n += solver.node_types()[cell + g.offset(D3Q19::c[q][0], D3Q19::c[q][1], D3Q19::c[q][2])] == kSolid;
  return n;
}

// The first bad node of planes [k_first, k_last) in scan order. Each plane's moments come
// from one pass over the 19 arrays (plane_moments, the thermo totals' pass); a node whose
// |u|^2 there lies clearly below the limit is fine (those moments are density()'s and
// velocity()'s bit for bit, and the margin would cover any round-off besides); any other
// node is judged, and reported, from density() and velocity() as before.
FluidStateProblem first_problem(const FluidSolver& solver, double max_speed, int k_first, int k_last) {
  FluidStateProblem problem;
  const BlockLayout& g = solver.layout();
  const std::uint8_t* const type = solver.node_types().data();
  const double clearly_fine2 = 0.99 * max_speed * max_speed;
  for (int k = k_first; k < k_last; ++k) {
    const std::size_t plane = g.cell(0, 0, k);
    const detail::PlaneMoments m = detail::plane_moments(solver, k);
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i) {
        const std::size_t cell = g.cell(i, j, k);
        if (type[cell] != kFluid) continue;
        const std::size_t slot = cell - plane;
        if (std::isfinite(m.rho[slot]) && m.rho[slot] > 0.0 && m.speed2[slot] <= clearly_fine2) continue;
        double rho, speed;
        if (node_is_fine(solver, cell, max_speed, rho, speed)) continue;
        problem.found = true;
        problem.node = g.to_global(i, j, k);
        problem.density = rho;
        problem.speed = speed;
        problem.wall_links = wall_links(solver, cell);
        return problem;
      }
  }
  return problem;
}
}  // namespace

FluidStateProblem check_fluid_state(const FluidSolver& solver, double max_speed) {
  // A scan of the whole lattice: its planes split over the OpenMP threads, each thread's
  // first bad node kept; the lowest planes' is the serial scan's first.
  const int planes = solver.layout().size(2);
#ifdef _OPENMP
  const int threads = std::max(1, std::min(omp_get_max_threads(), planes));
#else
  const int threads = 1;
#endif
  if (threads == 1) return first_problem(solver, max_speed, 0, planes);
  std::vector<FluidStateProblem> found(std::size_t(threads), FluidStateProblem{});
#pragma omp parallel num_threads(threads)
  {
    const auto [t, nt] = lbm::team_member();
    found[std::size_t(t)] = first_problem(solver, max_speed, planes * t / nt, planes * (t + 1) / nt);
  }
  for (const FluidStateProblem& problem : found)
    if (problem.found) return problem;
  return {};
}

FluidStateProblem fastest_node(const FluidSolver& solver) {
  FluidStateProblem fastest;
  fastest.speed = -1.0;
  const BlockLayout& g = solver.layout();
  std::size_t at = 0;
  for_owned_fluid(solver, [&](std::size_t cell, int i, int j, int k) {
    double rho, speed;
    node_is_fine(solver, cell, 0.0, rho, speed);
    if (!(speed > fastest.speed)) return true;
    fastest.found = true;
    fastest.node = g.to_global(i, j, k);
    fastest.density = rho;
    fastest.speed = speed;
    at = cell;
    return true;
  });
  if (fastest.found) fastest.wall_links = wall_links(solver, at);
  else fastest.speed = 0.0;
  return fastest;
}

double max_speed(const FluidSolver& solver) {
  double largest = 0.0;
  for_owned_fluid(solver, [&](std::size_t cell, int, int, int) {
    const auto u = solver.velocity(cell);
    largest = std::max(largest, std::sqrt(u[0] * u[0] + u[1] * u[1] + u[2] * u[2]));
    return true;
  });
  solver.decomposition().comm.max(&largest, 1);
  return largest;
}

}  // namespace lbm
