#pragma once
// Particle-wall contact of the paper (section II, "Particle-Wall Interaction"): for one
// surface point, dash-dot repulsion with the wall stiffness k_w and damping k_q while
// overlapping (Eq. 1), adhesion F_a = h k_a R_i while the gap is within 0.03 R_i (Eq. 4),
// and Coulomb friction capped at mu N (Eq. 5). The wall is static and infinitely heavy, so
// the effective mass is the particle's. The normal law is the pair contact's (pair_contact.h:
// the same dash_dot_force), with adhesion where the pair has cohesion.
//
// One call is one contact: its input struct carries the contact's own friction spring and
// its result the spring to keep, so any wall model can sum contacts. fix wall/voxel sums over
// the surface points of voxel_surface.h (Eq. 6), which merges the voxels into faces, edges
// and corners; the paper's voxel sum would call it once per solid voxel in reach.
#include "contact/coulomb_friction.h"
#include "contact/dash_dot.h"
#include "contact/short_range_attraction.h"
#include "contact/stability_limits.h"
#include "contact/vec3.h"

namespace contact {

struct WallContactParams {
  DashDotParams normal;      // k_w and zeta (paper: k_q = 0.5 sqrt(k_w m_i) -> zeta = 0.25)
  AdhesionParams adhesion;   // k_a
  FrictionParams friction;   // mu, k_t
};

struct WallContactInput {
  Vec3 normal;            // unit, from the wall towards the particle centre
  double gap = 0.0;       // surface distance minus radius; negative = overlap
  double radius = 0.0;
  double mass = 0.0;
  Vec3 velocity;          // particle velocity (the wall is at rest)
  Vec3 spring;            // tangential spring of this contact from the last step
  double dt = 0.0;
};

struct WallContactResult {
  Vec3 force;             // total force on the particle from this contact
  Vec3 spring;            // tangential spring to keep for the next step
  bool active = false;    // overlapping or adhering; an inactive contact forgets its spring
  bool sliding = false;
};

WallContactResult wall_contact_force(const WallContactParams& params, const WallContactInput& in);

// The terms of the law that depend on the particle alone (radius and mass), the same for each
// of its contacts: a wall model that sums many contacts of one particle (the voxel sum's
// 9-20) computes them, and their square roots, once per particle.
struct WallParticleTerms {
  double normal_damping = 0.0;      // k_q of Eq. 1 (dash_dot.h damping_coefficient)
  double tangential_damping = 0.0;  // gamma_t (coulomb_friction.h)
  double adhesion_range = 0.0;      // 0.03 R of Eq. 4
};
WallParticleTerms wall_particle_terms(const WallContactParams& params, double radius, double mass);

// The same law with those terms given (in.radius and in.mass must be the ones they were
// computed for): the same operations, so the same result bit for bit.
WallContactResult wall_contact_force(const WallContactParams& params, const WallParticleTerms& terms,
                                     const WallContactInput& in);

// Reach of the wall force from the particle centre: the radius plus the adhesion range.
inline double wall_contact_reach(const WallContactParams& params, double radius) {
  return radius + adhesion_range(params.adhesion, radius);
}

// The stiffer of the normal (k_w) and tangential (k_t) springs sets the shortest oscillation
// of a wall contact, so the time step limit; true when it is the tangential one.
inline bool wall_tangential_spring_is_stiffer(const WallContactParams& params) {
  return params.friction.k_t > params.normal.k_n;
}

// The normal spring with the stiffer of k_w and k_t, and the normal damping ratio.
DashDotParams wall_stiffest_spring(const WallContactParams& params);

// The time step limit of a wall contact of a particle of this mass (m_eff = m: the wall does
// not move).
TimeStepLimit wall_time_step_limit(const WallContactParams& params, double mass);

}  // namespace contact
