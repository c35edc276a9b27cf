#pragma once
#include <array>
#include <cstdint>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/population_field.h"

namespace lbm {

// On-site open boundary on a face normal to an axis (Zou & He 1997, extended to D3Q19 with
// the transverse-momentum correction of Hecht & Harting 2010, J. Stat. Mech. P01018).
// After streaming, a boundary node lacks the populations that would come from outside;
// we compute them from the known ones and write them into the ghost slots they are pulled
// from, so the fused kernel needs no special case.
struct OpenFace {
  int axis = 0;
  int inward = +1;         // +1: face at the lower bound (inlet), -1: upper bound (outlet)
  int local_plane = 0;     // local index of the boundary nodes along axis
  enum Kind { kVelocity, kDensity } kind = kVelocity;
  double value = 0.0;      // normal velocity along +axis (kVelocity) or density (kDensity)
  // > 0: the momentum is momentum_density * u (He & Luo's incompressible equilibrium with
  // rho0); 0: the local density's rho u.
  double momentum_density = 0.0;
};

// Applies one face to the owned fluid nodes of the block lying on it. The tangential
// velocity is set to zero. With `density` (a buffer of the plane's size) each fluid node's
// imposed density goes to its slot in the plane (row * row length + place in the row, the
// first tangential axis innermost): the node's density after the step's collision too,
// which conserves mass, so the face's mean pressure needs no second pass over its nodes.
void apply_open_face(const OpenFace& face, const BlockLayout& layout,
                     const std::vector<std::uint8_t>& node_type, PopulationField& f,
                     double* density = nullptr);

// The density apply_open_face gives the face's fluid node `cell` from its populations as they
// stand: the imposed value on a density face; on a velocity face the one its known
// populations and the velocity fix. The pressure of the fluid just beyond the face, which
// the lattice does not hold (the momentum exchange's open-face links).
double open_face_node_density(const OpenFace& face, const BlockLayout& layout, const PopulationField& f,
                              std::size_t cell);

// Mass the next streaming moves into the block through one open face: what the owned fluid
// nodes on it pull from the ghosts beyond it (the values apply_open_face wrote) less what
// they send there (their post-collision populations pointing out of the lattice, which no
// node pulls). Exact, unlike rho u sampled at the nodes: call it after the last stage that
// writes the face's slots (FluidSolver::apply_open_boundaries does). Negative = outflow.
double open_face_mass(const OpenFace& face, const BlockLayout& layout,
                      const std::vector<std::uint8_t>& node_type, const PopulationField& f);

}  // namespace lbm
