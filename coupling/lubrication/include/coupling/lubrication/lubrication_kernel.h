#pragma once
// The lubrication correction (lubrication.h) as a host applies it every DEM substep: over
// its particles in its own units, the pairs of its neighbour list and each particle's
// nearest wall. The law is in lattice units; the kernel converts positions and velocities
// in and forces out, so the host only hands over its arrays.
#include <vector>

#include "coupling/lubrication/lubrication.h"
#include "coupling/lubrication/nearest_wall.h"
#include "coupling/particle_view.h"

namespace coupling {

// Host units -> lattice units: lengths / dx, velocities * dt_fluid / dx; lattice force *
// force_unit -> host force.
struct LubricationScales {
  double dx = 1.0;
  double dt_fluid = 1.0;
  double force_unit = 1.0;
};

class LubricationKernel {
 public:
  LubricationKernel(const LubricationParameters& lattice_parameters, const LubricationScales& scales);

  // `view` in host units, indexed like `force` (3 per particle). For each pair closer than
  // the cutoff: i gets the force, j the opposite when j is owned. A pair split across ranks
  // is listed on both (newton off) and each side adds its own half.
  void add_pair_forces(const ParticleView& view, const std::vector<ParticlePair>& pairs, double* force) const;

  // Wall lubrication of the owned particles; wall_of(i) gives particle i's NearestWall
  // (known = false for particles to skip).
  template <class WallOf>
  void add_wall_forces(const ParticleView& view, const WallOf& wall_of, double* force) const {
    for (std::size_t i = 0; i < view.num_owned; ++i) {
      const NearestWall& wall = wall_of(i);
      if (!wall.known) continue;
      add_wall_force(wall, view.x(i), view.v(i), view.r(i), force + 3 * i);
    }
  }

  // The cutoff h_c in host units.
  double cutoff() const { return cutoff_; }
  const LubricationCorrection& law() const { return law_; }

 private:
  void add_wall_force(const NearestWall& wall, const Vec3& x, const Vec3& v, double radius, double* force) const;
  Vec3 to_lattice_velocity(const Vec3& v) const;

  LubricationCorrection law_;
  LubricationScales scales_;
  double cutoff_ = 0.0;
};

}  // namespace coupling
