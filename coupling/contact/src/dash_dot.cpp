#include "contact/dash_dot.h"

#include <cmath>

namespace contact {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

double restitution_coefficient(double damping_ratio) {
  if (damping_ratio >= 1.0) return 0.0;  // over-damped: no rebound
  return std::exp(-kPi * damping_ratio / std::sqrt(1.0 - damping_ratio * damping_ratio));
}

double contact_duration(const DashDotParams& params, double effective_mass) {
  // t_c = pi / (omega_0 sqrt(1 - zeta^2)), omega_0 = sqrt(k/m_eff).
  const double zeta = params.damping_ratio < 1.0 ? params.damping_ratio : 0.999;
  const double omega0 = std::sqrt(params.k_n / effective_mass);
  return kPi / (omega0 * std::sqrt(1.0 - zeta * zeta));
}

double stability_limit(const DashDotParams& params, double effective_mass) {
  return 2.0 * std::sqrt(effective_mass / params.k_n);
}

}  // namespace contact
