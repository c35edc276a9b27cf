#pragma once
// Lubrication correction below the resolved gap (paper Sec. II.A.1, after Zhang et al. 2005):
//   F = 6 pi rho nu a^2 v / h,  a = Ri Rj / (Ri + Rj)  (a = R against a wall),
// applied only for h < h_c, where the lattice no longer resolves the gap, with its value at
// h_c subtracted so the resolved part is not counted twice:
//   F = 6 pi rho nu a^2 v (1/h - 1/h_c),  h clamped at h_min = roughness * R (paper: 0.01 R).
// Only the normal (squeeze) component, as in the paper; v > 0 when the surfaces approach.
#include <functional>
#include <limits>

#include "coupling/particle_view.h"
#include "coupling/periodic_box.h"

namespace coupling {

struct LubricationParameters {
  double rho = 1.0;                // fluid density (lattice units)
  double nu = 1.0 / 6.0;           // kinematic viscosity (lattice units)
  double cutoff = 2.0 / 3.0;       // h_c in lattice cells
  double roughness = 0.01;         // h_min = roughness * min(Ri, Rj)
};

// Nearest wall seen from a point: distance (>= 0 in the fluid) and the unit normal pointing
// from the wall into the fluid. distance = +infinity when no wall is near.
struct WallDistance {
  double distance = std::numeric_limits<double>::infinity();
  Vec3 normal{0.0, 0.0, 0.0};
};
using WallDistanceFunction = std::function<WallDistance(const Vec3& point)>;

class LubricationCorrection {
 public:
  explicit LubricationCorrection(const LubricationParameters& parameters);

  // Force on sphere i from sphere j (the opposite acts on j). d = x_j - x_i.
  Vec3 pair_force(double Ri, double Rj, const Vec3& d, const Vec3& vi, const Vec3& vj) const;
  // The same with dist = sqrt(dot(d, d)) given, for a caller that has tested the gap with it.
  Vec3 pair_force(double Ri, double Rj, const Vec3& d, double dist, const Vec3& vi,
                  const Vec3& vj) const;
  // Force on a sphere of radius R with velocity v from a wall at distance `wall.distance`
  // from its centre.
  Vec3 wall_force(double R, const Vec3& v, const WallDistance& wall) const;
  // Magnitude law for a gap h and approach speed v (positive = repulsive), 0 for h >= h_c.
  double magnitude(double a, double h, double v, double R_min) const;

  // Adds the correction to the owned particles of the view: pairs (i owned, j any other, so
  // a pair split across ranks is counted once on each side and never twice) and walls
  // (if `wall` is set). O(N^2) over the view; `force` holds 3 per particle.
  void add_forces(const ParticleView& view, const PeriodicBox& box, const WallDistanceFunction& wall,
                  double* force) const;

  const LubricationParameters& parameters() const { return parameters_; }

 private:
  LubricationParameters parameters_;
};

// A plane wall {y : n.(y - point) = 0} with unit normal n into the fluid, for tests and
// simple scenes.
WallDistanceFunction plane_wall(const Vec3& point, const Vec3& normal);

}  // namespace coupling
