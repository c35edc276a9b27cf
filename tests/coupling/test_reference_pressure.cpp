// The reference pressure's share of the momentum exchange (coupling/force/momentum_exchange.h):
// a sphere resting on a wall at zero gap in fluid at rest (rho0 everywhere) feels nothing
// with the share removed (every link's populations are the reference ones), and with it kept
// (the paper's Eq. 2 read literally) the reference pressure p0 = rho0/3 on the surface that
// has no links, the part in contact with the wall: it is pressed into the wall. A sphere
// away from walls feels nothing either way (its link set is closed). A sphere reaching the
// outlet face, part of it beyond the lattice, feels nothing either way too: the links the
// lattice does not hold are taken as fluid at the face's density (open_face_pressure.h);
// without them, kept, it would be pushed out through the face.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "cases/serial_flow.h"
#include "coupling/force/open_face_pressure.h"
#include "coupling/sphere_coupling.h"

using namespace coupling;

namespace {

Vec3 force_at_rest(double centre_z, ReferencePressure reference) {
  lbm::VoxelGeometry g({16, 16, 16});
  for (int j = 0; j < 16; ++j)
    for (int i = 0; i < 16; ++i) g.set_solid(i, j, 0, true);  // the wall, its face at z = 0.5
  lbm::FluidParameters p;
  p.tau = 1.0;
  p.magic = 3.0 / 16.0;
  p.periodic = {true, true, false};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, cases::serial_decomposition(g, p.periodic));
  ParticleSet particles;
  particles.add(1, {8.2, 8.3, centre_z}, {0, 0, 0}, 4.0);
  SphereCouplingOptions options;
  options.reference_pressure = reference;
  SphereCoupling coupling(solver, options);
  coupling.step(particles.view());
  return coupling.force(0);
}

// A sphere of radius 4 whose centre lies `beyond` cells before the outlet face's node plane
// (x = 15) of a 16-cell channel driven by a zero pressure loss, in fluid at rest at rho0: its
// force and torque after one step, and the open-face links' own part with the share kept.
struct AtTheOutlet {
  Vec3 force, torque, open_face_part;
  std::size_t open_face_links;
};
AtTheOutlet at_the_outlet(double centre_x, ReferencePressure reference) {
  lbm::VoxelGeometry g({16, 16, 16});
  lbm::FluidParameters p;
  p.tau = 1.0;
  p.magic = 3.0 / 16.0;
  p.periodic = {false, true, true};
  lbm::FlowDrive drive;
  drive.kind = lbm::FlowDrive::kPressureLoss;
  drive.outlet_density = p.rho0;
  lbm::FluidSolver solver(g, p, drive, cases::serial_decomposition(g, p.periodic));
  ParticleSet particles;
  particles.add(1, {centre_x, 8.3, 7.6}, {0, 0, 0}, 4.0);
  SphereCouplingOptions options;
  options.reference_pressure = reference;
  SphereCoupling coupling(solver, options);
  coupling.step(particles.view());
  HydrodynamicLoads open;
  open.reset(1);
  const std::size_t links = add_open_face_pressure(particles.view(), solver, 0.0, open);
  return {coupling.force(0), coupling.torque(0), open.force[0], links};
}

}  // namespace

// Kept, the sphere at the outlet would feel p0 on the cross-section the face cuts from it,
// about p0 pi (R^2 - h^2) along +x (h: the centre's distance to the face), had the links
// beyond the face been left out; with them it feels nothing, as in open fluid.
TEST(ReferencePressure, ASphereReachingTheOutletFeelsTheFluidBeyondIt) {
  const double R = 4.0, p0 = 1.0 / 3.0;
  for (const double centre_x : {13.2, 15.0, 16.7}) {
    for (const ReferencePressure reference : {ReferencePressure::kRemoved, ReferencePressure::kKept}) {
      const AtTheOutlet r = at_the_outlet(centre_x, reference);
      EXPECT_GT(r.open_face_links, 0u) << centre_x;
      for (int a = 0; a < 3; ++a) {
        EXPECT_LT(std::abs(r.force[a]), 1e-12) << centre_x << " axis " << a;
        EXPECT_LT(std::abs(r.torque[a]), 1e-11) << centre_x << " axis " << a;
      }
      const double h = 15.0 - centre_x;  // the face's plane: the last node plane
      const double cut = p0 * M_PI * (R * R - h * h);
      std::printf("centre %.1f: %zu open-face links, their push kept %.4g (p0 pi (R^2 - h^2) = %.4g)\n", centre_x,
                  r.open_face_links, r.open_face_part[0], cut);
      // The links beyond the face push the sphere back into the lattice (-x), by about the
      // pressure on the cut cross-section (the face lies between x = 15 and its ghosts).
      EXPECT_LT(r.open_face_part[0], -0.5 * cut);
      EXPECT_GT(r.open_face_part[0], -2.0 * cut);
    }
  }
}

TEST(ReferencePressure, RemovedOrKeptOnASphereTouchingAWall) {
  const double touching = 0.5 + 4.0, free = 8.0;
  const Vec3 removed = force_at_rest(touching, ReferencePressure::kRemoved);
  const Vec3 kept = force_at_rest(touching, ReferencePressure::kKept);
  const Vec3 kept_free = force_at_rest(free, ReferencePressure::kKept);
  std::printf("sphere R = 4 on a wall in fluid at rest: force removed (%.3g, %.3g, %.3g), kept (%.4g, %.4g, "
              "%.4g); away from the wall, kept (%.3g, %.3g, %.3g)\n",
              removed[0], removed[1], removed[2], kept[0], kept[1], kept[2], kept_free[0], kept_free[1],
              kept_free[2]);
  for (int a = 0; a < 3; ++a) {
    EXPECT_LT(std::abs(removed[a]), 1e-12);
    EXPECT_LT(std::abs(kept_free[a]), 1e-12);
  }
  // Kept: pressed into the wall (-z) by p0 times the projected area of its unlinked surface,
  // a few cells^2 for R = 4 at zero gap; nothing sideways.
  EXPECT_LT(kept[2], -0.5);
  EXPECT_LT(std::abs(kept[0]), 1e-3 * std::abs(kept[2]));
  EXPECT_LT(std::abs(kept[1]), 1e-3 * std::abs(kept[2]));
}
