#include "coupling/diagnostics/pore_diagnostics.h"

#include <algorithm>
#include <cmath>

#include "lbm/d3q19.h"
#include "lbm/macroscopic.h"

namespace coupling {

namespace {
constexpr double kPi = 3.14159265358979323846;
}

bool in_pore_region(const Vec3& x, const PoreRegion& pore) {
  const int a = pore.axis, b = (a + 1) % 3, c = (a + 2) % 3;
  const int lo = std::min(b, c), hi = std::max(b, c);
  if (x[a] < pore.start || x[a] > pore.end) return false;
  const double d0 = x[lo] - pore.centre[0], d1 = x[hi] - pore.centre[1];
  return d0 * d0 + d1 * d1 <= 0.25 * pore.diameter * pore.diameter;
}

Deposition deposited(const ParticleView& view, const std::vector<char>& bonded, const PoreRegion& pore,
                     const DepositionCriteria& criteria, const lbm::Communicator& comm,
                     const std::vector<char>* on_wall, const ParticleForcesAlongFlow& forces) {
  constexpr std::size_t kLadder = kDepositSpeedLadder.size();
  constexpr std::size_t kFluid = 3 + kLadder, kWall = kFluid + 1, kTotal = kWall + 1;
  // volume, count, on the wall, the count under each scaled threshold, then the fluid's, the
  // wall's and every force on the deposited particles: one reduction.
  std::array<double, kTotal + 1> sums{};
  const auto force_on = [](const std::vector<double>* f, std::size_t p) { return f && p < f->size() ? (*f)[p] : 0.0; };
  for (std::size_t p = 0; p < view.num_owned; ++p) {
    if (p >= bonded.size() || !bonded[p]) continue;
    if (!in_pore_region(view.x(p), pore)) continue;
    const Vec3 v = view.v(p);
    const double speed = std::sqrt(dot(v, v));
    for (std::size_t i = 0; i < kLadder; ++i)
      if (speed < kDepositSpeedLadder[i] * criteria.speed_threshold) sums[3 + i] += 1.0;
    if (speed >= criteria.speed_threshold) continue;
    const double R = view.r(p);
    sums[0] += 4.0 / 3.0 * kPi * R * R * R;
    sums[1] += 1.0;
    if (on_wall && p < on_wall->size() && (*on_wall)[p]) sums[2] += 1.0;
    sums[kFluid] += force_on(forces.fluid, p);
    sums[kWall] += force_on(forces.wall, p);
    sums[kTotal] += force_on(forces.total, p);
  }
  comm.sum(sums.data(), int(sums.size()));
  Deposition d;
  d.volume = sums[0];
  d.count = (long long)std::llround(sums[1]);
  d.on_wall = (long long)std::llround(sums[2]);
  for (std::size_t i = 0; i < kLadder; ++i) d.count_at_scaled_threshold[i] = (long long)std::llround(sums[3 + i]);
  d.fluid_force = sums[kFluid];
  d.wall_force = sums[kWall];
  d.total_force = sums[kTotal];
  d.length = pore.diameter > 0.0 ? d.volume / (kPi * pore.diameter * pore.diameter / 4.0) : 0.0;
  return d;
}

PlaneCrossingCounter::Crossings PlaneCrossingCounter::update(const ParticleView& view, double box_length,
                                                             const lbm::Communicator& comm) {
  double sums[2] = {0.0, 0.0};
  std::unordered_map<int, double> now;
  now.reserve(view.num_owned);
  for (std::size_t p = 0; p < view.num_owned; ++p) {
    const int id = view.identifier(p);
    const double x = view.x(p)[axis_];
    now[id] = x;
    const auto it = previous_.find(id);
    if (it == previous_.end()) continue;
    const double x0 = it->second;
    if (box_length > 0.0 && std::abs(x - x0) > 0.5 * box_length) continue;  // periodic wrap
    int sign = 0;
    if (x0 < position_ && x >= position_) sign = +1;
    if (x0 >= position_ && x < position_) sign = -1;
    if (sign == 0) continue;
    const double R = view.r(p);
    sums[0] += sign;
    sums[1] += sign * 4.0 / 3.0 * kPi * R * R * R;
  }
  previous_ = std::move(now);
  comm.sum(sums, 2);
  Crossings c;
  c.count = (long long)std::llround(sums[0]);
  c.volume = sums[1];
  return c;
}

double fluid_flux(const lbm::FluidSolver& solver, int axis, int index) {
  return lbm::plane_flux(solver, axis, index);
}

double pressure_loss(const lbm::FluidSolver& solver) { return lbm::pressure_loss(solver); }

double outlet_pressure(const lbm::FluidSolver& solver) {
  const lbm::FlowDrive& drive = solver.drive();
  const double rho_out =
      drive.kind == lbm::FlowDrive::kNone ? solver.parameters().rho0 : drive.outlet_density;
  return lbm::D3Q19::cs2 * rho_out;
}

double pressure_loss_in_outlet_units(const lbm::FluidSolver& solver) {
  return lbm::pressure_loss(solver) / outlet_pressure(solver);
}

}  // namespace coupling
