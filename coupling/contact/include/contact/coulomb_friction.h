#pragma once
// Coulomb friction of the particle-wall contact (paper Eq. 5: F_f <= mu F_n, tangential).
//
// Regularisation: a tangential spring with history (Cundall-Strack). The stored spring
// displacement xi grows with the tangential slip, F_t = -k_t xi - gamma_t v_t, and is capped
// at mu N; when capped the contact slides and xi is reset to carry exactly the capped force.
// A spring (not a viscous law) is needed so that a particle at rest on a wall tilted below
// atan(mu) stays at rest instead of creeping: at equilibrium v_t = 0 and k_t xi balances the
// tangential load. The spring is rotated into the current tangent plane every step (its
// length kept), so a contact that turns slowly keeps its stored load.
//
// N is the magnitude of the conservative normal force of the contact: k_w delta when
// overlapping, the adhesion F_a when adhering. So a particle held only by adhesion still
// feels friction, as the paper asks ("as long as the particle adheres"), and the damping
// part of the normal force does not make the friction limit chatter.
#include "contact/vec3.h"

namespace contact {

// The tangential stiffness when none is given: 2/7 of the normal one, as LIGGGHTS hooke.
inline double default_tangential_stiffness(double k_n) { return 2.0 / 7.0 * k_n; }

struct FrictionParams {
  double mu = 0.1;              // paper table
  double k_t = default_tangential_stiffness(0.1);  // of the paper's k_w = 0.1
  double damping_ratio = 0.25;  // of the tangential oscillator, as for the normal one
};

struct FrictionInput {
  Vec3 normal;                  // unit contact normal
  Vec3 relative_velocity;       // particle velocity minus wall velocity (projected here)
  Vec3 spring;                  // xi from the previous step (zero for a new contact)
  double normal_force = 0.0;    // N >= 0, see above
  double effective_mass = 0.0;  // for the tangential damping
  double dt = 0.0;
};

struct FrictionResult {
  Vec3 force;   // tangential force on the particle
  Vec3 spring;  // xi to store for the next step
  bool sliding = false;
};

FrictionResult coulomb_friction(const FrictionParams& params, const FrictionInput& in);

// The same with the tangential dashpot gamma_t = tangential_damping(params,
// in.effective_mass) given, for a caller that sums many contacts of one particle.
double tangential_damping(const FrictionParams& params, double effective_mass);
FrictionResult coulomb_friction(const FrictionParams& params, double gamma_t,
                                const FrictionInput& in);

}  // namespace contact
