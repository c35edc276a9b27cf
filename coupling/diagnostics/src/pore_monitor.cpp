#include "coupling/diagnostics/pore_monitor.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "lbm/macroscopic.h"
#include "lbm/node_type.h"
#include "lbm/stability.h"

namespace coupling {

PoreMonitorSetup pore_scene_monitor(const lbm::PoreSceneSpec& spec, DepositRegion region) {
  const auto r = lbm::regions_of(spec);
  PoreMonitorSetup s;
  s.pore.axis = 0;
  s.pore.start = (region == DepositRegion::kPore ? r.pore_begin : r.inlet_end) - 0.5;
  s.pore.end = r.pore_end - 0.5;
  s.pore.centre = {r.axis_y, r.axis_z};
  s.pore.diameter = spec.pore_diameter;
  s.pore_diameter = spec.pore_diameter;
  s.inlet_plane = r.inlet_end - 0.5;
  s.outlet_plane = r.outlet_begin - 0.5;
  s.flow_length = r.outlet_end;
  s.upstream_plane = r.pore_begin - 1;
  s.downstream_plane = r.pore_end;
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
      values_(kCount, 0.0),
      detector_(setup.bursts) {}

void PoreMonitor::record_particles(const ParticleView& view, const std::vector<char>& bonded,
                                   const std::vector<char>& on_wall, const ParticleLoads& local,
                                   const lbm::Communicator& comm) {
  const double dx = units_.inputs().dx;
  const double volume_unit = dx * dx * dx;
  const auto given = [](const std::vector<double>& f) { return f.empty() ? nullptr : &f; };
  const ParticleForcesAlongFlow per_particle{given(local.fluid_along_flow), given(local.wall_along_flow),
                                            given(local.total_along_flow)};
  const auto deposit = deposited(view, bonded, setup_.pore, setup_.criteria, comm, &on_wall, per_particle);
  values_[kDepositedOnWall] = double(deposit.on_wall);
  values_[kDepositFluidForceX] = deposit.fluid_force;
  values_[kDepositWallForceX] = deposit.wall_force;
  values_[kDepositTotalForceX] = deposit.total_force;
  auto& v = values_;
  for (std::size_t i = 0; i < kDepositSpeedLadder.size(); ++i)
    v[kDepositedCountScaledSpeed + i] = double(deposit.count_at_scaled_threshold[i]);
  if (speed_every_ > 0) {
    step_speeds_.clear();
    step_speeds_.add(view, bonded, on_wall, setup_.pore);
  }
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
  double forces[2] = {local.fluid_force, local.wall_force};
  comm.sum(forces, 2);
  v[kHydroForceX] = forces[0];
  v[kWallForceX] = forces[1];
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
  const lbm::LatticeTotals totals = lbm::lattice_totals(solver);
  v[kMaxFluidSpeed] = units_.velocity_to_physical(totals.max_speed);
  v[kLatticeMach] = totals.max_speed / lbm::kSoundSpeed;
  v[kFluidSteps] = double(fluid_steps);
  v[kFluidMassHeld] = totals.mass / solver.parameters().rho0 * fluid_mass_unit();
  v[kParticleDisplacedMass] = double(totals.moving_nodes) * fluid_mass_unit();
  v[kPressureLossAcrossPore] = 0.0;
  if (setup_.upstream_plane >= 0 && setup_.downstream_plane >= 0)
    v[kPressureLossAcrossPore] = (lbm::plane_mean_pressure(solver, setup_.pore.axis, setup_.upstream_plane) -
                                  lbm::plane_mean_pressure(solver, setup_.pore.axis, setup_.downstream_plane)) /
                                 outlet_pressure(solver);
}

// Host mass of one lattice cell of fluid at the reference density.
double PoreMonitor::fluid_mass_unit() const {
  const double dx = units_.inputs().dx;
  return units_.inputs().rho * dx * dx * dx;
}

// The mass the step's streaming moved through the open faces (FluidSolver::open_face_mass:
// exact, from the populations that crossed them) and what the coupling put in (recorded by
// record_coupling_mass), over all ranks in one reduction.
void PoreMonitor::add_plane_masses(const lbm::FluidSolver& solver) {
  double sums[4] = {solver.open_face_mass(0), solver.open_face_mass(1), coupling_mass_[0],
                    coupling_mass_[1]};
  coupling_mass_[0] = coupling_mass_[1] = 0.0;
  solver.decomposition().comm.sum(sums, 4);
  const double unit = fluid_mass_unit() / solver.parameters().rho0;
  values_[kFluidMassIn] += sums[0] * unit;
  values_[kFluidMassOut] -= sums[1] * unit;
  values_[kParticleSurfaceMass] += sums[2] * unit;
  values_[kParticleRefillMass] += sums[3] * unit;
}

void PoreMonitor::record_coupling_mass(double surface_mass, double refill_mass) {
  coupling_mass_[0] += surface_mass;
  coupling_mass_[1] += refill_mass;
}

std::optional<BurstRecord> PoreMonitor::record_fluid_step(const lbm::FluidSolver& solver, long long fluid_step,
                                                          long long step, double time) {
  const double pressure = pressure_loss_in_outlet_units(solver);
  values_[kPressureLossOutlet] = pressure;
  if (fluid_step <= last_burst_sample_) return std::nullopt;
  // Fluid step 0 (the setup of the first run) has moved no fluid yet.
  if (fluid_step > 0) add_plane_masses(solver);
  last_burst_sample_ = fluid_step;
  PressureSample sample;
  sample.fluid_step = fluid_step;
  sample.step = step;
  sample.time = time;
  sample.pressure_loss = pressure;
  sample.deposited_volume = values_[kDepositedVolume];
  sample.deposited_length = values_[kDepositedLength];
  sample.deposited_count = static_cast<long long>(values_[kDepositedCount]);
  sample.wall_force = values_[kWallForceX];
  sample.deposited_on_wall = static_cast<long long>(values_[kDepositedOnWall]);
  // P pi D^2 / 4: the pressure loss's push on the pore's cross-section (paper, theory section).
  const double D = setup_.pore_diameter * units_.inputs().dx;
  sample.pressure_force = units_.pressure_to_physical(pressure * outlet_pressure(solver)) * M_PI * D * D / 4.0;
  auto burst = detector_.add(sample);
  values_[kLargestPressureLoss] = detector_.largest_pressure_loss();
  if (burst && !eroded_a_deposit(*burst)) burst.reset();
  if (burst) bursts_.push_back(*burst);
  values_[kBurstCount] = double(bursts_.size());
  if (burst && burst_file_) burst_file_->write(*burst);
  if (speed_every_ > 0) take_deposit_speeds(solver, fluid_step);
  return burst;
}

void PoreMonitor::write_deposit_speeds_to(const std::string& path, long long every, bool append) {
  speed_every_ = every;
  speed_first_step_ = -1;
  if (!path.empty())
    speed_file_ = std::make_unique<DepositSpeedFileWriter>(path, 1.0 / units_.inputs().dx, units_.dt_lbm(), append);
}

// The step's speeds join the interval (a fluid step already recorded, the setup of a later
// run, adds none); at the end of each interval of speed_every_ fluid steps (counted from
// fluid step 0, so a resumed run keeps the intervals of an uninterrupted one; its first may be
// shorter, and the counts of an interval cut short by the run's end are not written) they go
// to the file.
void PoreMonitor::take_deposit_speeds(const lbm::FluidSolver& solver, long long fluid_step) {
  speeds_.add(step_speeds_);
  step_speeds_.clear();
  if (speed_first_step_ < 0) speed_first_step_ = fluid_step;
  if (fluid_step == 0 || fluid_step % speed_every_ != 0) return;
  const std::vector<double> counts = speeds_.take(solver.decomposition().comm);
  if (speed_file_) speed_file_->write(speed_first_step_, fluid_step, counts);
  speed_first_step_ = -1;
}

void PoreMonitor::write_bursts_to(const std::string& path, const BurstUnits& units, bool append) {
  burst_file_ = std::make_unique<BurstFileWriter>(path, units, append);
}

double PoreMonitor::burst_value(int row, int column) const {
  if (row < 0 || row >= int(bursts_.size()) || column < 0 || column >= BurstRecord::kColumns) return 0.0;
  return bursts_[std::size_t(row)].row()[std::size_t(column)];
}

std::vector<double> PoreMonitor::state() const {
  std::vector<double> state{double(kCount)};
  state.insert(state.end(), values_.begin(), values_.end());
  state.push_back(double(last_burst_sample_));
  const auto detector = detector_.state();
  state.insert(state.end(), detector.begin(), detector.end());
  return state;
}

void PoreMonitor::restore(const std::vector<double>& state) {
  // Restart files written before the wall's hold was recorded hold the first
  // kWallForceX values; the hold then starts at 0 and is recorded from the next fluid step.
  // Files written before the pressure across the pore and the threshold ladder were recorded
  // hold the first kPressureLossAcrossPore, those written before the deposit's own loads the
  // first kDepositFluidForceX, those before every force on the deposit the first
  // kDepositTotalForceX; the rest start at 0 and are recorded from the next fluid step.
  const std::size_t count = state.empty() ? 0 : std::size_t(state[0]);
  const bool known = count == std::size_t(kCount) || count == std::size_t(kDepositTotalForceX) ||
                     count == std::size_t(kDepositFluidForceX) ||
                     count == std::size_t(kPressureLossAcrossPore) || count == std::size_t(kWallForceX);
  if (!known || state.size() < count + 2)
    throw std::invalid_argument(
        "pore monitor: the restart file holds another set of diagnostics (written by another "
        "version of lbm-pore, " +
        std::to_string(kCount) + " values expected); restart from a file written by this one");
  std::fill(values_.begin(), values_.end(), 0.0);
  std::copy(state.begin() + 1, state.begin() + 1 + count, values_.begin());
  last_burst_sample_ = static_cast<long long>(state[count + 1]);
  detector_.restore(std::vector<double>(state.begin() + count + 2, state.end()));
  keep_erosive_bursts();
}

void PoreMonitor::keep_erosive_bursts() {
  bursts_.clear();
  for (const BurstRecord& burst : detector_.bursts())
    if (eroded_a_deposit(burst)) bursts_.push_back(burst);
}

// A fall is an erosive burst when a deposit was there to tear off: at the peak, or over the
// window before it (a deposit that has begun to slide at the peak drops out of the count
// there; BurstRecord::deposit_count).
bool PoreMonitor::eroded_a_deposit(const BurstRecord& burst) const {
  return std::max(burst.count_before, burst.deposit_count) >= setup_.burst_min_deposited;
}

}  // namespace coupling
