#include "lattice_particles.h"

namespace lbm_pore {

void LatticeParticles::gather(const AtomArrays& atoms, const coupling::LatticeFrame& frame,
                              const coupling::UnitConversion& units) {
  atom_.clear();
  id_.clear();
  position_.clear();
  velocity_.clear();
  angular_velocity_.clear();
  radius_.clear();
  rotating_ = atoms.omega != nullptr;
  const double velocity_scale = units.velocity_to_lattice_factor();
  const double angular_velocity_scale = units.angular_velocity_to_lattice_factor();
  auto add = [&](int i) {
    atom_.push_back(i);
    id_.push_back(atoms.tag ? atoms.tag[i] : i);
    const auto x = frame.to_lattice(atoms.x[i]);
    position_.insert(position_.end(), x.begin(), x.end());
    for (int a = 0; a < 3; ++a) velocity_.push_back(atoms.v[i][a] * velocity_scale);
    for (int a = 0; a < 3; ++a) angular_velocity_.push_back(rotating_ ? atoms.omega[i][a] * angular_velocity_scale : 0.0);
    radius_.push_back(units.length_to_lattice(atoms.radius[i]));
  };
  const auto in_group = [&](int i) { return !atoms.mask || (atoms.mask[i] & atoms.groupbit); };
  // Owned atoms first: the mapping gives a node covered twice to the lower index, and the
  // diagnostics count only [0, num_owned).
  for (int i = 0; i < atoms.nlocal; ++i)
    if (in_group(i)) add(i);
  num_owned_ = atom_.size();
  for (int i = atoms.nlocal; i < atoms.nlocal + atoms.nghost; ++i)
    if (in_group(i)) add(i);
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

coupling::ParticleView LatticeParticles::view() const {
  coupling::ParticleView view;
  view.num_owned = num_owned_;
  view.num_total = atom_.size();
  view.id = id_.data();
  view.position = position_.data();
  view.velocity = velocity_.data();
  view.angular_velocity = rotating_ ? angular_velocity_.data() : nullptr;
  view.radius = radius_.data();
  return view;
}

}  // namespace lbm_pore
