// Case 4: restitution of a head-on collision of two equal spheres under the dash-dot
// (linear spring-dashpot) contact, integrated with velocity Verlet at dt = t_c / N for
// N = 10, 20, 50, 100 DEM steps per contact, against the analytic restitution
// e = exp(-pi zeta / sqrt(1 - zeta^2)) of the unclipped linear law (doc/references.md).
// Where the contact starts inside a step matters at coarse dt, so each N is the mean of
// |e_sim / e - 1| over 8 evenly spaced start phases. One collision takes microseconds, so
// the wall time is that of the 8 collisions, averaged over as many repetitions as fit in
// 20 ms.
#include <cmath>
#include <cstdio>
#include <vector>

#include "accuracy.h"
#include "contact/dash_dot.h"
#include "contact/pair_contact.h"

namespace accuracy {
namespace {

// Two spheres of mass 1, radius 1, approaching at relative speed 2 v0; the contact starts
// a fraction `phase` of a step after t = 0. Returns the restitution and the steps taken.
double collide(const contact::PairContactParams& params, int steps_per_contact, double phase,
               long* steps) {
  const double m = 1.0, R = 1.0, v0 = 0.01, m_eff = 0.5 * m;
  const double dt = contact::contact_duration(params.normal, m_eff) / steps_per_contact;
  double x1 = 0.0, x2 = 2 * R + 2 * v0 * dt * phase, v1 = v0, v2 = -v0;
  auto force_on_1 = [&]() {  // along +x; the pair force is repulsive positive
    const double gap = (x2 - x1) - 2 * R;
    const double f = contact::pair_normal_force(params, {gap, v2 - v1, R, R, m_eff});
    return -f;
  };
  double f1 = force_on_1();
  long s = 0;
  for (; s < 100L * steps_per_contact; ++s) {
    v1 += 0.5 * dt * f1 / m;
    v2 -= 0.5 * dt * f1 / m;
    x1 += dt * v1;
    x2 += dt * v2;
    f1 = force_on_1();
    v1 += 0.5 * dt * f1 / m;
    v2 -= 0.5 * dt * f1 / m;
    if (x2 - x1 > 2 * R && v2 - v1 > 0.0 && s > 2) break;
  }
  *steps += s + 1;
  return (v2 - v1) / (2 * v0);
}

}  // namespace

void run_dashdot(const Options&, std::vector<Row>& rows) {
  const int phases = 8;
  for (double zeta : {0.1, 0.25, 0.5}) {
    contact::PairContactParams params;
    params.normal.k_n = 1.0;
    params.normal.damping_ratio = zeta;
    params.cohesion.k_c = 0.0;  // dash-dot only
    const double e_ref = contact::restitution_coefficient(zeta);
    for (int n : {10, 20, 50, 100}) {
      double sum = 0.0, e_mean = 0.0, seconds = 0.0;
      long steps = 0, repetitions = 0;
      Stopwatch watch;
      do {
        sum = 0.0;
        e_mean = 0.0;
        steps = 0;
        for (int j = 0; j < phases; ++j) {
          const double e = collide(params, n, (j + 0.5) / phases, &steps);
          sum += std::abs(e / e_ref - 1.0);
          e_mean += e / phases;
        }
        ++repetitions;
        seconds = watch.seconds();
      } while (seconds < 0.02);
      Row row;
      row.case_name = "dashdot";
      char option[32];
      std::snprintf(option, sizeof option, "zeta=%.2f", zeta);
      row.option = option;
      row.n_dem = n;
      row.error = sum / phases;
      row.reference = "e=exp(-pi zeta/sqrt(1-zeta^2))";
      row.wall_seconds = seconds / double(repetitions);
      row.value = e_mean;
      row.reference_value = e_ref;
      row.steps = steps;
      char note[80];
      std::snprintf(note, sizeof note, "signed_error_of_mean=%+.4f;timing_repetitions=%ld", e_mean / e_ref - 1.0,
                    repetitions);
      row.note = note;
      rows.push_back(row);
      std::fprintf(stderr, "dashdot %-10s N=%3d  e %.4f (ref %.4f) mean |error| %.2f %%  %.2e s\n",
                   option, n, e_mean, e_ref, 100 * row.error, row.wall_seconds);
    }
  }
}

}  // namespace accuracy
