#include "coupling/force/momentum_exchange.h"

#include <algorithm>

#include "lbm/d3q19.h"
#include "lbm/thread_team.h"

namespace coupling {

namespace {
using L = lbm::D3Q19;

// c_q and |c_q|^2 as doubles: the same (exact) values the integer table converts to per link.
struct DoubleVelocities {
  double c[L::Q][3];
  double norm2[L::Q];
};
constexpr DoubleVelocities double_velocities() {
  DoubleVelocities v{};
  for (int q = 0; q < L::Q; ++q) {
    for (int a = 0; a < 3; ++a) v.c[q][a] = L::c[q][a];
    v.norm2[q] = L::c[q][0] * L::c[q][0] + L::c[q][1] * L::c[q][1] + L::c[q][2] * L::c[q][2];
  }
  return v;
}
constexpr DoubleVelocities kC = double_velocities();

// Links [first, last), which hold every link of their particles: each particle's sums run
// over its links in order, whatever the split. A particle's links are consecutive, so its
// sums are kept in registers over the run of them (the same additions in the same order as
// into the arrays).
// rho_gauge: the reference density whose share 2 w_q rho_gauge each link loses (rho0, or 0
// with the reference pressure kept).
template <bool kGalilean>
void sum_links(const SphereLinks& sl, const std::vector<lbm::LinkPopulations>& populations,
               std::size_t first, std::size_t last, double rho0, double rho_gauge, HydrodynamicLoads& loads) {
  std::size_t l = first;
  while (l < last) {
    const int p = sl.particle[l];
    Vec3 force = loads.force[p];
    Vec3 torque = loads.torque[p];
    double coefficient = loads.velocity_coefficient[p];
    for (; l < last && sl.particle[l] == p; ++l) {
      const lbm::BoundaryLink& link = sl.links[l];
      const int q = link.q;
      const double out = populations[l].out;
      const double back = populations[l].back;
      // The reference pressure's share 2 w_q rho0 is removed per link: over a closed link set
      // it sums to zero exactly (as many links along +c_q as along -c_q), but where a sphere
      // touches a wall or another sphere and its covered nodes lose their fluid neighbours
      // it would act as the pressure p0 = rho0/3 on one side only ("void as vacuum").
      const double sum = out + back - 2.0 * L::w[q] * rho_gauge;
      Vec3 F{sum * kC.c[q][0], sum * kC.c[q][1], sum * kC.c[q][2]};
      if (kGalilean) {
        const double diff = out - back;
        for (int a = 0; a < 3; ++a) F[a] -= link.wall_velocity[a] * diff;
      }
      for (int a = 0; a < 3; ++a) force[a] += F[a];
      // Isotropic part of 6 w_q rho0 c_q c_q: trace / 3 = 2 w_q rho0 |c_q|^2.
      coefficient += 2.0 * L::w[q] * rho0 * kC.norm2[q];
      const Vec3 t = cross(sl.arm[l], F);
      for (int a = 0; a < 3; ++a) torque[a] += t[a];
    }
    loads.force[p] = force;
    loads.torque[p] = torque;
    loads.velocity_coefficient[p] = coefficient;
  }
}

// The first link at or after l of a particle other than link l - 1's (links sorted by
// particle).
std::size_t particle_boundary(const SphereLinks& sl, std::size_t l) {
  while (l > 0 && l < sl.particle.size() && sl.particle[l] == sl.particle[l - 1]) ++l;
  return l;
}

template <bool kGalilean>
void sum_all_links(const SphereLinks& sl, const std::vector<lbm::LinkPopulations>& populations,
                   double rho0, double rho_gauge, HydrodynamicLoads& loads) {
  const std::size_t n = sl.links.size();
  int threads = 1;
#ifdef _OPENMP
  // Split only links in particle order (build_sphere_links'), so that each particle's links
  // fall to one thread.
  if (std::is_sorted(sl.particle.begin(), sl.particle.end())) threads = lbm::link_threads(n);
#endif
  if (threads <= 1) {
    sum_links<kGalilean>(sl, populations, 0, n, rho0, rho_gauge, loads);
    return;
  }
  // Blocks of whole particles, one per thread: no two threads add to one particle.
#pragma omp parallel num_threads(threads)
  {
    const lbm::TeamMember member = lbm::team_member();
    const std::size_t t = std::size_t(member.index), nt = std::size_t(member.size);
    sum_links<kGalilean>(sl, populations, particle_boundary(sl, n * t / nt),
                         particle_boundary(sl, n * (t + 1) / nt), rho0, rho_gauge, loads);
  }
}
}  // namespace

void add_momentum_exchange(const SphereLinks& links,
                           const std::vector<lbm::LinkPopulations>& populations,
                           MomentumExchange method, double rho0, HydrodynamicLoads& loads,
                           ReferencePressure reference) {
  const double rho_gauge = gauge_density(reference, rho0);
  if (method == MomentumExchange::kGalileanInvariant)
    sum_all_links<true>(links, populations, rho0, rho_gauge, loads);
  else
    sum_all_links<false>(links, populations, rho0, rho_gauge, loads);
}

}  // namespace coupling
