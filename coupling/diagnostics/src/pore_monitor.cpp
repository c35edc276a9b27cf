#include "coupling/diagnostics/pore_monitor.h"

#include <algorithm>
#include <cmath>

#include "lbm/macroscopic.h"
#include "lbm/stability.h"

namespace coupling {

PoreMonitorSetup pore_scene_monitor(const lbm::PoreSceneSpec& spec) {
  const auto r = lbm::regions_of(spec);
  PoreMonitorSetup s;
  s.pore.axis = 0;
  s.pore.start = r.inlet_end - 0.5;
  s.pore.end = r.pore_end - 0.5;
  s.pore.centre = {r.axis_y, r.axis_z};
  s.pore.diameter = spec.pore_diameter;
  s.pore_diameter = spec.pore_diameter;
  s.inlet_plane = r.inlet_end - 0.5;
  s.outlet_plane = r.outlet_begin - 0.5;
  s.flow_length = r.outlet_end;
  return s;
}

PoreMonitorSetup voxel_geometry_monitor(const lbm::VoxelGeometry& geometry) {
  const auto& d = geometry.dims();
  PoreMonitorSetup s;
  s.pore.axis = 0;
  s.pore.start = -0.5;
  s.pore.end = d[0] - 0.5;
  s.pore.centre = {0.5 * (d[1] - 1), 0.5 * (d[2] - 1)};
  s.pore.diameter = 1e30;
  s.pore_diameter = lbm::narrowest_section_diameter(geometry);
  s.inlet_plane = 0.5;
  s.outlet_plane = d[0] - 1.5;
  s.flow_length = d[0];
  return s;
}

PoreMonitor::PoreMonitor(const PoreMonitorSetup& setup, const UnitConversion& units)
    : setup_(setup),
      units_(units),
      inlet_counter_(setup.pore.axis, setup.inlet_plane),
      outlet_counter_(setup.pore.axis, setup.outlet_plane),
      values_(kCount, 0.0) {}

void PoreMonitor::record_particles(const ParticleView& view, const std::vector<char>& bonded,
                                   double local_force_x, const lbm::Communicator& comm) {
  const double dx = units_.inputs().dx;
  const double volume_unit = dx * dx * dx;
  const auto deposit = deposited(view, bonded, setup_.pore, setup_.criteria, comm);
  auto& v = values_;
  v[kDepositedVolume] = deposit.volume * volume_unit;
  v[kDepositedCount] = double(deposit.count);
  // L_dep = V_dep / (pi D^2 / 4) with the pore's diameter (the equivalent one for a voxel file);
  // 0 for a geometry without an open section (no pore, no deposit length; not 0/0 = NaN).
  const double D = setup_.pore_diameter;
  v[kDepositedLength] = D > 0.0 ? deposit.volume / (M_PI * D * D / 4.0) * dx : 0.0;
  const auto in = inlet_counter_.update(view, setup_.flow_length, comm);
  const auto out = outlet_counter_.update(view, setup_.flow_length, comm);
  v[kParticlesIn] += double(in.count);
  v[kParticlesOut] += double(out.count);
  v[kParticlesInVolume] += in.volume * volume_unit;
  v[kParticlesOutVolume] += out.volume * volume_unit;
  double force_x = local_force_x;
  comm.sum(&force_x, 1);
  v[kHydroForceX] = force_x;
}

double PoreMonitor::value(int quantity, const lbm::FluidSolver& solver, long long fluid_steps) {
  if (quantity < 0 || quantity >= kCount) return 0.0;
  if (fluid_stale_) update_fluid(solver, fluid_steps);
  return values_[quantity];
}

void PoreMonitor::update_fluid(const lbm::FluidSolver& solver, long long fluid_steps) {
  fluid_stale_ = false;
  auto& v = values_;
  v[kPressureLoss] = units_.pressure_to_physical(lbm::pressure_loss(solver));
  // plane_flux is in lattice volume per lattice time step.
  const double dx = units_.inputs().dx;
  const double flux_unit = dx * dx * dx / units_.dt_lbm();
  const int last = solver.decomposition().global.size(setup_.pore.axis) - 1;
  v[kFluidFluxInlet] = lbm::plane_flux(solver, setup_.pore.axis, 0) * flux_unit;
  v[kFluidFluxOutlet] = lbm::plane_flux(solver, setup_.pore.axis, last) * flux_unit;
  const double speed = lbm::max_speed(solver);
  v[kMaxFluidSpeed] = units_.velocity_to_physical(speed);
  v[kLatticeMach] = speed / lbm::kSoundSpeed;
  v[kFluidSteps] = double(fluid_steps);
}

void PoreMonitor::restore(const double* values) { std::copy(values, values + kCount, values_.begin()); }

}  // namespace coupling
