#include "lattice_particles.h"

namespace lbm_pore {

void LatticeParticles::gather(const AtomArrays& atoms, const coupling::LatticeFrame& frame,
                              const coupling::UnitConversion& units) {
  atom_.clear();
  particles_.clear();
  rotating_ = atoms.omega != nullptr;
  const double velocity_scale = units.velocity_to_lattice_factor();
  const double angular_velocity_scale = units.angular_velocity_to_lattice_factor();
  auto add = [&](int i, bool owned) {
    atom_.push_back(i);
    coupling::Vec3 v, omega{0.0, 0.0, 0.0};
    for (int a = 0; a < 3; ++a) v[a] = atoms.v[i][a] * velocity_scale;
    if (rotating_)
      for (int a = 0; a < 3; ++a) omega[a] = atoms.omega[i][a] * angular_velocity_scale;
    particles_.add(atoms.tag ? atoms.tag[i] : i, frame.to_lattice(atoms.x[i]), v, omega,
                   units.length_to_lattice(atoms.radius[i]), owned);
  };
  const auto in_group = [&](int i) { return !atoms.mask || (atoms.mask[i] & atoms.groupbit); };
  // Owned atoms first: the mapping gives a node covered twice to the lower index, and the
  // diagnostics count only [0, num_owned).
  for (int i = 0; i < atoms.nlocal; ++i)
    if (in_group(i)) add(i, true);
  for (int i = atoms.nlocal; i < atoms.nlocal + atoms.nghost; ++i)
    if (in_group(i)) add(i, false);
}

coupling::ParticleView host_view(const AtomArrays& atoms) {
  coupling::ParticleView view;
  view.num_owned = static_cast<std::size_t>(atoms.nlocal);
  view.num_total = static_cast<std::size_t>(atoms.nlocal + atoms.nghost);
  view.position = atoms.x[0];
  view.velocity = atoms.v[0];
  view.radius = atoms.radius;
  return view;
}

}  // namespace lbm_pore
