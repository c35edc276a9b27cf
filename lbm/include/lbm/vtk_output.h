#pragma once
#include <string>
#include <vector>

#include "lbm/fluid_solver.h"

namespace lbm {

// Fluid output for ParaView: VTK XML images written through the VTK library.
// Serial: <directory>/<prefix>_<step>.vti. Parallel: one piece per rank
// <prefix>_<step>_<rank>.vti and a <prefix>_<step>.pvti that joins them. Every write
// appends to <directory>/<prefix>.pvd, a time series ParaView opens directly.
// Point data: density, pressure, velocity (vector), node_type. Coordinates are physical:
// origin + index * spacing of the solver's geometry. Values in lattice units, pressure
// p = cs^2 rho = rho/3. Pieces share their boundary points (a piece holds its owned nodes
// plus the first node layer of the rank above), so ParaView shows no gap between ranks.
// write() is collective over the solver's communicator.
// Without VTK at build time, constructing a writer throws InputError saying so.
class VtkSeriesWriter {
 public:
  VtkSeriesWriter(std::string directory, std::string prefix);
  void write(const FluidSolver& solver, double time);
  static bool available();

 private:
  std::string directory_, prefix_;
  std::vector<std::pair<double, std::string>> entries_;  // time, file name (rank 0)
};

}  // namespace lbm
