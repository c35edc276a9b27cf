#include "coupling/lattice_frame.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "lbm/input_error.h"

namespace coupling {

namespace {
// First node index at or above coordinate x; a relative tolerance keeps a node that sits
// exactly on a face (up to round-off) on one side only, consistently for both neighbours.
int first_node_at_or_above(double x, double origin, double dx) {
  return static_cast<int>(std::ceil((x - origin) / dx - 1e-9));
}
}  // namespace

lbm::Box LatticeFrame::owned_box(const double* sublo, const double* subhi, const bool* at_lower,
                                 const bool* at_upper) const {
  lbm::Box box;
  for (int a = 0; a < 3; ++a) {
    int lo = at_lower[a] ? 0 : first_node_at_or_above(sublo[a], origin[a], dx);
    int hi = at_upper[a] ? dims[a] : first_node_at_or_above(subhi[a], origin[a], dx);
    box.lo[a] = std::clamp(lo, 0, dims[a]);
    box.hi[a] = std::clamp(hi, 0, dims[a]);
  }
  return box;
}

void LatticeFrame::check_fills_box(const double* box_lo, const double* box_hi, const int* periodic) const {
  // Round-off of a box length written with 15 digits (LIGGGHTS's ${} of a variable).
  constexpr double kPeriodTolerance = 1e-9;
  for (int a = 0; a < 3; ++a) {
    const double lattice_lo = origin[a] - 0.5 * dx;
    const double lattice_hi = lattice_lo + dims[a] * dx;
    const double period = dims[a] * dx, length = box_hi[a] - box_lo[a];
    if (periodic && periodic[a] && std::abs(length - period) > kPeriodTolerance * dx) {
      char text[400];
      std::snprintf(text, sizeof text,
                    "scene: the box is periodic along %c with length %.10g, but the lattice's period "
                    "there is %d cells of dx = %.10g, %.10g: a periodic length must be a whole number "
                    "of cells (set the box's length to %.15g)",
                    "xyz"[a], length, dims[a], dx, period, period);
      throw lbm::InputError(text);
    }
    if (std::abs(lattice_lo - box_lo[a]) <= 0.5 * dx && std::abs(lattice_hi - box_hi[a]) <= 0.5 * dx) continue;
    char text[400];
    std::snprintf(text, sizeof text,
                  "scene: the lattice spans [%g, %g] on axis %c but the simulation box is "
                  "[%g, %g]; make the box match the scene (dims %d x %d x %d cells of dx = %g) "
                  "or set 'origin'",
                  lattice_lo, lattice_hi, "xyz"[a], box_lo[a], box_hi[a], dims[0], dims[1], dims[2], dx);
    throw lbm::InputError(text);
  }
}

lbm::Decomposition subdomain_decomposition(const LatticeFrame& frame, const SubdomainGrid& grid,
                                           const std::array<bool, 3>& periodic, const lbm::Communicator& comm,
                                           int rank) {
  lbm::Decomposition d;
  d.global.hi = frame.dims;
  d.periodic = periodic;
  d.comm = comm;
  bool at_lower[3], at_upper[3];
  for (int a = 0; a < 3; ++a) {
    at_lower[a] = grid.location[a] == 0;
    at_upper[a] = grid.location[a] == grid.procs[a] - 1;
    for (int side = 0; side < 2; ++side) {
      const bool edge = side == 0 ? at_lower[a] : at_upper[a];
      d.neighbor[a][side] = (edge && !periodic[a]) ? -1 : grid.neighbors[a][side];
    }
  }
  d.owned = frame.owned_box(grid.sublo, grid.subhi, at_lower, at_upper);
  for (int a = 0; a < 3; ++a)
    if (d.owned.size(a) < 1)
      throw lbm::InputError("the subdomain of rank " + std::to_string(rank) + " holds no lattice node on axis " +
                            std::string(1, "xyz"[a]) + ": use fewer ranks along that axis (processors command)");
  return d;
}

}  // namespace coupling
