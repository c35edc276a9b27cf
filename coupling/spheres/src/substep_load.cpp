#include "coupling/force/substep_load.h"

#include <algorithm>
#include <cmath>

namespace coupling {

SubstepLoad SubstepLoadModel::at_substep(const SubstepLoadState& state, const Vec3& velocity,
                                         double radius) const {
  SubstepLoad load;
  const double C = state.coefficient, share = parameters_.share;
  for (int a = 0; a < 3; ++a) {
    load.hydrodynamic[a] = share * (state.force[a] - C * (velocity[a] - state.step_velocity[a]));
    load.torque[a] = share * state.torque[a];
  }
  if (parameters_.buoyancy) {
    const double volume = 4.0 / 3.0 * M_PI * radius * radius * radius;
    for (int a = 0; a < 3; ++a) load.buoyancy[a] = -(parameters_.fluid_density * volume * parameters_.gravity[a]);
  }
  return load;
}

void SubstepLoadModel::start_fluid_step(SubstepLoadState& state, bool owned) {
  if (owned) {
    state.previous_force = state.force;
    state.previous_velocity = state.step_velocity;
  }
  state.force = {0.0, 0.0, 0.0};
  state.torque = {0.0, 0.0, 0.0};
  state.coefficient = 0.0;
  state.step_velocity = {0.0, 0.0, 0.0};
}

void SubstepLoadModel::finish_fluid_step(SubstepLoadState& state, const Vec3& velocity,
                                         double mass) const {
  state.step_velocity = velocity;
  // The force's response to the velocity between the last two steps: -dF.dv / |dv|^2.
  double dv2 = 0.0, dFdv = 0.0;
  for (int a = 0; a < 3; ++a) {
    const double dv = state.step_velocity[a] - state.previous_velocity[a];
    dv2 += dv * dv;
    dFdv += (state.force[a] - state.previous_force[a]) * dv;
  }
  const double c_max = mass > 0.0 ? parameters_.max_coefficient_masses * mass / parameters_.dt_fluid
                                  : state.coefficient;
  const double secant = dv2 > 0.0 ? -dFdv / dv2 : 0.0;
  state.coefficient = std::clamp(secant, std::min(state.coefficient, c_max), c_max);
}

}  // namespace coupling
