#pragma once
// Diagnostics of the paper's clogging runs (Sec. III): pressure loss, deposited volume and
// length, particle and fluid flux through planes.
#include <array>
#include <unordered_map>
#include <vector>

#include "coupling/particle_view.h"
#include "coupling/periodic_box.h"
#include "lbm/fluid_solver.h"

namespace coupling {

// The pore (paper Fig. 1, region IV): a cylinder of diameter D along `axis` from `start` to
// `end`, its centre line through `centre` (the two coordinates other than `axis`, in
// ascending axis order). Lattice units.
struct PoreRegion {
  int axis = 0;
  double start = 0.0, end = 0.0;
  std::array<double, 2> centre{0.0, 0.0};
  double diameter = 0.0;
};

// A particle counts as deposited when
//   - it is bonded (cohesive bond to another particle or adhesive bond to the wall; the
//     caller's per-particle flag, from the contact models),
//   - its speed is below `speed_threshold` (default 1e-4 lattice units per fluid step:
//     about 1 % of the paper's inlet velocity, so it is at rest on the fluid time scale),
//   - its centre lies in the pore: start <= x_axis <= end and distance to the centre line
//     <= D/2 (the whole pore cross-section, "inside the pore radius").
// V_dep = sum of 4/3 pi R^3 over deposited owned particles (summed over ranks with the
// solver's communicator) and L_dep = V_dep / (pi D^2 / 4) (paper Sec. III).
// Under a velocity drive the threshold is this fraction of the inlet velocity: deposited
// particles are "at zero or very low velocity, such that moving flocks are not counted"
// (paper Sec. III); flocks move with the flow, at or above the inlet velocity, while
// particles in a clog creep far slower.
constexpr double kDepositSpeedFraction = 0.1;

struct DepositionCriteria {
  double speed_threshold = 1e-4;
};

// The deposit's sensitivity to its speed threshold: the same count with the threshold
// scaled by each of these factors (quartered to multiplied by 16), so one run shows how the
// count at a peak, and the law fitted to the bursts, move with the threshold.
constexpr std::array<double, 6> kDepositSpeedLadder{0.25, 0.5, 2.0, 4.0, 8.0, 16.0};

struct Deposition {
  double volume = 0.0;
  double length = 0.0;
  long long count = 0;
  long long on_wall = 0;  // of them, those the caller flags as touching the pore wall
  // The loads along the flow on the deposited particles alone (the caller's per-particle
  // forces, 0 where none are given): the deposit's own side of the paper's force balance,
  // which the totals over every particle in the box mix with the wall's push on particles
  // queued elsewhere (the outlet region, the pore's entrance face).
  double fluid_force = 0.0;
  double wall_force = 0.0;
  // Every force on the deposited particles (the caller's per-particle total): their mass
  // times their acceleration. What it leaves after the fluid's and the wall's is the push of
  // particles outside the deposit (contacts and cohesion across its edge; those within it
  // cancel in the sum).
  double total_force = 0.0;
  // Deposited counts under the threshold times kDepositSpeedLadder[i] (bonded, in the region).
  std::array<long long, kDepositSpeedLadder.size()> count_at_scaled_threshold{};
};

// Whether a lattice point lies in the deposit region: start <= x_axis <= end and within D/2
// of the centre line.
bool in_pore_region(const Vec3& x, const PoreRegion& pore);

// Per-particle forces along the flow, indexed like the view (either may be null).
struct ParticleForcesAlongFlow {
  const std::vector<double>* fluid = nullptr;  // the fluid's force on each particle
  const std::vector<double>* wall = nullptr;   // the wall's
  const std::vector<double>* total = nullptr;  // every force on it (contacts, wall, fluid)
};

// on_wall (indexed like the view, may be null): which particles touch the wall (within the
// adhesion range), to count the deposited ones that hold on to it directly. forces: summed
// over the deposited particles into Deposition::fluid_force, wall_force and total_force.
Deposition deposited(const ParticleView& view, const std::vector<char>& bonded, const PoreRegion& pore,
                     const DepositionCriteria& criteria, const lbm::Communicator& comm,
                     const std::vector<char>* on_wall = nullptr, const ParticleForcesAlongFlow& forces = {});

// Counts owned particles whose centre crossed the plane x_axis = position since the previous
// call (matched by id): +1 and +volume in the +axis direction, -1 and -volume back. Periodic
// wrap-around jumps larger than half the box are ignored. The first call only records.
class PlaneCrossingCounter {
 public:
  PlaneCrossingCounter(int axis, double position) : axis_(axis), position_(position) {}
  struct Crossings {
    long long count = 0;   // net number, + along the axis
    double volume = 0.0;   // net particle volume
  };
  Crossings update(const ParticleView& view, double box_length, const lbm::Communicator& comm);

 private:
  int axis_;
  double position_;
  std::unordered_map<int, double> previous_;
};

// Fluid flux through a plane and the pressure loss, forwarded from lbm/ so the host reads all
// diagnostics from one place.
double fluid_flux(const lbm::FluidSolver& solver, int axis, int index);
double pressure_loss(const lbm::FluidSolver& solver);

// The pressure loss as the paper reports it, in units of the outlet pressure
// P_out = rho_out c_s^2 (rho_out: the density the drive imposes at the outlet, rho0 without
// a drive). With rho_out = 1, P / P_out = 3 Delta p = rho_in - rho_out (doc/references.md).
double outlet_pressure(const lbm::FluidSolver& solver);
double pressure_loss_in_outlet_units(const lbm::FluidSolver& solver);

}  // namespace coupling
