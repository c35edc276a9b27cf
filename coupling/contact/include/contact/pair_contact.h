#pragma once
// Particle-particle normal force of the paper: dash-dot repulsion (Eq. 1) while the spheres
// overlap plus short-range cohesion (Eq. 2) while the gap is within 0.03 (Ri+Rj).
// Inline: it runs in the pair style's inner loop.
#include <cmath>

#include "contact/dash_dot.h"
#include "contact/short_range_attraction.h"

namespace contact {

struct PairContactParams {
  DashDotParams normal;
  CohesionParams cohesion;
};

struct PairContactInput {
  double gap = 0.0;        // h = |x_i - x_j| - (Ri + Rj); negative = overlap delta = -h
  double gap_rate = 0.0;   // dh/dt (= -d(delta)/dt), negative while approaching
  double radius_i = 0.0, radius_j = 0.0;
  double effective_mass = 0.0;  // mi mj / (mi + mj)
};

// Normal force along the line of centres, repulsive positive (pushes i away from j);
// cohesion gives a negative (attractive) value.
inline double pair_normal_force(const PairContactParams& params, const PairContactInput& in) {
  if (in.gap < 0.0) {
    const double k_d =
        2.0 * params.normal.damping_ratio * std::sqrt(params.normal.k_n * in.effective_mass);
    return params.normal.k_n * (-in.gap) + k_d * (-in.gap_rate);
  }
  const double a_star = in.radius_i * in.radius_j / (in.radius_i + in.radius_j);
  if (in.gap <= params.cohesion.range_factor * (in.radius_i + in.radius_j))
    return -in.gap * params.cohesion.k_c * a_star;
  return 0.0;
}

// True while the pair is bonded: overlapping or within the cohesion range.
inline bool pair_bonded(const PairContactParams& params, double gap, double radius_i,
                        double radius_j) {
  return gap <= params.cohesion.range_factor * (radius_i + radius_j);
}

}  // namespace contact
