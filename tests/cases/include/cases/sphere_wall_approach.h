#pragma once
// A sphere of diameter d approaching a plane wall at constant speed (tests/coupling/
// test_lubrication.cpp and the lubrication case of examples/accuracy): total force,
// momentum exchange with and without the lubrication correction, against Brenner (1961),
// F = 6 pi mu a U lambda(delta/a), delta the gap. The box is (6a, 7a, 6a), periodic in x and
// z, the wall the half-way bounce-back plane y = -1/2; the sphere starts at delta = 2a + 0.2
// and stops at delta = 0.005 a. The speed is U = 0.032 / d, so the Reynolds number
// U d / nu = 0.19 is the same at every resolution (at a fixed U the inertial (Oseen) drag
// increase would grow with d and hide the discretisation error).
#include <cmath>
#include <vector>

#include "cases/serial_flow.h"
#include "coupling/lubrication/lubrication.h"
#include "coupling/sphere_coupling.h"

namespace cases {

// Brenner (1961), doc/references.md: lambda at the gaps delta/a.
constexpr int kBrennerPoints = 7;
constexpr double kBrennerDelta[kBrennerPoints] = {1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01};
constexpr double kBrennerLambda[kBrennerPoints] = {2.1255, 3.2054, 6.3409, 11.459,
                                                   21.586, 51.761, 101.90};

struct LambdaSample {
  double delta_over_a, lambda;
};

// lambda at a target delta/a from a history sorted by decreasing gap (5-step average).
inline double lambda_at(const std::vector<LambdaSample>& s, double target) {
  for (std::size_t i = 2; i + 2 < s.size(); ++i)
    if (s[i].delta_over_a <= target) {
      double sum = 0.0;
      for (std::size_t k = i - 2; k <= i + 2; ++k) sum += s[k].lambda;
      return sum / 5.0;
    }
  return 0.0;
}

struct WallApproach {
  std::vector<LambdaSample> lattice;    // momentum exchange alone, one sample per step
  std::vector<LambdaSample> corrected;  // plus the lubrication correction
  double lubrication_seconds = 0.0;     // time spent in the correction
};

inline WallApproach sphere_approaching_wall(int diameter) {
  using namespace coupling;
  const double R = 0.5 * diameter, U = 0.032 / diameter, mu = 1.0 / 6.0;
  const int nx = static_cast<int>(std::lround(6 * R)), ny = static_cast<int>(std::lround(7 * R));
  auto solver = make_solver({nx, ny, nx}, {true, false, true});
  ParticleSet particles;
  const double x = 0.5 * nx - 0.4, z = 0.5 * nx + 0.3;
  const double y0 = -0.5 + R + (2 * R + 0.2);
  particles.add(1, {x, y0, z}, {0, -U, 0}, R);
  SphereCoupling coupling(*solver);
  LubricationCorrection lub(LubricationParameters{});
  const auto wall = plane_wall({0, -0.5, 0}, {0, 1, 0});
  const PeriodicBox box = PeriodicBox::from(solver->decomposition());
  WallApproach run;
  for (long t = 0;; ++t) {
    const double y = y0 - U * t;
    const double gap = y + 0.5 - R;
    if (gap < 0.005 * R) break;
    particles.set_position(0, {x, y, z});
    coupling.step(particles.view());
    Stopwatch lub_watch;
    double F[3] = {0, 0, 0};
    lub.add_forces(particles.view(), box, wall, F);
    run.lubrication_seconds += lub_watch.seconds();
    const double scale = 6 * kPi * mu * R * U;
    run.lattice.push_back({gap / R, coupling.force(0)[1] / scale});
    run.corrected.push_back({gap / R, (coupling.force(0)[1] + F[1]) / scale});
  }
  return run;
}

}  // namespace cases
