#pragma once
// Serial lattice set-ups shared by the tests and the accuracy study (lbmpore::cases): a
// solver on one rank, the steady-state loop, the relative L2 error against an analytic
// profile, the superficial velocity and the fluid mass over fluid nodes.
#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <functional>
#include <memory>

#include "lbm/fluid_solver.h"
#include "lbm/macroscopic.h"
#include "lbm/node_type.h"

namespace cases {

constexpr double kPi = 3.14159265358979323846;

struct Stopwatch {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
};

// The whole lattice of `g` on one rank.
inline lbm::Decomposition serial_decomposition(const lbm::VoxelGeometry& g,
                                               std::array<bool, 3> periodic) {
  lbm::Box box;
  box.hi = g.dims();
  return lbm::Decomposition::serial(box, periodic);
}

// A serial solver of an all-fluid box with Lambda = 3/16 (bounce-back walls exactly half-way).
inline std::unique_ptr<lbm::FluidSolver> make_solver(std::array<int, 3> dims,
                                                     std::array<bool, 3> periodic, double tau = 1.0,
                                                     std::array<double, 3> body_force = {0, 0, 0}) {
  lbm::VoxelGeometry g(dims);
  lbm::FluidParameters p;
  p.tau = tau;
  p.magic = 3.0 / 16.0;
  p.periodic = periodic;
  p.body_force = body_force;
  return std::make_unique<lbm::FluidSolver>(g, p, lbm::FlowDrive{},
                                            serial_decomposition(g, periodic));
}

// Steps (`advance`, default solver.step()) until the largest velocity change over
// `check_every` steps falls below `tolerance` relative to the largest velocity, or until
// max_steps. Returns the steps taken.
inline long run_to_steady(lbm::FluidSolver& solver, double tolerance, long max_steps,
                          int check_every = 200, const std::function<void()>& advance = nullptr) {
  auto previous = lbm::compute_fields(solver).velocity;
  long steps = 0;
  while (steps < max_steps) {
    for (int s = 0; s < check_every; ++s, ++steps) {
      if (advance)
        advance();
      else
        solver.step();
    }
    const auto now = lbm::compute_fields(solver).velocity;
    double change = 0.0, scale = 1e-300;
    for (std::size_t i = 0; i < now.size(); ++i) {
      change = std::max(change, std::abs(now[i] - previous[i]));
      scale = std::max(scale, std::abs(now[i]));
    }
    if (change < tolerance * scale) break;
    previous = now;
  }
  return steps;
}

// Relative L2 error of the velocity component `axis` over fluid nodes against `exact`.
inline double relative_l2_error(const lbm::FluidSolver& solver, int axis,
                                const std::function<double(int, int, int)>& exact) {
  const auto fields = lbm::compute_fields(solver);
  const auto& g = solver.layout();
  double num = 0.0, den = 0.0;
  std::size_t n = 0;
  for (int k = 0; k < g.size(2); ++k)
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i, ++n) {
        if (fields.node_type[n] != lbm::kFluid) continue;
        const auto gl = g.to_global(i, j, k);
        const double e = exact(gl[0], gl[1], gl[2]);
        num += std::pow(fields.velocity[3 * n + axis] - e, 2);
        den += e * e;
      }
  return std::sqrt(num / den);
}

// Calls visit(cell) for every fluid node of the solver, k slowest and i fastest.
template <class Visit>
void for_each_fluid_node(const lbm::FluidSolver& s, Visit&& visit) {
  const auto& L = s.layout();
  for (int k = 0; k < L.size(2); ++k)
    for (int j = 0; j < L.size(1); ++j)
      for (int i = 0; i < L.size(0); ++i) {
        const std::size_t c = L.cell(i, j, k);
        if (s.node_types()[c] == lbm::kFluid) visit(c);
      }
}

// Sum of u_axis over fluid nodes / number of all owned nodes: the superficial velocity.
// `fluid_nodes`, when given, receives the number of fluid nodes.
inline double superficial_velocity(const lbm::FluidSolver& s, int axis,
                                   long long* fluid_nodes = nullptr) {
  double sum = 0.0;
  long long n = 0;
  for_each_fluid_node(s, [&](std::size_t c) {
    sum += s.velocity(c)[axis];
    ++n;
  });
  if (fluid_nodes) *fluid_nodes = n;
  return sum / double(s.layout().owned().volume());
}

// Sum of the density over fluid nodes; `fluid_nodes`, when given, receives their number.
inline double fluid_mass(const lbm::FluidSolver& s, long long* fluid_nodes = nullptr) {
  double m = 0.0;
  long long n = 0;
  for_each_fluid_node(s, [&](std::size_t c) {
    m += s.density(c);
    ++n;
  });
  if (fluid_nodes) *fluid_nodes = n;
  return m;
}

}  // namespace cases
