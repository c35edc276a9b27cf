#pragma once
// Small helpers shared by the lbm physics tests: steady-state runs and error norms.
#include <cmath>
#include <functional>

#include "lbm/fluid_solver.h"
#include "lbm/macroscopic.h"

namespace flow_cases {

inline lbm::Decomposition serial(const lbm::VoxelGeometry& g, std::array<bool, 3> periodic) {
  lbm::Box box;
  box.hi = g.dims();
  return lbm::Decomposition::serial(box, periodic);
}

// Steps until the largest velocity change over `check_every` steps falls below `tolerance`
// relative to the largest velocity (or max_steps is reached). Returns steps taken.
inline long run_to_steady(lbm::FluidSolver& solver, double tolerance, long max_steps,
                          int check_every = 200,
                          const std::function<void()>& before_step = nullptr) {
  auto previous = lbm::compute_fields(solver).velocity;
  long steps = 0;
  while (steps < max_steps) {
    for (int s = 0; s < check_every; ++s, ++steps) {
      if (before_step) before_step();
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

}  // namespace flow_cases
