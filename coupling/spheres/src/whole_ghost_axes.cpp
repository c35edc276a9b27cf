#include "coupling/boundary/whole_ghost_axes.h"

namespace coupling {

namespace {
// Whether a sphere covers a cell of the padded plane `plane` normal to `axis`.
bool plane_covered(const SphereMapping& mapping, int axis, int plane) {
  const lbm::BlockLayout& layout = mapping.layout();
  const int b = axis == 0 ? 1 : 0, c = axis == 2 ? 1 : 2;  // the other two, increasing
  int ijk[3];
  ijk[axis] = plane;
  for (int v = -1; v <= layout.size(c); ++v)
    for (int u = -1; u <= layout.size(b); ++u) {
      ijk[b] = u;
      ijk[c] = v;
      if (mapping.particle_at(layout.cell(ijk[0], ijk[1], ijk[2])) >= 0) return true;
    }
  return false;
}
}  // namespace

std::array<long long, 3> whole_ghost_axes(const SphereMapping& mapping, lbm::MovingWallScheme scheme,
                                          const lbm::FluidSolver& solver) {
  std::array<long long, 3> whole{0, 0, 0};
  if (scheme != lbm::MovingWallScheme::kMeiLuoShyy || mapping.moving_cells().empty()) return whole;
  const lbm::BlockLayout& layout = mapping.layout();
  for (int a = 0; a < 3; ++a) {
    // The sphere node of a link from plane 0 (n - 1) whose second node lies beyond the face.
    const int second[2] = {1, layout.size(a) - 2};
    for (int side = 0; side < 2 && !whole[a]; ++side)
      whole[a] = solver.exchanges_face(a, side) && plane_covered(mapping, a, second[side]);
  }
  return whole;
}

}  // namespace coupling
