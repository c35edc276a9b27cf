#pragma once
// Shared pieces of the accuracy study (examples/accuracy): one result row per run, timing,
// and the small lattice helpers the cases need. Every number in a row is computed by the run.
#include <array>
#include <chrono>
#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "coupling/particle_view.h"
#include "lbm/fluid_solver.h"
#include "lbm/node_type.h"

namespace accuracy {

constexpr double kPi = 3.14159265358979323846;

// One run of one case: the columns of accuracy.csv.
struct Row {
  std::string case_name;   // pipe, drag, lubrication, dashdot, moving
  std::string option;      // scheme or variant
  double resolution = 0;   // cells (pipe: radius, spheres: diameter); 0 where none
  int n_dem = 0;           // DEM steps per contact (dashdot); 0 where not applicable
  double error = 0;        // relative error, >= 0 (the case says which norm)
  std::string reference;   // the source the error is measured against
  double wall_seconds = 0;
  double value = 0;            // the headline quantity measured ...
  double reference_value = 0;  // ... and its reference value (the error's basis may differ)
  long steps = 0;              // fluid or DEM steps
  std::string note;            // key=value extras (mass drift, signed errors)
};

struct Options {
  bool quick = false;
};

struct Stopwatch {
  std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  double seconds() const {
    return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  }
};

// The cases; each appends its rows.
void run_pipe(const Options& options, std::vector<Row>& rows);
void run_drag(const Options& options, std::vector<Row>& rows);
void run_lubrication(const Options& options, std::vector<Row>& rows);
void run_dashdot(const Options& options, std::vector<Row>& rows);
void run_moving(const Options& options, std::vector<Row>& rows);

// A serial solver with Lambda = 3/16.
inline std::unique_ptr<lbm::FluidSolver> make_solver(std::array<int, 3> dims,
                                                    std::array<bool, 3> periodic, double tau,
                                                    std::array<double, 3> body_force) {
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

// Sum of u_axis over fluid nodes / number of all nodes: the superficial velocity.
inline double superficial_velocity(const lbm::FluidSolver& s, int axis,
                                   long long* fluid_nodes = nullptr) {
  const auto& L = s.layout();
  double sum = 0.0;
  long long n = 0;
  for (int k = 0; k < L.size(2); ++k)
    for (int j = 0; j < L.size(1); ++j)
      for (int i = 0; i < L.size(0); ++i) {
        const std::size_t c = L.cell(i, j, k);
        if (s.node_types()[c] != lbm::kFluid) continue;
        sum += s.velocity(c)[axis];
        ++n;
      }
  if (fluid_nodes) *fluid_nodes = n;
  return sum / double(L.owned().volume());
}

inline double fluid_mass(const lbm::FluidSolver& s) {
  const auto& L = s.layout();
  double m = 0.0;
  for (int k = 0; k < L.size(2); ++k)
    for (int j = 0; j < L.size(1); ++j)
      for (int i = 0; i < L.size(0); ++i) {
        const std::size_t c = L.cell(i, j, k);
        if (s.node_types()[c] == lbm::kFluid) m += s.density(c);
      }
  return m;
}

// Sangani & Acrivos (1982) for a simple-cubic array at chi = d/L = 0.5 (REFERENCES.md).
constexpr double kDragChi = 0.5;
constexpr double kDragKRef = 2.8420;

}  // namespace accuracy
