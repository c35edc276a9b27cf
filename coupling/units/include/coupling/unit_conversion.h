#pragma once
#include <string>

namespace coupling {

// Converts between the units of a LIGGGHTS script (any consistent system: si, cgs, or the
// paper's lattice units) and lattice units (dx = dt = rho = 1).
// The user gives the lattice spacing dx, the fluid density rho and kinematic viscosity nu;
// the DEM time step dt_dem comes from the script's `timestep`, and the fluid advances once
// every n_dem DEM steps (paper: N_DEM = 100), so dt_lbm = n_dem * dt_dem and
//   nu_lattice = nu dt_lbm / dx^2,  tau = 3 nu_lattice + 1/2.
struct UnitInputs {
  double dx = 1.0;
  double rho = 1.0;
  double nu = 1.0 / 6.0;
  double dt_dem = 0.01;
  int n_dem = 100;
};

class UnitConversion {
 public:
  // Throws lbm::InputError naming the keyword (dx, rho, nu, n_dem, timestep) and its range,
  // including the resulting tau when it falls outside (0.5, tau_max].
  explicit UnitConversion(const UnitInputs& in, double tau_max = 10.0);

  double tau() const { return tau_; }
  double dt_lbm() const { return dt_lbm_; }
  double nu_lattice() const { return nu_lattice_; }
  const UnitInputs& inputs() const { return in_; }

  // physical -> lattice
  double length_to_lattice(double l) const { return l / in_.dx; }
  double velocity_to_lattice(double v) const { return v * dt_lbm_ / in_.dx; }
  double pressure_to_lattice(double p) const { return p / pressure_unit(); }
  double density_to_lattice(double r) const { return r / in_.rho; }
  // lattice -> physical
  double length_to_physical(double l) const { return l * in_.dx; }
  double velocity_to_physical(double v) const { return v * in_.dx / dt_lbm_; }
  double force_to_physical(double f) const { return f * force_unit(); }
  double torque_to_physical(double t) const { return t * force_unit() * in_.dx; }
  double pressure_to_physical(double p) const { return p * pressure_unit(); }
  double time_to_physical(double steps) const { return steps * dt_lbm_; }

  // One lattice unit of force: rho dx^4 / dt^2; of pressure: rho dx^2 / dt^2.
  double force_unit() const { return in_.rho * in_.dx * in_.dx * in_.dx * in_.dx / (dt_lbm_ * dt_lbm_); }
  double pressure_unit() const { return in_.rho * in_.dx * in_.dx / (dt_lbm_ * dt_lbm_); }
  // One lattice unit of torque: a force unit times dx.
  double torque_unit() const { return force_unit() * in_.dx; }
  // One lattice unit of a force-velocity coefficient (the coupling's C, force per velocity):
  // a force unit over a velocity unit, force_unit dt / dx.
  double velocity_coefficient_unit() const { return force_unit() * dt_lbm_ / in_.dx; }

  // For a host that converts whole arrays (every particle at every fluid step), one factor
  // to multiply each value by: velocity -> lattice, dt / dx (v * factor may differ from
  // velocity_to_lattice(v) in the last bit); angular velocity -> lattice (radians per fluid
  // step), dt.
  double velocity_to_lattice_factor() const { return dt_lbm_ / in_.dx; }
  double angular_velocity_to_lattice_factor() const { return dt_lbm_; }

  // A one-line summary for the setup printout (tau, nu, time steps).
  std::string summary() const;

  // The fluid's relaxation time is fixed once its lattice exists: throws lbm::InputError
  // when `later` (a later run's time step or n_dem) gives another tau than this.
  void check_same_tau(const UnitConversion& later) const;

 private:
  UnitInputs in_;
  double dt_lbm_ = 1.0, nu_lattice_ = 1.0 / 6.0, tau_ = 1.0;
};

}  // namespace coupling
