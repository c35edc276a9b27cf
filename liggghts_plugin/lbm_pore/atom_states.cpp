#include "atom_states.h"

#include "coupling/diagnostics/bonds.h"

namespace lbm_pore {

void AtomStates::reset(int i, double tag) {
  (*this)[i] = AtomCouplingState{};
  (*this)[i].tag = tag;
}

AtomCouplingState& AtomStates::own(int i, double tag) {
  if ((*this)[i].tag != tag) reset(i, tag);
  return (*this)[i];
}

AtomArrays AtomStates::seen_by_fluid(const AtomArrays& atoms) {
  const int ntotal = atoms.nlocal + atoms.nghost;
  fluid_velocity_rows_.resize(static_cast<std::size_t>(ntotal));
  for (int i = 0; i < ntotal; ++i) fluid_velocity_rows_[i] = (*this)[i].fluid_velocity.data();
  AtomArrays seen = atoms;
  seen.v = fluid_velocity_rows_.data();
  return seen;
}

void AtomStates::find_walls(const AtomArrays& atoms, const contact::VoxelSurface& surface, double reach,
                            std::vector<contact::SurfacePoint>& scratch) {
  for (int i = 0; i < atoms.nlocal; ++i) {
    coupling::NearestWall& wall = own(i, atoms.tag[i]).wall;
    if (atoms.mask && !(atoms.mask[i] & atoms.groupbit)) {
      wall.known = false;
      continue;
    }
    const double* x = atoms.x[i];
    wall = coupling::find_nearest_wall(surface, {x[0], x[1], x[2]}, atoms.radius[i] + reach, scratch);
  }
}

void AtomStates::add_substep_loads(const coupling::SubstepLoadModel& model, const AtomArrays& atoms, double** f,
                                   double** torque, bool buoyancy, double** hydrodynamic) {
  for (int i = 0; i < atoms.nlocal; ++i) {
    hydrodynamic[i][0] = hydrodynamic[i][1] = hydrodynamic[i][2] = 0.0;
    if (atoms.mask && !(atoms.mask[i] & atoms.groupbit)) continue;
    const double* v = atoms.v[i];
    const auto load = model.at_substep(own(i, atoms.tag[i]).load, {v[0], v[1], v[2]}, atoms.radius[i]);
    for (int a = 0; a < 3; ++a) f[i][a] += load.hydrodynamic[a];
    for (int a = 0; a < 3; ++a) hydrodynamic[i][a] = load.hydrodynamic[a];
    if (torque)
      for (int a = 0; a < 3; ++a) torque[i][a] += load.torque[a];
    if (buoyancy)
      for (int a = 0; a < 3; ++a) f[i][a] += load.buoyancy[a];
  }
}

void AtomStates::add_lubrication(const coupling::LubricationKernel& kernel, const AtomArrays& atoms,
                                 const std::vector<coupling::ParticlePair>& pairs, double** f,
                                 double** hydrodynamic) {
  const coupling::ParticleView view = host_view(atoms);
  force_before_.assign(f[0], f[0] + 3 * atoms.nlocal);
  kernel.add_pair_forces(view, pairs, f[0]);
  static const coupling::NearestWall kNoWall;
  const auto wall_of = [&](std::size_t i) -> const coupling::NearestWall& {
    return (!atoms.mask || (atoms.mask[i] & atoms.groupbit)) ? (*this)[int(i)].wall : kNoWall;
  };
  kernel.add_wall_forces(view, wall_of, f[0]);
  for (int i = 0; i < atoms.nlocal; ++i)
    for (int a = 0; a < 3; ++a) hydrodynamic[i][a] += f[i][a] - force_before_[3 * i + a];
}

double AtomStates::mark_deposits(const LatticeParticles& particles, const AtomArrays& atoms,
                                 const std::vector<char>& bonded_atoms, bool walls_followed,
                                 const contact::VoxelSurface& surface, std::vector<contact::SurfacePoint>& scratch,
                                 std::vector<char>& bonded, std::vector<char>& on_wall,
                                 std::vector<double>& fluid_along_flow) const {
  const std::size_t total = particles.size(), owned = particles.num_owned();
  bonded.assign(total, 0);
  on_wall.assign(total, 0);
  fluid_along_flow.assign(total, 0.0);
  double fluid_force = 0.0;
  for (std::size_t p = 0; p < total; ++p) {
    const int i = particles.atom(p);
    if (p >= owned) {
      bonded[p] = bonded_atoms[i];
      continue;
    }
    fluid_along_flow[p] = (*this)[i].load.force[0];
    fluid_force += fluid_along_flow[p];
    const double* x = atoms.x[i];
    on_wall[p] = coupling::touches_wall(walls_followed ? &(*this)[i].wall : nullptr, surface, {x[0], x[1], x[2]},
                                        atoms.radius[i], scratch);
    bonded[p] = bonded_atoms[i] || on_wall[p];
  }
  return fluid_force;
}

void AtomStates::start_fluid_step(int nlocal, int ntotal) {
  for (int i = 0; i < ntotal; ++i) coupling::SubstepLoadModel::start_fluid_step((*this)[i].load, i < nlocal);
}

void AtomStates::store_loads(const LatticeParticles& particles, const coupling::HydrodynamicLoads& loads,
                             const coupling::UnitConversion& units) {
  const double force_unit = units.force_unit(), torque_unit = units.torque_unit();
  const double coefficient_unit = units.velocity_coefficient_unit();
  for (std::size_t p = 0; p < particles.size(); ++p) {
    coupling::SubstepLoadState& load = (*this)[particles.atom(p)].load;
    for (int a = 0; a < 3; ++a) {
      load.force[a] = loads.force[p][a] * force_unit;
      load.torque[a] = loads.torque[p][a] * torque_unit;
    }
    load.coefficient = loads.velocity_coefficient[p] * coefficient_unit;
  }
}

void AtomStates::finish_fluid_step(const coupling::SubstepLoadModel& model, const AtomArrays& atoms,
                                   const double* rmass) {
  for (int i = 0; i < atoms.nlocal; ++i) {
    const double* v = atoms.v[i];
    model.finish_fluid_step((*this)[i].load, {v[0], v[1], v[2]}, rmass ? rmass[i] : 0.0);
  }
}

int AtomStates::pack_exchange(int i, double* buf) const {
  (*this)[i].pack(buf);
  return AtomCouplingState::kDoubles;
}

int AtomStates::unpack_exchange(int i, const double* buf) {
  (*this)[i].unpack(buf);
  return AtomCouplingState::kDoubles;
}

int AtomStates::pack_restart(int i, double* buf) const {
  buf[0] = kRestart;
  (*this)[i].pack(buf + 1);
  return kRestart;
}

bool AtomStates::unpack_restart(int i, const double* entry) {
  const int size = static_cast<int>(entry[0]);
  if (size != kRestart && size != AtomCouplingState::kDoubles1 + 1) return false;
  (*this)[i].unpack(entry + 1, size - 1);
  return true;
}

int AtomStates::pack_forward(int n, const int* list, double* const* omega, double* buf) const {
  int m = 0;
  for (int k = 0; k < n; ++k) {
    const int i = list[k];
    for (int a = 0; a < 3; ++a) buf[m++] = (*this)[i].fluid_velocity[a];
    for (int a = 0; a < 3; ++a) buf[m++] = omega ? omega[i][a] : 0.0;
  }
  return kForward;
}

void AtomStates::unpack_forward(int n, int first, double* const* omega, const double* buf) {
  int m = 0;
  for (int i = first; i < first + n; ++i) {
    for (int a = 0; a < 3; ++a) (*this)[i].fluid_velocity[a] = buf[m++];
    for (int a = 0; a < 3; ++a) {
      if (omega) omega[i][a] = buf[m];
      ++m;
    }
  }
}

int AtomStates::pack_reverse(int n, int first, double* buf) const {
  for (int i = first; i < first + n; ++i) (*this)[i].pack_summed(buf + kReverse * (i - first));
  return kReverse;
}

void AtomStates::unpack_reverse(int n, const int* list, const double* buf) {
  for (int k = 0; k < n; ++k) (*this)[list[k]].add_summed(buf + kReverse * k);
}

}  // namespace lbm_pore
