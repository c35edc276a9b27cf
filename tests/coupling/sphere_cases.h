#pragma once
// Shared set-up of the coupling tests: a solver on one rank and small helpers.
#include <chrono>
#include <cmath>
#include <memory>

#include "coupling/sphere_coupling.h"
#include "lbm/fluid_solver.h"
#include "lbm/node_type.h"

namespace sphere_cases {

constexpr double kPi = 3.14159265358979323846;

inline std::unique_ptr<lbm::FluidSolver> make_solver(std::array<int, 3> dims, std::array<bool, 3> periodic,
                                                    double tau = 1.0,
                                                    std::array<double, 3> body_force = {0, 0, 0}) {
  lbm::VoxelGeometry g(dims);
  lbm::FluidParameters p;
  p.tau = tau;
  p.magic = 3.0 / 16.0;
  p.periodic = periodic;
  p.body_force = body_force;
  lbm::Box box;
  box.hi = dims;
  return std::make_unique<lbm::FluidSolver>(g, p, lbm::FlowDrive{},
                                            lbm::Decomposition::serial(box, periodic));
}

// Sum of rho u_axis over fluid nodes / number of all owned nodes: the superficial velocity.
inline double superficial_velocity(const lbm::FluidSolver& s, int axis) {
  const auto& L = s.layout();
  double sum = 0.0;
  for (int k = 0; k < L.size(2); ++k)
    for (int j = 0; j < L.size(1); ++j)
      for (int i = 0; i < L.size(0); ++i) {
        const std::size_t c = L.cell(i, j, k);
        if (s.node_types()[c] != lbm::kFluid) continue;
        sum += s.velocity(c)[axis];
      }
  return sum / double(L.owned().volume());
}

inline double fluid_mass(const lbm::FluidSolver& s, long long* count = nullptr) {
  const auto& L = s.layout();
  double m = 0.0;
  long long n = 0;
  for (int k = 0; k < L.size(2); ++k)
    for (int j = 0; j < L.size(1); ++j)
      for (int i = 0; i < L.size(0); ++i) {
        const std::size_t c = L.cell(i, j, k);
        if (s.node_types()[c] != lbm::kFluid) continue;
        m += s.density(c);
        ++n;
      }
  if (count) *count = n;
  return m;
}

struct Stopwatch {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
};

}  // namespace sphere_cases
