#pragma once
// Particle-particle normal force of the paper: dash-dot repulsion (Eq. 1) while the spheres
// overlap plus short-range cohesion (Eq. 2) while the gap is within 0.03 (Ri+Rj). The same
// dash_dot_force as the wall contact (wall_contact.h), with cohesion where the wall has
// adhesion. Inline: it runs in the pair style's inner loop.
#include "contact/dash_dot.h"
#include "contact/short_range_attraction.h"
#include "contact/stability_limits.h"

namespace contact {

struct PairContactParams {
  DashDotParams normal;
  CohesionParams cohesion;
};

struct PairContactInput {
  double gap = 0.0;       // h = |x_i - x_j| - (Ri + Rj); negative = overlap delta = -h
  double gap_rate = 0.0;  // dh/dt (= -d(delta)/dt), negative while approaching
  double radius_i = 0.0, radius_j = 0.0;
  double effective_mass = 0.0;  // pair_effective_mass(mi, mj)
};

// The reduced mass mi mj / (mi + mj) of the two-body contact.
inline double pair_effective_mass(double mass_i, double mass_j) {
  return mass_i * mass_j / (mass_i + mass_j);
}

// Normal force along the line of centres, repulsive positive (pushes i away from j);
// cohesion gives a negative (attractive) value.
inline double pair_normal_force(const PairContactParams& params, const PairContactInput& in) {
  if (in.gap < 0.0) {
    NormalContactInput normal_in;
    normal_in.overlap = -in.gap;
    normal_in.overlap_rate = -in.gap_rate;
    normal_in.effective_mass = in.effective_mass;
    return dash_dot_force(params.normal, normal_in);
  }
  return -cohesion_force(params.cohesion, in.gap, in.radius_i, in.radius_j);
}

// True while the pair is bonded: overlapping or within the cohesion range.
inline bool pair_bonded(const PairContactParams& params, double gap, double radius_i,
                        double radius_j) {
  return gap <= cohesion_range(params.cohesion, radius_i, radius_j);
}

// The time step limit of a contact between two of the lightest particles present (mass m
// each, so m_eff = m/2).
inline TimeStepLimit pair_time_step_limit(const PairContactParams& params, double lightest_mass) {
  return time_step_limit(params.normal, 0.5 * lightest_mass);
}

}  // namespace contact
