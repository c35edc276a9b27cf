#pragma once
#include <string>

#include "lbm/input_error.h"

namespace lbm {

// Two-relaxation-time collision parameters (Ginzburg; Talon et al. 2012). The symmetric
// (even) part relaxes with omega_plus = 1/tau, which sets the viscosity nu = (tau - 1/2)/3;
// the antisymmetric (odd) part with omega_minus chosen from the "magic" parameter
//   Lambda = (1/omega_plus - 1/2) (1/omega_minus - 1/2).
// Lambda = 3/16 places a half-way bounce-back wall exactly mid-link for Poiseuille flow;
// Lambda = 1/4 is the most stable choice for advection.
struct TrtParameters {
  double omega_plus = 1.0;
  double omega_minus = 1.0;

  static TrtParameters from_tau(double tau, double magic) {
    if (!(tau > 0.5))
      throw InputError("tau = " + std::to_string(tau) + ": must be > 0.5 (viscosity > 0)");
    if (!(magic > 0.0) || magic > 10.0)
      throw InputError("magic = " + std::to_string(magic) + ": must be in (0, 10]");
    TrtParameters p;
    p.omega_plus = 1.0 / tau;
    p.omega_minus = 1.0 / (magic / (tau - 0.5) + 0.5);
    return p;
  }
  static double viscosity(double tau) { return (tau - 0.5) / 3.0; }
};

}  // namespace lbm
