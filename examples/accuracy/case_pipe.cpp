// Case 1: Poiseuille flow in a circular pipe driven by a body force, relative L2 error of
// u_x against u(r) = g (R^2 - r^2) / (4 mu), for interpolated (Bouzidi) and half-way
// bounce-back links on the curved wall. Set-up as tests/lbm/test_poiseuille.cpp: the pipe
// axis is periodic and 2 nodes long, the wall links are cut at the exact radius, and each
// resolution is the mean over R, R +- 7.5 % (curved-wall errors oscillate with how the wall
// cuts the lattice).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "accuracy.h"
#include "lbm/d3q19.h"
#include "lbm/link_boundary.h"
#include "lbm/macroscopic.h"

namespace accuracy {
namespace {

constexpr double kForce = 1e-6;

struct PipeRun {
  double l2 = 0.0;
  long steps = 0;
};

PipeRun pipe(double R, lbm::MovingWallScheme scheme) {
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
  p.body_force = {kForce, 0.0, 0.0};
  p.periodic = {true, false, false};
  lbm::Box box;
  box.hi = g.dims();
  lbm::FluidSolver solver(g, p, lbm::FlowDrive{}, lbm::Decomposition::serial(box, p.periodic));
  const double mu = lbm::TrtParameters::viscosity(1.0);
  auto exact = [&](int y, int z) {
    const double r2 = std::pow(y - centre, 2) + std::pow(z - centre, 2);
    return kForce * (R * R - r2) / (4.0 * mu);
  };
  // Starting from the analytic profile only shortens the transient.
  solver.initialise_equilibrium(
      [&](int, int y, int z) { return std::array<double, 4>{1.0, exact(y, z), 0.0, 0.0}; });

  std::vector<lbm::BoundaryLink> links;
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
          // |p + s c| = R in the cross-section.
          const double py = j - centre, pz = k - centre;
          const double a = cy * cy + cz * cz, b = py * cy + pz * cz, c = py * py + pz * pz - R * R;
          const double s = (-b + std::sqrt(b * b - a * c)) / a;
          links.push_back({x, q, s, {0.0, 0.0, 0.0}});
        }
      }

  PipeRun run;
  auto previous = lbm::compute_fields(solver).velocity;
  for (run.steps = 0; run.steps < 100000;) {
    for (int t = 0; t < 100; ++t, ++run.steps) {
      solver.exchange_halo();
      solver.apply_wall_bounce_back();
      lbm::apply_links(links, scheme, 1.0, solver.layout(), solver.node_types(),
                       solver.populations());
      solver.collide_stream();
    }
    const auto now = lbm::compute_fields(solver).velocity;
    double change = 0.0, scale = 1e-300;
    for (std::size_t i = 0; i < now.size(); ++i) {
      change = std::max(change, std::abs(now[i] - previous[i]));
      scale = std::max(scale, std::abs(now[i]));
    }
    if (change < 1e-9 * scale) break;
    previous = now;
  }
  // Relative L2 error over fluid nodes.
  const auto f = lbm::compute_fields(solver);
  double num = 0.0, den = 0.0;
  std::size_t c = 0;
  for (int k = 0; k < L.size(2); ++k)
    for (int j = 0; j < L.size(1); ++j)
      for (int i = 0; i < L.size(0); ++i, ++c) {
        if (f.node_type[c] != lbm::kFluid) continue;
        const auto gl = L.to_global(i, j, k);
        const double e = exact(gl[1], gl[2]);
        num += std::pow(f.velocity[3 * c] - e, 2);
        den += e * e;
      }
  run.l2 = std::sqrt(num / den);
  return run;
}

}  // namespace

void run_pipe(const Options& options, std::vector<Row>& rows) {
  const std::vector<double> radii = options.quick ? std::vector<double>{4, 8}
                                                  : std::vector<double>{4, 8, 16};
  const struct {
    lbm::MovingWallScheme scheme;
    const char* name;
  } schemes[] = {{lbm::MovingWallScheme::kBouzidi, "Bouzidi"},
                 {lbm::MovingWallScheme::kBounceBack, "bounce-back"}};
  for (const auto& s : schemes)
    for (double R : radii) {
      Stopwatch watch;
      double sum = 0.0;
      long steps = 0;
      char note[200];
      std::string parts;
      for (double f : {0.925, 1.0, 1.075}) {
        const PipeRun r = pipe(f * R, s.scheme);
        sum += r.l2;
        steps += r.steps;
        std::snprintf(note, sizeof note, "%sL2(R=%.2f)=%.3e", parts.empty() ? "" : ";", f * R, r.l2);
        parts += note;
      }
      Row row;
      row.case_name = "pipe";
      row.option = s.name;
      row.resolution = R;
      row.error = sum / 3.0;
      row.reference = "u(r)=g(R^2-r^2)/(4mu)";
      row.wall_seconds = watch.seconds();
      row.value = row.error;
      row.reference_value = 0.0;
      row.steps = steps;
      row.note = parts;
      rows.push_back(row);
      std::fprintf(stderr, "pipe %-12s R=%4.1f  mean L2 %.3e  %6ld steps  %.2f s\n", s.name, R,
                   row.error, steps, row.wall_seconds);
    }
}

}  // namespace accuracy
