#pragma once
// SphereCoupling::step() stage by stage, with the halo exchange's populations chosen by the
// caller: the reference (all 19) and the negative control (the crossing five only) of the
// halo tests, against which the coupling's own choice (whole_ghost_axes) is checked.
#include <algorithm>
#include <cmath>

#include "coupling/sphere_coupling.h"
#include "lbm/d3q19.h"
#include "lbm/node_type.h"

namespace cases {

// Moves every particle by `steps` times its velocity: spheres fast enough to cover and
// uncover nodes at every coupled step (the tests that compare two ways of taking one).
inline void advance_particles(coupling::ParticleSet& particles, double steps) {
  for (std::size_t p = 0; p < particles.size(); ++p) {
    coupling::Vec3 x = particles.view().x(p);
    const coupling::Vec3 v = particles.view().v(p);
    for (int a = 0; a < 3; ++a) x[a] += steps * v[a];
    particles.set_position(p, x);
  }
}

inline void staged_step(coupling::SphereCoupling& c, const coupling::ParticleView& view,
                        const lbm::HaloPopulations& which) {
  lbm::FluidSolver& solver = c.solver();
  c.map_and_refill(view);
  solver.exchange_halo(which);
  solver.apply_wall_bounce_back();
  c.apply_moving_walls(view);
  solver.apply_open_boundaries();
  solver.collide_stream();
  c.exchange_momentum();
}

// Largest |a - b| over the owned populations of two solvers on the same block.
inline double max_population_difference(const lbm::FluidSolver& a, const lbm::FluidSolver& b) {
  const lbm::BlockLayout& g = a.layout();
  double worst = 0.0;
  for (int k = 0; k < g.size(2); ++k)
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i)
        for (int q = 0; q < lbm::D3Q19::Q; ++q) {
          const std::size_t cell = g.cell(i, j, k);
          worst = std::max(worst, std::abs(double(a.populations().at(q, cell)) -
                                           double(b.populations().at(q, cell))));
        }
  return worst;
}

}  // namespace cases
