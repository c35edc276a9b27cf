// Case 5: a sphere translating at constant velocity through a periodic box (chi = d/L = 0.5)
// for thousands of steps, crossing cells in all three directions. A body force g on the
// fluid along the motion holds the flow in a steady periodic state; in the sphere's frame
// this is the fixed simple-cubic array of case 2 (cases/sphere_array_drag.h; Stokes drag
// of a cubic array is isotropic, so the oblique direction does not change K).
// K = g L^3 / (6 pi mu a U_rel), U_rel the superficial fluid velocity relative to the
// sphere averaged over the second half of the run; error |K/K_ref - 1| against Sangani &
// Acrivos (1982). Also reported: the drift of the fluid mass over the run
// (covering/refilling and the moving-wall terms are not exactly conservative) and the rms
// fluctuation of the force as the sphere crosses cells.
#include <cmath>
#include <cstdio>
#include <vector>

#include "accuracy.h"
#include "cases/sphere_array_drag.h"

namespace accuracy {

void run_moving(const Options& options, std::vector<Row>& rows) {
  const std::vector<int> diameters = options.quick ? std::vector<int>{6, 8}
                                                   : std::vector<int>{6, 8, 12};
  const long steps = options.quick ? 3000 : 8000;
  using lbm::MovingWallScheme;
  for (MovingWallScheme scheme :
       {MovingWallScheme::kMeiLuoShyy, MovingWallScheme::kBouzidi, MovingWallScheme::kBounceBack}) {
    if (options.quick && scheme != MovingWallScheme::kMeiLuoShyy) continue;
    for (int d : diameters) {
      Stopwatch watch;
      const int L = static_cast<int>(std::lround(d / cases::kDragChi));
      const double a = 0.5 * d, nu = 1.0 / 6.0, U = 0.005;  // Re = U d / nu = 0.18 ... 0.36
      const double norm = std::sqrt(1.0 + 0.09 + 0.01);
      const coupling::Vec3 n{1.0 / norm, 0.3 / norm, 0.1 / norm};
      const double g = cases::drag_array_body_force(U, nu, a, L);
      auto solver = make_solver({L, L, L}, {true, true, true}, 1.0, {g * n[0], g * n[1], g * n[2]});
      coupling::ParticleSet particles;
      const coupling::Vec3 x0{0.5 * L + 0.23, 0.5 * L - 0.31, 0.5 * L + 0.17};
      particles.add(1, x0, {-U * n[0], -U * n[1], -U * n[2]}, a);
      coupling::SphereCouplingOptions copt;
      copt.wall_scheme = scheme;
      coupling::SphereCoupling coupling(*solver, copt);
      coupling.map_and_refill(particles.view());
      const double m0 = fluid_mass(*solver);
      double sum_urel = 0.0, sum_f = 0.0, sum_f2 = 0.0, sum_balance = 0.0;
      long samples = 0, force_samples = 0;
      for (long t = 0; t < steps; ++t) {
        coupling::Vec3 x;
        for (int k = 0; k < 3; ++k) {
          x[k] = std::fmod(x0[k] - U * n[k] * double(t), double(L));
          if (x[k] < 0.0) x[k] += L;
        }
        particles.set_position(0, x);
        coupling.step(particles.view());
        if (t < steps / 2) continue;
        const auto& F = coupling.force(0);
        const double Fn = F[0] * n[0] + F[1] * n[1] + F[2] * n[2];
        sum_f += Fn;
        sum_f2 += Fn * Fn;
        ++force_samples;
        if (t % 10 == 0) {
          long long fluid = 0;
          double S = 0.0;
          for (int k = 0; k < 3; ++k) S += superficial_velocity(*solver, k, &fluid) * n[k];
          const double N = double(L) * L * L;
          sum_urel += S + (double(fluid) / N) * U;
          sum_balance += Fn / (g * double(fluid));
          ++samples;
        }
      }
      const double m1 = fluid_mass(*solver);
      const double U_rel = sum_urel / samples;
      const double K = g * L * L * L / (6.0 * kPi * nu * a * U_rel);
      const double F_mean = sum_f / force_samples;
      const double F_rms = std::sqrt(std::max(0.0, sum_f2 / force_samples - F_mean * F_mean));
      const double drift = (m1 - m0) / m0;
      Row row;
      row.case_name = "moving";
      row.option = lbm::moving_wall::label(scheme);
      row.resolution = d;
      row.error = std::abs(K / cases::kDragKRef - 1.0);
      row.reference = "Sangani-Acrivos1982 K(chi=0.5)";
      row.wall_seconds = watch.seconds();
      row.value = K;
      row.reference_value = cases::kDragKRef;
      row.steps = steps;
      char note[240];
      std::snprintf(note, sizeof note,
                    "signed_error=%+.4f;mass_drift=%+.3e;mass_drift_per_step=%+.2e;"
                    "force_rms/mean=%.4f;F_me/(g*N_fluid)=%.4f;travel_cells=%.0f",
                    K / cases::kDragKRef - 1.0, drift, drift / steps, F_rms / std::abs(F_mean),
                    sum_balance / samples, U * steps);
      row.note = note;
      rows.push_back(row);
      std::fprintf(stderr,
                   "moving %-12s d=%2d  K %.4f (ref %.4f) error %+.2f %%  mass drift %+.2e  "
                   "force rms %.2f %%  %ld steps  %.2f s\n",
                   row.option.c_str(), d, K, cases::kDragKRef, 100 * (K / cases::kDragKRef - 1.0),
                   drift, 100 * F_rms / std::abs(F_mean), steps, row.wall_seconds);
    }
  }
}

}  // namespace accuracy
