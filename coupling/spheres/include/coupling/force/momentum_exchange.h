#pragma once
// Hydrodynamic force and torque on the spheres by momentum exchange (paper Eq. 2).
#include <vector>

#include "coupling/boundary/sphere_links.h"
#include "lbm/moving_wall/link_boundary.h"

namespace coupling {

enum class MomentumExchange {
  // Ladd (1994) / Mei et al. (2002), paper Eq. 2: per link c_q (f*_q(x) + f_{-q}(x, t+1)).
  kPlain,
  // Galilean-invariant form of Wen, Zhang, Tu, Wang & Fang (2014), J. Comput. Phys. 266:161:
  // per link (c_q - u_w) f*_q(x) - (c_{-q} - u_w) f_{-q}(x, t+1)
  //        = c_q (f*_q + f_{-q}) - u_w (f*_q - f_{-q}).
  // The extra term removes the spurious force a moving wall feels from the rest mass it
  // carries across links; no covered/uncovered node momentum is added with it.
  kGalileanInvariant,
};

// The reference pressure's share of each link, 2 w_q rho0: removed (the default) or kept (the
// paper's Eq. 2 read literally). Over a closed link set it sums to zero either way; where a
// sphere touches a wall or another sphere its covered nodes lose fluid neighbours, and kept,
// it pushes the sphere with p0 = rho0 / 3 on the part of its surface that has no links: into
// the wall ("void as vacuum"), two touching spheres together.
enum class ReferencePressure { kRemoved, kKept };

// The gauge density whose share 2 w_q rho_gauge each link loses: rho0 removed, 0 kept.
inline double gauge_density(ReferencePressure reference, double rho0) {
  return reference == ReferencePressure::kRemoved ? rho0 : 0.0;
}

// Per-particle force and torque of one fluid step (lattice units, force = momentum per step).
struct HydrodynamicLoads {
  std::vector<Vec3> force;   // indexed like the view of the step (owned and ghosts)
  std::vector<Vec3> torque;  // about the particle centre
  // How strongly the force resists a change of the particle's velocity through the
  // moving-wall term of its links: dF/dv = -C (isotropic part of sum 6 w_q rho0 c_q c_q).
  // A host that keeps the force over several DEM substeps applies F - C (v - v_step) so the
  // fluid resists velocity changes at once (Nguyen & Ladd 2002, implicit particle update):
  // without it, the explicit coupling is unstable for particles in near contact, whose
  // relative motion has half the mass (C dt / m_reduced > 2 with rho_p / rho_f = 2.3).
  std::vector<double> velocity_coefficient;
  void reset(std::size_t n) {
    force.assign(n, Vec3{0.0, 0.0, 0.0});
    torque.assign(n, Vec3{0.0, 0.0, 0.0});
    velocity_coefficient.assign(n, 0.0);
  }
};

// Both forms use the gauge populations, 2 w_q rho0 subtracted per link (exact no-op for a
// sphere surrounded by fluid; removes the spurious p0 push where its surface has no fluid
// links, i.e. in contact with a wall or another sphere), unless `reference` keeps it.
// Sums over the links (all from owned fluid nodes, so ghost layers never double count),
// from the populations the moving-wall stage recorded per link (lbm::apply_links' output:
// no lattice access). Torque arm: the cut point on the surface. Links in particle order (as
// build_sphere_links gives them) are split over OpenMP threads by whole particles, each
// summed in link order, so the loads are the same for any number of threads.
void add_momentum_exchange(const SphereLinks& links,
                           const std::vector<lbm::LinkPopulations>& populations,
                           MomentumExchange method, double rho0, HydrodynamicLoads& loads,
                           ReferencePressure reference = ReferencePressure::kRemoved);

}  // namespace coupling
