#include "lbm/capped_drive.h"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "lbm/d3q19.h"
#include "lbm/input_error.h"
#include "lbm/macroscopic.h"
#include "lbm/stability.h"

namespace lbm {

DriveFaces read_drive_faces(const FluidSolver& solver) {
  DriveFaces faces;
  faces.pressure_loss = pressure_loss(solver);
  // This rank's inlet mass of the step, its nodes' density sum and count, and its outlet
  // mass (nothing where the rank has no such face or the step did not set it).
  double sums[4] = {0.0, 0.0, 0.0, 0.0};
  if (solver.add_open_face_densities(0, sums + 1)) sums[0] = solver.open_face_mass(0);
  double outlet[2] = {0.0, 0.0};
  if (solver.add_open_face_densities(1, outlet)) sums[3] = -solver.open_face_mass(1);
  solver.decomposition().comm.sum(sums, 4);
  // The mass a node's momentum carries: rho u, or rho0 u with He & Luo's incompressible
  // equilibrium (OpenFace::momentum_density), so that a velocity inlet reads its velocity.
  faces.inlet_carried_mass = solver.parameters().incompressible ? solver.parameters().rho0 * sums[2] : sums[1];
  if (faces.inlet_carried_mass > 0.0) faces.inlet_velocity = sums[0] / faces.inlet_carried_mass;
  faces.outflow = sums[3];
  return faces;
}

CappedVelocityDrive::CappedVelocityDrive(const FluidSolver& solver, const FlowDrive& velocity_drive,
                                         double max_pressure_loss)
    : velocity_drive_(velocity_drive),
      max_pressure_loss_(max_pressure_loss),
      inlet_velocity_(velocity_drive.inlet_velocity) {
  if (velocity_drive.kind != FlowDrive::kInletVelocity || !(velocity_drive.inlet_velocity > 0.0))
    throw InputError("capped drive: the pressure loss can only cap a velocity inlet with a velocity > 0");
  if (!(max_pressure_loss > 0.0))
    throw InputError("capped drive: the largest pressure loss must be > 0 (lattice units)");
  FlowDrive pressure = velocity_drive;
  pressure.kind = FlowDrive::kPressureLoss;
  pressure.pressure_loss = max_pressure_loss;
  const std::string violation = drive_limit_violation(pressure);
  if (!violation.empty()) throw InputError("capped drive: the largest pressure loss is " + violation);
  const VoxelGeometry& geometry = solver.geometry();
  const auto dims = geometry.dims();
  long long fluid = 0;
  for (int k = 0; k < dims[2]; ++k)
    for (int j = 0; j < dims[1]; ++j)
      for (int i = 0; i < dims[0]; ++i) fluid += !geometry.is_solid(i, j, k);
  compliance_ = double(fluid) / D3Q19::cs2;
  transit_steps_ = dims[std::size_t(velocity_drive.axis)] / kSoundSpeed;
}

void CappedVelocityDrive::impose(FluidSolver& solver) {
  FlowDrive drive = velocity_drive_;
  drive.inlet_velocity = inlet_velocity_;
  solver.set_drive(drive);
}

DriveFaces CappedVelocityDrive::update(FluidSolver& solver) {
  const DriveFaces faces = read_drive_faces(solver);
  if (!(faces.inlet_carried_mass > 0.0)) return faces;  // faces not set by a step: nothing read
  mean_outflow_ += (faces.outflow - mean_outflow_) / transit_steps_;
  const double relaxation = kRelaxationTransits * transit_steps_;
  const double inflow = mean_outflow_ + compliance_ * (max_pressure_loss_ - faces.pressure_loss) / relaxation;
  // Every rank read the same reduced values: every rank sets the same velocity.
  inlet_velocity_ = std::clamp(inflow / faces.inlet_carried_mass, 0.0, max_inlet_velocity());
  impose(solver);
  return faces;
}

double drive_inlet_velocity(const FluidSolver& solver, const CappedVelocityDrive* capped) {
  if (capped) return capped->inlet_velocity();
  if (solver.drive().kind == FlowDrive::kInletVelocity) return solver.drive().inlet_velocity;
  return read_drive_faces(solver).inlet_velocity;
}

std::vector<double> CappedVelocityDrive::state() const { return {inlet_velocity_, mean_outflow_}; }

void CappedVelocityDrive::set_state(const std::vector<double>& state, FluidSolver& solver) {
  if (state.size() != 2)
    throw std::invalid_argument("capped drive: a state of " + std::to_string(state.size()) + " values, expected 2");
  inlet_velocity_ = state[0];
  mean_outflow_ = state[1];
  impose(solver);
}

}  // namespace lbm
