#pragma once
// Dash-dot (linear spring-dashpot) normal contact, paper Eq. (1): F_n = k_n delta + k_d delta_dot.
//
// Damping convention: we take the damping *ratio* zeta (fraction of critical damping) as
// input, with critical damping c_crit = 2 sqrt(k m_eff), so k_d = 2 zeta sqrt(k m_eff).
// The paper's table gives k_d = 0.5 sqrt(k_n m_eff) (particle-particle, m_eff = mi mj/(mi+mj))
// and k_q = 0.5 sqrt(k_w m_i) (particle-wall): that is zeta = 0.25, our default. (Its text
// says "half of the critical damping", which would be zeta = 0.5 with the usual c_crit; we
// follow the table's formula.)
//
// The force is not clipped at zero while the particles separate: the analytic restitution
// e = exp(-pi zeta / sqrt(1 - zeta^2)) holds for exactly this unclipped linear law, and the
// small attraction at the end of a contact is what the paper's Eq. (1) gives.
//
// The force functions are inline: they run in the pair style's and the wall fix's inner loops.
#include <cmath>

namespace contact {

struct DashDotParams {
  double k_n = 0.1;            // normal stiffness (force/length); paper: k_n = k_w = 0.1
  double damping_ratio = 0.25;  // zeta = k_d / (2 sqrt(k_n m_eff)); paper table: 0.25
};

struct NormalContactInput {
  double overlap = 0.0;         // delta > 0 when the bodies overlap
  double overlap_rate = 0.0;    // d(delta)/dt > 0 while approaching
  double effective_mass = 0.0;  // mi mj/(mi+mj) for two particles, m_i against a wall
};

// Critical damping 2 sqrt(k m_eff) times zeta: k_d of the pair, k_q of the wall (paper table),
// and the tangential dashpot of the friction spring (with k_t in place of k_n).
inline double damping_coefficient(const DashDotParams& params, double effective_mass) {
  return 2.0 * params.damping_ratio * std::sqrt(params.k_n * effective_mass);
}

// Paper Eq. (1), F_n = k_n delta + k_d delta_dot; repulsive positive. Zero when delta <= 0
// (no contact).
// With the damping coefficient k_d = damping_coefficient(params, in.effective_mass) given: a
// caller with many contacts of one particle computes it (and its square root) once.
inline double dash_dot_force(const DashDotParams& params, double damping,
                             const NormalContactInput& in) {
  if (in.overlap <= 0.0) return 0.0;
  return params.k_n * in.overlap + damping * in.overlap_rate;
}

inline double dash_dot_force(const DashDotParams& params, const NormalContactInput& in) {
  if (in.overlap <= 0.0) return 0.0;
  return dash_dot_force(params, damping_coefficient(params, in.effective_mass), in);
}

// Analytic figures of the linear contact (doc/references.md, "Linear spring-dashpot"):
double restitution_coefficient(double damping_ratio);               // e(zeta)
double contact_duration(const DashDotParams& params, double effective_mass);  // t_c
// Largest stable explicit step dt < 2 sqrt(m_eff/k) of the undamped oscillator.
double stability_limit(const DashDotParams& params, double effective_mass);

}  // namespace contact
