#include "lbm/macroscopic.h"

#include <algorithm>
#include <cmath>
#include <utility>
#include <vector>

#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "plane_moments.h"
#include "plane_nodes.h"

namespace lbm {

MacroscopicFields compute_fields(const FluidSolver& solver) {
  const BlockLayout& g = solver.layout();
  const std::size_t count = std::size_t(g.size(0)) * g.size(1) * g.size(2);
  MacroscopicFields out;
  out.density.assign(count, solver.parameters().rho0);
  out.velocity.assign(3 * count, 0.0);
  out.node_type.assign(count, kSolid);
  std::size_t n = 0;
  for (int k = 0; k < g.size(2); ++k)
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i, ++n) {
        const std::size_t cell = g.cell(i, j, k);
        out.node_type[n] = solver.node_types()[cell];
        if (out.node_type[n] != kFluid) continue;
        out.density[n] = solver.density(cell);
        const auto u = solver.velocity(cell);
        for (int a = 0; a < 3; ++a) out.velocity[3 * n + a] = u[a];
      }
  return out;
}

namespace {
// j += c v for a velocity component c in {-1, 0, 1} known at compile time: the terms with
// c = 0 are left out and c = -1 subtracts. Exactly the sum of the terms c v (each exact) in
// q order, as a loop over all 19 would give it (which also multiplies by the zeros and
// converts c to double), in a third of the instructions.
template <int c>
void add_component(double& j, double v) {
  if constexpr (c == 1) j += v;
  if constexpr (c == -1) j -= v;
}

template <std::size_t... q>
NodeMoments moments_of(const PopulationField& f, std::size_t cell,
                       const std::array<double, 3>& body_force, std::index_sequence<q...>) {
  using L = D3Q19;
  const double v[L::Q] = {double(f.at(int(q), cell))...};
  NodeMoments m;
  double j[3] = {0.0, 0.0, 0.0};
  ((m.rho += v[q]), ...);  // folds over the comma operator run in q order
  (add_component<L::c[q][0]>(j[0], v[q]), ...);
  (add_component<L::c[q][1]>(j[1], v[q]), ...);
  (add_component<L::c[q][2]>(j[2], v[q]), ...);
  for (int a = 0; a < 3; ++a) m.u[a] = (j[a] - 0.5 * body_force[a]) / m.rho;
  return m;
}
}  // namespace

NodeMoments node_moments(const PopulationField& f, std::size_t cell,
                         const std::array<double, 3>& body_force) {
  return moments_of(f, cell, body_force, std::make_index_sequence<D3Q19::Q>{});
}

namespace {
// Visits the owned fluid nodes of global plane `index` normal to `axis`, asking ahead for
// the populations of the nodes to come (plane_nodes.h).
template <class Visit>
void for_plane(const FluidSolver& solver, int axis, int index, Visit visit) {
  const BlockLayout& g = solver.layout();
  const int local = index - g.owned().lo[axis];
  if (local < 0 || local >= g.size(axis)) return;
  const PopulationField& f = solver.populations();
  detail::for_plane_fluid_nodes(g, solver.node_types(), axis, local, visit,
                                [&](std::size_t ahead) { detail::prefetch_node(f, ahead); });
}
}  // namespace

double plane_flux(const FluidSolver& solver, int axis, int index) {
  double flux = 0.0;
  // The momentum, rho u (or rho0 u with the incompressible equilibrium), over rho0.
  const bool incompressible = solver.parameters().incompressible;
  for_plane(solver, axis, index, [&](std::size_t cell) {
    const double rho = incompressible ? solver.parameters().rho0 : solver.density(cell);
    flux += rho * solver.velocity(cell)[axis];
  });
  return solver.decomposition().comm.sum(flux) / solver.parameters().rho0;
}

namespace {
// This rank's density sum and fluid node count on global plane `index` normal to `axis`. It
// runs every fluid step (pressure_loss), and on an x-normal plane each node's density reads
// 19 lines: the densities are computed over the OpenMP threads, each into the node's slot of
// a buffer of the plane's size, then summed on one thread in the plane's order, so the sum
// is the same for any number of threads.
void add_plane_density(const FluidSolver& solver, int axis, int index, double* sums) {
  const BlockLayout& g = solver.layout();
  const int local = index - g.owned().lo[axis];
  if (local < 0 || local >= g.size(axis)) return;
  const PopulationField& f = solver.populations();
  thread_local std::vector<double> kept;  // the calling thread's, allocated once
  kept.resize(std::size_t(g.size((axis + 1) % 3)) * std::size_t(g.size((axis + 2) % 3)));
  // A pointer, not the name: in a worker thread the name would be that thread's own vector.
  double* const density = kept.data();
  detail::for_plane_fluid_nodes_in_parallel(
      g, solver.node_types(), axis, local,
      [&](std::size_t cell, std::size_t slot) { density[slot] = solver.density(cell); },
      [&](std::size_t ahead) { detail::prefetch_node(f, ahead); });
  detail::for_plane_fluid_nodes(g, solver.node_types(), axis, local,
                                [&](std::size_t, std::size_t slot) {
                                  sums[0] += density[slot];
                                  sums[1] += 1.0;
                                },
                                [](std::size_t) {});
}
double mean_pressure(const double* sums) {
  return sums[1] > 0.0 ? D3Q19::cs2 * sums[0] / sums[1] : 0.0;
}
}  // namespace

double plane_mean_pressure(const FluidSolver& solver, int axis, int index) {
  double sums[2] = {0.0, 0.0};
  add_plane_density(solver, axis, index, sums);
  solver.decomposition().comm.sum(sums, 2);
  return mean_pressure(sums);
}

double total_mass(const FluidSolver& solver) {
  const BlockLayout& g = solver.layout();
  double mass = 0.0;
  for (int k = 0; k < g.size(2); ++k)
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i) {
        const std::size_t cell = g.cell(i, j, k);
        if (solver.node_types()[cell] == kFluid) mass += solver.density(cell);
      }
  return solver.decomposition().comm.sum(mass);
}

namespace detail {
namespace {
// Array p's populations added into the sums of the slots [0, length): rho += v, and j_a += v
// or -= v where c_pa is +1 or -1. Called for p = 0 ... 18 in turn, each slot gets the same
// additions in the same order as FluidSolver::density() and velocity() make (j += c v with
// c = +-1 is j +- v exactly; c = 0 adds a zero there, which changes at most the sign of a
// zero sum, and so neither u - F/2 nor |u|^2). One array at a time, front to back, so the
// loop vectorises: the sums of a plane stay in L1/L2 while the 19 stretches stream past.
template <int p>
void add_array(const Real* __restrict v, std::size_t length, double* __restrict rho,
               double* __restrict jx, double* __restrict jy, double* __restrict jz) {
  using L = D3Q19;
  double* const j[3] = {jx, jy, jz};
  for (std::size_t i = 0; i < length; ++i) {
    const double x = v[i];
    rho[i] += x;
    if constexpr (L::c[p][0] > 0) j[0][i] += x;
    if constexpr (L::c[p][0] < 0) j[0][i] -= x;
    if constexpr (L::c[p][1] > 0) j[1][i] += x;
    if constexpr (L::c[p][1] < 0) j[1][i] -= x;
    if constexpr (L::c[p][2] > 0) j[2][i] += x;
    if constexpr (L::c[p][2] < 0) j[2][i] -= x;
  }
}

// rho and |u|^2 of the slots [0, length) from the 19 arrays f[q] + [0, length), |u|^2 as
// max_speed() computes it; `scratch` holds 3 x length doubles.
template <int... q>
void row_moments(const Real* const* f, std::size_t length, const std::array<double, 3>& F,
                 bool incompressible, double rho0, double* __restrict rho,
                 double* __restrict speed2, double* __restrict scratch,
                 std::integer_sequence<int, q...>) {
  double* const jx = scratch;
  double* const jy = scratch + length;
  double* const jz = scratch + 2 * length;
  std::fill(rho, rho + length, 0.0);
  std::fill(scratch, scratch + 3 * length, 0.0);
  (add_array<q>(f[q], length, rho, jx, jy, jz), ...);
  for (std::size_t i = 0; i < length; ++i) {
    const double r = incompressible ? rho0 : rho[i];
    const double u[3] = {(jx[i] - 0.5 * F[0]) / r, (jy[i] - 0.5 * F[1]) / r, (jz[i] - 0.5 * F[2]) / r};
    speed2[i] = u[0] * u[0] + u[1] * u[1] + u[2] * u[2];
  }
}
}  // namespace

PlaneMoments plane_moments(const FluidSolver& solver, int k) {
  const BlockLayout& g = solver.layout();
  const PopulationField& f = solver.populations();
  // A plane's owned rows and the padding between them are one stretch of each array.
  const std::size_t length = g.cell(g.size(0) - 1, g.size(1) - 1, 0) - g.cell(0, 0, 0) + 1;
  thread_local std::vector<double> buffer;  // rho, |u|^2 and j of one plane, allocated once
  buffer.resize(5 * length);
  const std::size_t plane = g.cell(0, 0, k);
  const Real* arrays[D3Q19::Q];
  for (int q = 0; q < D3Q19::Q; ++q) arrays[q] = f.q(q) + plane;
  const FluidParameters& p = solver.parameters();
  double* const rho = buffer.data();
  double* const speed2 = rho + length;
  row_moments(arrays, length, p.body_force, p.incompressible, p.rho0, rho, speed2, speed2 + length,
              std::make_integer_sequence<int, D3Q19::Q>{});
  return {length, rho, speed2};
}
}  // namespace detail

LatticeTotals lattice_totals(const FluidSolver& solver) {
  const BlockLayout& g = solver.layout();
  const std::uint8_t* const type = solver.node_types().data();
  const int nx = g.size(0), ny = g.size(1);
  LatticeTotals out;
  double mass = 0.0;      // in a local: a member would be stored and reloaded every node
  long long moving = 0;
  double largest2 = 0.0;  // the largest |u| is the root of the largest |u|^2 (monotonic)
  for (int k = 0; k < g.size(2); ++k) {
    const std::size_t plane = g.cell(0, 0, k);
    const detail::PlaneMoments m = detail::plane_moments(solver, k);
    for (int y = 0; y < ny; ++y) {
      const std::size_t row = g.cell(0, y, k) - plane;
      for (int x = 0; x < nx; ++x) {
        const std::size_t i = row + std::size_t(x);
        const std::uint8_t t = type[plane + i];
        moving += t == kMoving;
        if (t != kFluid) continue;
        mass += m.rho[i];
        if (m.rho[i] > 0.0) largest2 = std::max(largest2, m.speed2[i]);  // velocity() gives 0 else
      }
    }
  }
  out.mass = mass;
  out.moving_nodes = moving;
  out.max_speed = std::sqrt(largest2);
  double sums_over_ranks[2] = {out.mass, double(out.moving_nodes)};
  solver.decomposition().comm.sum(sums_over_ranks, 2);
  out.mass = sums_over_ranks[0];
  out.moving_nodes = static_cast<long long>(sums_over_ranks[1]);
  solver.decomposition().comm.max(&out.max_speed, 1);
  return out;
}

// Both planes in one reduction (it runs every fluid step, for the burst detector): the
// same element-wise sums as two plane_mean_pressure calls, one synchronisation instead of two.
// The planes are the open faces: their densities come from the open boundary of the last
// step where it set them (FluidSolver::add_open_face_densities, equal to round-off), which
// spares reading 19 lines per node of two planes every step; read otherwise.
double pressure_loss(const FluidSolver& solver) {
  const int axis = solver.drive().axis;
  const Box& global = solver.decomposition().global;
  double sums[4] = {0.0, 0.0, 0.0, 0.0};
  if (!solver.add_open_face_densities(0, sums)) add_plane_density(solver, axis, global.lo[axis], sums);
  if (!solver.add_open_face_densities(1, sums + 2)) add_plane_density(solver, axis, global.hi[axis] - 1, sums + 2);
  solver.decomposition().comm.sum(sums, 4);
  return mean_pressure(sums) - mean_pressure(sums + 2);
}

}  // namespace lbm
