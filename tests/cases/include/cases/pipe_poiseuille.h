#pragma once
// Poiseuille flow in a circular pipe driven by a body force (tests/lbm/test_poiseuille.cpp
// and the pipe case of examples/accuracy): the pipe lies along x, periodic and 2 nodes long,
// solid outside r = R; its wall links are cut at the exact radius and reconstructed by
// `scheme`. Reference: u(r) = g (R^2 - r^2) / (4 mu).
#include <array>
#include <cmath>
#include <vector>

#include "cases/serial_flow.h"
#include "lbm/d3q19.h"
#include "lbm/moving_wall/link_boundary.h"

namespace cases {

constexpr double kPipeForce = 1e-6;  // body force g along the axis
// Curved-wall errors oscillate with how the wall cuts the lattice, so a resolution R is
// measured as the mean over the radii R * these factors (R, R +- 7.5 %).
constexpr double kPipeRadiusFactors[] = {0.925, 1.0, 1.075};

struct PipeRun {
  double l2_error = 0.0;  // relative L2 error of u_x over fluid nodes
  long steps = 0;
  std::vector<lbm::BoundaryLink> links;  // the wall links (fractions in (0, 1])
};

// Starts from the analytical profile (the steady state does not depend on the start, it is
// only reached sooner) and runs until the velocity changes by less than 1e-9 relative per
// 100 steps (at most 100000 steps).
inline PipeRun pipe_poiseuille(double R, lbm::MovingWallScheme scheme) {
  const int n = static_cast<int>(std::ceil(2 * R)) + 2;
  const double centre = 0.5 * (n - 1);
  lbm::VoxelGeometry g({2, n, n});
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      if (std::hypot(j - centre, k - centre) >= R)
        for (int i = 0; i < 2; ++i) g.set_solid(i, j, k, true);
  lbm::FluidParameters p;
  p.tau = 1.0;
  p.magic = 3.0 / 16.0;
  p.body_force = {kPipeForce, 0.0, 0.0};
  p.periodic = {true, false, false};
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, serial_decomposition(g, p.periodic));
  const double mu = lbm::TrtParameters::viscosity(1.0);
  auto exact = [&](int, int y, int z) {
    const double r2 = std::pow(y - centre, 2) + std::pow(z - centre, 2);
    return kPipeForce * (R * R - r2) / (4.0 * mu);
  };
  solver.initialise_equilibrium([&](int x, int y, int z) {
    return std::array<double, 4>{1.0, exact(x, y, z), 0.0, 0.0};
  });

  PipeRun run;
  const auto& L = solver.layout();
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < 2; ++i) {
        const std::size_t x = L.cell(i, j, k);
        if (solver.node_types()[x] != lbm::kFluid) continue;
        for (int q = 1; q < lbm::D3Q19::Q; ++q) {
          const int cy = lbm::D3Q19::c[q][1], cz = lbm::D3Q19::c[q][2];
          if (solver.node_types()[x + L.offset(lbm::D3Q19::c[q][0], cy, cz)] == lbm::kFluid)
            continue;
          // |p + s c| = R on the pipe's cross-section.
          const double py = j - centre, pz = k - centre;
          const double a = cy * cy + cz * cz, b = py * cy + pz * cz, c = py * py + pz * pz - R * R;
          const double s = (-b + std::sqrt(b * b - a * c)) / a;
          run.links.push_back({x, q, s, {0.0, 0.0, 0.0}});
        }
      }

  // The step has an extra stage (the links) before the collision, so step by hand instead
  // of solver.step().
  run.steps = run_to_steady(solver, 1e-9, 100000, 100, [&] {
    solver.exchange_halo();
    solver.apply_wall_bounce_back();
    lbm::apply_links(run.links, scheme, 1.0, solver.layout(), solver.node_types(),
                     solver.populations());
    solver.collide_stream();
  });
  run.l2_error = relative_l2_error(solver, 0, exact);
  return run;
}

}  // namespace cases
