#pragma once
// Boundary links between fluid nodes and the spheres covering their neighbours.
#include <vector>

#include "coupling/mapping/sphere_mapping.h"
#include "coupling/particle_view.h"
#include "lbm/moving_wall/link_boundary.h"

namespace coupling {

// The links of one step and, per link, the sphere it meets (index in the view) and the
// cut point relative to the sphere centre (the torque arm).
struct SphereLinks {
  std::vector<lbm::BoundaryLink> links;
  std::vector<int> particle;
  std::vector<Vec3> arm;
  void clear() { links.clear(); particle.clear(); arm.clear(); }
  void append(const SphereLinks& other);
};

// One link per owned fluid node x and direction q whose neighbour x + c_q is covered by a
// sphere. The fraction is the exact intersection of the segment x + s c_q, 0 < s <= 1, with
// the sphere |y - X| = R (the smaller root of a quadratic, Iglberger et al. 2008), and the
// wall velocity is v + omega x r at the cut point. Only owned fluid nodes get links, so the
// momentum summed over them counts each fluid-particle exchange on exactly one rank.
// The links of a sphere are contiguous, spheres in view order. Only the mapping's surface
// cells are visited, so the work is the spheres' surface. With `scratch` (per-thread lists
// kept by the caller, so that they are allocated once) the spheres are split over the
// OpenMP threads; the result is the same for any number of threads.
void build_sphere_links(const SphereMapping& mapping, const ParticleView& view,
                        const std::vector<std::uint8_t>& node_type, SphereLinks& out,
                        std::vector<SphereLinks>* scratch = nullptr);

// Smallest s in [0, 1] with |d + s c|^2 = R^2 for d outside and d + c inside the sphere
// (d = node - centre); clamped to [1e-6, 1].
double link_fraction(const Vec3& d, const int c[3], double R);

}  // namespace coupling
