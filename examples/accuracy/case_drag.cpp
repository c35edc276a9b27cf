// Case 2: drag on a fixed sphere in a periodic simple-cubic array (chi = d/L = 0.5) driven by
// a body force g, against Sangani & Acrivos (1982), K(0.5) = 2.8420: F = 6 pi mu a K U with
// U the superficial velocity and F = g L^3 in steady state (tests/coupling/test_drag_array.cpp).
// Error: |K/K_ref - 1|.
#include <cmath>
#include <cstdio>
#include <vector>

#include "accuracy.h"
#include "coupling/sphere_coupling.h"

namespace accuracy {
namespace {

struct DragRun {
  double K = 0.0;
  double force_balance = 0.0;  // F_me / (g N_fluid), 1 in steady state
  long steps = 0;
};

DragRun drag(int diameter, lbm::MovingWallScheme scheme) {
  const int L = static_cast<int>(std::lround(diameter / kDragChi));
  const double a = 0.5 * diameter, nu = 1.0 / 6.0;
  const double U_target = 2e-4;  // Re = U d / nu ~ 0.01: Stokes flow
  const double g = U_target * 6.0 * kPi * nu * a * kDragKRef / double(L) / L / L;
  auto solver = make_solver({L, L, L}, {true, true, true}, 1.0, {g, 0.0, 0.0});
  coupling::ParticleSet particles;
  // Off the lattice symmetry so the links see generic fractions.
  particles.add(1, {0.5 * L + 0.23, 0.5 * L - 0.31, 0.5 * L + 0.17}, {0, 0, 0}, a);
  coupling::SphereCouplingOptions options;
  options.wall_scheme = scheme;
  coupling::SphereCoupling coupling(*solver, options);
  DragRun r;
  double previous = 0.0;
  for (r.steps = 0; r.steps < 30000;) {
    for (int s = 0; s < 100; ++s, ++r.steps) coupling.step(particles.view());
    const double U = superficial_velocity(*solver, 0);
    if (std::abs(U - previous) < 1e-5 * std::abs(U)) break;
    previous = U;
  }
  long long fluid = 0;
  const double U = superficial_velocity(*solver, 0, &fluid);
  r.K = g * L * L * L / (6.0 * kPi * nu * a * U);
  r.force_balance = coupling.force(0)[0] / (g * double(fluid));
  return r;
}

}  // namespace

void run_drag(const Options& options, std::vector<Row>& rows) {
  const std::vector<int> diameters = options.quick ? std::vector<int>{6, 8}
                                                   : std::vector<int>{6, 8, 12, 16};
  using lbm::MovingWallScheme;
  for (MovingWallScheme scheme :
       {MovingWallScheme::kMeiLuoShyy, MovingWallScheme::kBouzidi, MovingWallScheme::kBounceBack}) {
    if (options.quick && scheme == MovingWallScheme::kBounceBack) continue;
    for (int d : diameters) {
      Stopwatch watch;
      const DragRun r = drag(d, scheme);
      Row row;
      row.case_name = "drag";
      row.option = lbm::moving_wall::label(scheme);
      row.resolution = d;
      row.error = std::abs(r.K / kDragKRef - 1.0);
      row.reference = "Sangani-Acrivos1982 K(chi=0.5)";
      row.wall_seconds = watch.seconds();
      row.value = r.K;
      row.reference_value = kDragKRef;
      row.steps = r.steps;
      char note[160];
      std::snprintf(note, sizeof note, "signed_error=%+.4f;F_me/(g*N_fluid)=%.5f", r.K / kDragKRef - 1.0,
                    r.force_balance);
      row.note = note;
      rows.push_back(row);
      std::fprintf(stderr, "drag %-12s d=%2d  K %.4f (ref %.4f) error %+.2f %%  %5ld steps  %.2f s\n",
                   row.option.c_str(), d, r.K, kDragKRef, 100 * (r.K / kDragKRef - 1.0), r.steps,
                   row.wall_seconds);
    }
  }
}

}  // namespace accuracy
