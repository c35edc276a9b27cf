#include "coupling/lattice_frame.h"

#include <algorithm>
#include <cmath>

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

}  // namespace coupling
