#pragma once
// The push of the fluid beyond an open face (the drive's inlet or outlet) on the part of a
// sphere that reaches past it, which the lattice does not hold.
#include <vector>

#include "coupling/force/momentum_exchange.h"
#include "coupling/particle_view.h"
#include "lbm/fluid_solver.h"

namespace coupling {

// A sphere within a cell of an open face has links that the lattice does not hold: from
// nodes beyond the face into the sphere, and from the face's nodes into parts of the sphere
// beyond it. The momentum exchange (paper Eq. 2) sums only the others. Each missing link of
// the unbounded lattice is taken here as fluid at rest at the face's density rho_f (the
// imposed density, or FluidSolver::open_face_density at the face node it is nearest to):
// 2 w_q (rho_f - rho_gauge) c_q on the sphere, with its torque about the link's cut point.
// With the reference pressure kept (rho_gauge = 0) this closes the sphere's surface: without
// it a sphere reaching the outlet feels p0 = rho0 / 3 on the cross-section the face cuts from
// it, a push out of the lattice that shoots it through the face (doc/calibration.md). With it
// removed (rho_gauge = rho0) it adds the face's deviation from rho0, zero at an outlet held
// at rho0. Each link is counted by the rank that owns its face node, from the first copy of
// its particle in the view (periodic images give the same links), so no link counts twice.
// `loads` indexed like the view; returns the number of links added on this rank.
std::size_t add_open_face_pressure(const ParticleView& view, const lbm::FluidSolver& solver,
                                   double rho_gauge, HydrodynamicLoads& loads);

// The same in two steps, for a step that sums its loads after the collide-stream (which
// changes the face densities this reads): the pushes of the missing links, in the order
// add_open_face_pressure adds them, read now, and added to `loads` later, one by one, so the
// loads are the same bits.
struct OpenFacePush {
  std::size_t particle;  // in the view
  Vec3 force, torque;
};
std::size_t record_open_face_pressure(const ParticleView& view, const lbm::FluidSolver& solver,
                                      double rho_gauge, std::vector<OpenFacePush>& pushes);
void add_open_face_pushes(const std::vector<OpenFacePush>& pushes, HydrodynamicLoads& loads);

}  // namespace coupling
