#pragma once
// The group's atoms as the coupling sees them: lattice-unit copies of positions, velocities,
// angular velocities and radii, owned atoms first and then ghosts, behind a
// coupling::ParticleView, with the atom index each entry came from so loads computed per
// entry go back to the right atom. No LIGGGHTS dependency: the fix passes raw arrays, a test
// can pass its own.
#include <cstddef>
#include <vector>

#include "coupling/lattice_frame.h"
#include "coupling/particle_view.h"
#include "coupling/unit_conversion.h"

namespace lbm_pore {

struct AtomArrays {
  int nlocal = 0, nghost = 0;
  const int* mask = nullptr;  // null: every atom is in the group
  int groupbit = 0;
  const int* tag = nullptr;
  double* const* x = nullptr;
  double* const* v = nullptr;
  double* const* omega = nullptr;  // null: not rotating
  const double* radius = nullptr;
};

// The atoms as they are, in host units, over the host's own arrays (x and v as contiguous
// rows, as LIGGGHTS allocates them), for the kernels that work in host units (lubrication,
// bonds). Owned atoms and ghosts, the group's or not.
coupling::ParticleView host_view(const AtomArrays& atoms);

class LatticeParticles {
 public:
  // Positions through the frame, velocities, angular velocities and radii through the units.
  void gather(const AtomArrays& atoms, const coupling::LatticeFrame& frame, const coupling::UnitConversion& units);

  coupling::ParticleView view() const { return particles_.view(rotating_); }
  std::size_t size() const { return atom_.size(); }
  std::size_t num_owned() const { return particles_.num_owned; }
  // LIGGGHTS atom index (0..nlocal+nghost) of view entry p.
  int atom(std::size_t p) const { return atom_[p]; }

 private:
  coupling::ParticleSet particles_;  // the lattice-unit copies, entry p from atom_[p]
  bool rotating_ = false;
  std::vector<int> atom_;
};

}  // namespace lbm_pore
