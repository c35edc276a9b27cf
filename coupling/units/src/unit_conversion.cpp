#include "coupling/unit_conversion.h"

#include <cmath>
#include <cstdio>

#include "lbm/input_error.h"

namespace coupling {

namespace {
std::string number(double v) {
  char buffer[64];
  std::snprintf(buffer, sizeof buffer, "%.6g", v);
  return buffer;
}
void require_positive(double v, const char* keyword) {
  if (!(v > 0.0)) throw lbm::InputError(std::string(keyword) + " = " + number(v) + ": must be > 0");
}
}  // namespace

UnitConversion::UnitConversion(const UnitInputs& in, double tau_max) : in_(in) {
  require_positive(in.dx, "dx");
  require_positive(in.rho, "rho");
  require_positive(in.nu, "nu");
  require_positive(in.dt_dem, "timestep");
  if (in.n_dem < 1 || in.n_dem > 100000)
    throw lbm::InputError("n_dem = " + std::to_string(in.n_dem) + ": must be in [1, 100000]");
  dt_lbm_ = in.n_dem * in.dt_dem;
  nu_lattice_ = in.nu * dt_lbm_ / (in.dx * in.dx);
  tau_ = 3.0 * nu_lattice_ + 0.5;
  if (!(tau_ > 0.5 + 1e-6) || tau_ > tau_max)
    throw lbm::InputError(
        "tau = 3 nu dt_lbm / dx^2 + 1/2 = " + number(tau_) + " (nu = " + number(in.nu) +
        ", dt_lbm = n_dem * timestep = " + number(dt_lbm_) + ", dx = " + number(in.dx) +
        "): must be in (0.5, " + number(tau_max) +
        "]; change nu, dx, n_dem or the timestep (tau = 1 at dt_lbm = dx^2 / (6 nu))");
}

void UnitConversion::check_same_tau(const UnitConversion& later) const {
  if (std::abs(later.tau() - tau_) > 1e-12)
    throw lbm::InputError("the DEM time step or n_dem changed between runs (tau " + std::to_string(tau_) +
                          " -> " + std::to_string(later.tau()) +
                          "); the fluid's relaxation time is fixed once the lattice exists");
}

std::string UnitConversion::summary() const {
  return "tau = " + number(tau_) + ", nu_lattice = " + number(nu_lattice_) +
         ", dt_lbm = " + number(dt_lbm_) + " (n_dem = " + std::to_string(in_.n_dem) +
         " x dt_dem = " + number(in_.dt_dem) + "), dx = " + number(in_.dx);
}

}  // namespace coupling
