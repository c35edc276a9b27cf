#include "contact/wall_contact.h"

#include <algorithm>

namespace contact {

DashDotParams wall_stiffest_spring(const WallContactParams& params) {
  DashDotParams stiffest = params.normal;
  stiffest.k_n = std::max(params.normal.k_n, params.friction.k_t);
  return stiffest;
}

TimeStepLimit wall_time_step_limit(const WallContactParams& params, double mass) {
  return time_step_limit(wall_stiffest_spring(params), mass);
}

WallParticleTerms wall_particle_terms(const WallContactParams& params, double radius, double mass) {
  WallParticleTerms terms;
  terms.normal_damping = damping_coefficient(params.normal, mass);
  terms.tangential_damping = tangential_damping(params.friction, mass);
  terms.adhesion_range = adhesion_range(params.adhesion, radius);
  return terms;
}

WallContactResult wall_contact_force(const WallContactParams& params, const WallContactInput& in) {
  return wall_contact_force(params, wall_particle_terms(params, in.radius, in.mass), in);
}

WallContactResult wall_contact_force(const WallContactParams& params, const WallParticleTerms& terms,
                                     const WallContactInput& in) {
  WallContactResult out;
  double normal_force = 0.0;     // along the normal, repulsive positive
  double friction_limit_force = 0.0;  // N of coulomb_friction.h
  if (in.gap < 0.0) {
    NormalContactInput normal_in;
    normal_in.overlap = -in.gap;
    normal_in.overlap_rate = -dot(in.velocity, in.normal);
    normal_in.effective_mass = in.mass;
    normal_force = dash_dot_force(params.normal, terms.normal_damping, normal_in);
    friction_limit_force = params.normal.k_n * normal_in.overlap;
  } else if (in.gap <= terms.adhesion_range) {
    normal_force = -adhesion_force(params.adhesion, in.gap, in.radius);
    friction_limit_force = -normal_force;
  } else {
    return out;  // out of reach: no force, spring forgotten
  }
  out.active = true;
  out.force = normal_force * in.normal;

  if (params.friction.mu > 0.0) {
    FrictionInput friction_in;
    friction_in.normal = in.normal;
    friction_in.relative_velocity = in.velocity;
    friction_in.spring = in.spring;
    friction_in.normal_force = friction_limit_force;
    friction_in.effective_mass = in.mass;
    friction_in.dt = in.dt;
    const FrictionResult friction =
        coulomb_friction(params.friction, terms.tangential_damping, friction_in);
    out.force += friction.force;
    out.spring = friction.spring;
    out.sliding = friction.sliding;
  }
  return out;
}

}  // namespace contact
