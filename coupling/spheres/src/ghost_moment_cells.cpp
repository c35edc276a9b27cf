#include "coupling/boundary/ghost_moment_cells.h"

#include <algorithm>
#include <cmath>

namespace coupling {

namespace {
// The cells of padded plane `plane` normal to axis a (tangential axes b, c) within `reach`
// of the local centre `centre`.
void add_disc(const lbm::BlockLayout& layout, int a, int b, int c, int plane, const double centre[3],
              double reach, std::vector<std::size_t>& out) {
  const double d = plane - centre[a];
  const double rest = reach * reach - d * d;
  if (rest < 0.0) return;
  const double half_c = std::sqrt(rest);
  const int v0 = std::max(-1, int(std::ceil(centre[c] - half_c)));
  const int v1 = std::min(layout.size(c), int(std::floor(centre[c] + half_c)));
  int ijk[3];
  ijk[a] = plane;
  for (int v = v0; v <= v1; ++v) {
    const double dv = v - centre[c];
    const double row = rest - dv * dv;
    if (row < 0.0) continue;
    const double half_b = std::sqrt(row);
    const int u0 = std::max(-1, int(std::ceil(centre[b] - half_b)));
    const int u1 = std::min(layout.size(b), int(std::floor(centre[b] + half_b)));
    ijk[c] = v;
    for (int u = u0; u <= u1; ++u) {
      ijk[b] = u;
      out.push_back(layout.cell(ijk[0], ijk[1], ijk[2]));
    }
  }
}
}  // namespace

void ghost_moment_cells(const SphereMapping& mapping, const ParticleView& view,
                        const lbm::FluidSolver& solver, const std::array<bool, 3>& axes,
                        GhostMomentCells& out) {
  out.sent.clear();
  out.received.clear();
  const lbm::BlockLayout& layout = mapping.layout();
  for (int a = 0; a < 3; ++a) {
    if (!axes[a]) continue;
    const int b = a == 0 ? 1 : 0, c = a == 2 ? 1 : 2;
    for (int side = 0; side < 2; ++side) {
      if (!solver.exchanges_face(a, side)) continue;
      const int sent_plane = side == 0 ? 0 : layout.size(a) - 1;
      const int ghost_plane = side == 0 ? -1 : layout.size(a);
      for (std::size_t p = 0; p < view.num_total; ++p) {
        const double reach = view.r(p) + kGhostMomentMargin;
        mapping.for_each_local_image(view.x(p), [&](const double centre[3]) {
          add_disc(layout, a, b, c, sent_plane, centre, reach, out.sent);
          add_disc(layout, a, b, c, ghost_plane, centre, reach, out.received);
        });
      }
    }
  }
}

}  // namespace coupling
