#include "coupling/boundary/sphere_links.h"

#include <algorithm>
#include <cmath>

#include "lbm/d3q19.h"
#include "lbm/node_type.h"

namespace coupling {

double link_fraction(const Vec3& d, const int c[3], double R) {
  const double a = c[0] * c[0] + c[1] * c[1] + c[2] * c[2];
  const double b = c[0] * d[0] + c[1] * d[1] + c[2] * d[2];
  const double e = d[0] * d[0] + d[1] * d[1] + d[2] * d[2] - R * R;  // >= 0 (outside)
  const double disc = std::max(0.0, b * b - a * e);
  // Smaller root written without cancellation: s = e / (-b + sqrt(disc)) (b < 0 here).
  const double denom = -b + std::sqrt(disc);
  double s = denom > 0.0 ? e / denom : 0.5;
  return std::clamp(s, 1e-6, 1.0);
}

void build_sphere_links(const SphereMapping& mapping, const ParticleView& view,
                        const std::vector<std::uint8_t>& node_type, SphereLinks& out) {
  using L = lbm::D3Q19;
  out.clear();
  const lbm::BlockLayout& layout = mapping.layout();
  for (std::size_t wall : mapping.moving_cells()) {
    const auto w = layout.coords(wall);
    const int p = mapping.particle_at(wall);
    const Vec3 centre = view.x(std::size_t(p));
    const double R = view.r(std::size_t(p));
    for (int q = 1; q < L::Q; ++q) {
      // The fluid node x = wall - c_q sends population q into the wall node.
      const int xi = w[0] - L::c[q][0], xj = w[1] - L::c[q][1], xk = w[2] - L::c[q][2];
      if (!layout.is_owned(xi, xj, xk)) continue;
      const std::size_t x = layout.cell(xi, xj, xk);
      if (node_type[x] != lbm::kFluid) continue;
      // The node's global position from the wall cell's coordinates (no division).
      const auto g = layout.to_global(xi, xj, xk);
      const Vec3 d = mapping.box().displacement(centre, Vec3{double(g[0]), double(g[1]), double(g[2])});
      const double s = link_fraction(d, L::c[q], R);
      const Vec3 arm{d[0] + s * L::c[q][0], d[1] + s * L::c[q][1], d[2] + s * L::c[q][2]};
      lbm::BoundaryLink link;
      link.fluid_cell = x;
      link.q = q;
      link.fraction = s;
      link.wall_velocity = view.surface_velocity(std::size_t(p), arm);
      out.links.push_back(link);
      out.particle.push_back(p);
      out.arm.push_back(arm);
    }
  }
}

}  // namespace coupling
