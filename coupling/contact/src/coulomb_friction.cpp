#include "contact/coulomb_friction.h"

#include "contact/dash_dot.h"

namespace contact {

double tangential_damping(const FrictionParams& params, double effective_mass) {
  // The dashpot of the tangential oscillator, damped like the normal one (dash_dot.h).
  return damping_coefficient(DashDotParams{params.k_t, params.damping_ratio}, effective_mass);
}

FrictionResult coulomb_friction(const FrictionParams& params, const FrictionInput& in) {
  return coulomb_friction(params, tangential_damping(params, in.effective_mass), in);
}

FrictionResult coulomb_friction(const FrictionParams& params, double gamma_t,
                                const FrictionInput& in) {
  FrictionResult out;
  // Rotate the stored spring into the current tangent plane, keeping its length.
  Vec3 spring = tangential_part(in.spring, in.normal);
  const double old_length = norm(in.spring);
  const double new_length = norm(spring);
  if (new_length > 0.0) spring = (old_length / new_length) * spring;

  const Vec3 slip_velocity = tangential_part(in.relative_velocity, in.normal);
  spring += in.dt * slip_velocity;

  Vec3 force = -params.k_t * spring - gamma_t * slip_velocity;
  const double limit = params.mu * in.normal_force;
  const double magnitude = norm(force);
  if (magnitude > limit) {
    // Sliding: dynamic Coulomb force opposite the trial force, spring carries all of it.
    force = magnitude > 0.0 ? (limit / magnitude) * force : Vec3{};
    spring = params.k_t > 0.0 ? (-1.0 / params.k_t) * force : Vec3{};
    out.sliding = true;
  }
  out.force = force;
  out.spring = spring;
  return out;
}

}  // namespace contact
