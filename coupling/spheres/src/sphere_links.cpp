#include "coupling/boundary/sphere_links.h"

#include <algorithm>
#include <cmath>

#ifdef _OPENMP
#include <omp.h>
#endif

#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "lbm/thread_team.h"

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

void SphereLinks::append(const SphereLinks& other) {
  links.insert(links.end(), other.links.begin(), other.links.end());
  particle.insert(particle.end(), other.particle.begin(), other.particle.end());
  arm.insert(arm.end(), other.arm.begin(), other.arm.end());
}

namespace {
using L = lbm::D3Q19;

// Appends the links of spheres [first, last), sphere by sphere, each over its surface cells
// in mapping order and the directions in q order: the order of the links, and with it every
// sum over them, is that of the particles and does not depend on how they are split.
void append_links(const SphereMapping& mapping, const ParticleView& particles,
                  const std::vector<std::uint8_t>& node_type, std::size_t first, std::size_t last,
                  SphereLinks& out) {
  const lbm::BlockLayout& layout = mapping.layout();
  // Local copies: the stores into `out` could alias the originals, which the compiler would
  // then reload for every link.
  const ParticleView view = particles;
  const PeriodicBox box = mapping.box();
  const std::uint8_t* const type = node_type.data();
  const int n[3] = {layout.size(0), layout.size(1), layout.size(2)};
  std::ptrdiff_t offset[L::Q];  // cell-index step of c_q
  for (int q = 0; q < L::Q; ++q) offset[q] = layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
  for (std::size_t p = first; p < last; ++p) {
    const Vec3 centre = view.x(p);
    const double R = view.r(p);
    // The link from fluid node x = wall - c_q (local coordinates w - c_q), which sends
    // population q into the wall node.
    const auto add_link = [&](std::size_t x, int q, const std::array<int, 3>& w) {
      // The node's global position from the wall cell's coordinates (no division).
      const auto g = layout.to_global(w[0] - L::c[q][0], w[1] - L::c[q][1], w[2] - L::c[q][2]);
      const Vec3 d = box.displacement(centre, Vec3{double(g[0]), double(g[1]), double(g[2])});
      const double s = link_fraction(d, L::c[q], R);
      // Written in place: a link built on the stack with 8-byte stores and copied in 16-byte
      // moves stalled every copy on store forwarding (a third of link building's samples).
      Vec3& arm = out.arm.emplace_back();
      for (int a = 0; a < 3; ++a) arm[a] = d[a] + s * L::c[q][a];
      lbm::BoundaryLink& link = out.links.emplace_back();
      link.fluid_cell = x;
      link.q = q;
      link.fraction = s;
      link.wall_velocity = view.surface_velocity(p, arm);
      out.particle.push_back(int(p));
    };
    for (std::size_t wall : mapping.surface_cells(p)) {
      const auto w = layout.coords(wall);
      // Off the owned box's outer layer (and its ghosts) all 18 neighbours are owned: only
      // their type decides. Most surface cells are such.
      const bool inner = w[0] >= 1 && w[1] >= 1 && w[2] >= 1 && w[0] < n[0] - 1 &&
                         w[1] < n[1] - 1 && w[2] < n[2] - 1;
      if (inner) {
        const std::uint8_t* const at = type + wall;
        for (int q = 1; q < L::Q; ++q)
          if (at[-offset[q]] == lbm::kFluid) add_link(wall - offset[q], q, w);
        continue;
      }
      for (int q = 1; q < L::Q; ++q) {
        if (!layout.is_owned(w[0] - L::c[q][0], w[1] - L::c[q][1], w[2] - L::c[q][2])) continue;
        const std::size_t x = wall - offset[q];
        if (type[x] == lbm::kFluid) add_link(x, q, w);
      }
    }
  }
}
// The first sphere of share t of nt, the spheres split by their surface cells (the work of
// their links: spheres differ in size, and in how much of them a rank owns); n for t = nt.
std::size_t sphere_of_share(const SphereMapping& mapping, std::size_t n, std::size_t t, std::size_t nt) {
  if (t >= nt) return n;
  const std::size_t* const base = mapping.surface_cells(0).first;
  const std::size_t target = std::size_t(mapping.surface_cells(n - 1).last - base) * t / nt;
  std::size_t p = 0;
  while (p < n && std::size_t(mapping.surface_cells(p).first - base) < target) ++p;
  return p;
}
}  // namespace

void build_sphere_links(const SphereMapping& mapping, const ParticleView& view,
                        const std::vector<std::uint8_t>& node_type, SphereLinks& out,
                        std::vector<SphereLinks>* scratch) {
  out.clear();
  const std::size_t n = mapping.num_mapped_particles();
  int threads = 1;
#ifdef _OPENMP
  if (scratch && n > 1) threads = std::min<int>(omp_get_max_threads(), int(n));
#endif
  if (threads <= 1) {
    append_links(mapping, view, node_type, 0, n, out);
    return;
  }
  // Thread t takes the t-th contiguous block of spheres (by surface cells): thread 0 into
  // `out` itself, the others into lists of their own, which join `out` in thread order, i.e.
  // in particle order (the same links as one thread's), each copied by the thread that built
  // it, from its own core's cache.
  scratch->resize(std::size_t(threads));
#pragma omp parallel num_threads(threads)
  {
    const auto [t, nt] = lbm::team_member();
    SphereLinks& part = t == 0 ? out : (*scratch)[std::size_t(t)];
    if (t > 0) part.clear();
    append_links(mapping, view, node_type, sphere_of_share(mapping, n, std::size_t(t), std::size_t(nt)),
                 sphere_of_share(mapping, n, std::size_t(t) + 1, std::size_t(nt)), part);
    // Iteration u runs on thread u; ordered: after thread u - 1's part has joined.
#pragma omp for ordered schedule(static, 1)
    for (int u = 0; u < nt; ++u) {
#pragma omp ordered
      if (u > 0) out.append((*scratch)[std::size_t(u)]);
    }
  }
}

}  // namespace coupling
