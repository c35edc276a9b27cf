// Case 3: a sphere of radius a approaching a plane wall at constant speed U, total force
// (momentum exchange + optional lubrication correction) against Brenner (1961):
// F = 6 pi mu a U lambda(delta/a), delta the gap (tests/coupling/test_lubrication.cpp).
// The box is (6a, 7a, 6a), periodic in x and z, the wall the half-way bounce-back plane
// y = -1/2; the sphere starts at delta = 2a + 0.2 and stops at delta = 0.005 a. The speed
// is U = 0.032 / d, so the Reynolds number U d / nu = 0.19 is the same at every resolution
// (at a fixed U the inertial (Oseen) drag increase would grow with d and hide the
// discretisation error).
// Error: rms over the 7 tabulated gaps delta/a = 1 ... 0.01 of lambda/lambda_Brenner - 1.
// One lattice run gives both options: the correction is added on top of the same force.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "accuracy.h"
#include "coupling/lubrication/lubrication.h"
#include "coupling/sphere_coupling.h"

namespace accuracy {
namespace {

constexpr double kDeltas[] = {1.0, 0.5, 0.2, 0.1, 0.05, 0.02, 0.01};
constexpr double kBrenner[] = {2.1255, 3.2054, 6.3409, 11.459, 21.586, 51.761, 101.90};
constexpr int kPoints = 7;

struct Sample {
  double delta_over_a, lambda_lattice, lambda_corrected;
};

// lambda at a target delta/a from a history sorted by decreasing gap (5-step average).
double lambda_at(const std::vector<Sample>& s, double target, bool corrected) {
  for (std::size_t i = 2; i + 2 < s.size(); ++i)
    if (s[i].delta_over_a <= target) {
      double sum = 0.0;
      for (std::size_t k = i - 2; k <= i + 2; ++k)
        sum += corrected ? s[k].lambda_corrected : s[k].lambda_lattice;
      return sum / 5.0;
    }
  return 0.0;
}

}  // namespace

void run_lubrication(const Options& options, std::vector<Row>& rows) {
  const std::vector<int> diameters = options.quick ? std::vector<int>{6, 8}
                                                   : std::vector<int>{6, 8, 12, 16};
  using namespace coupling;
  for (int d : diameters) {
    const double R = 0.5 * d, U = 0.032 / d, mu = 1.0 / 6.0;
    const int nx = static_cast<int>(std::lround(6 * R)), ny = static_cast<int>(std::lround(7 * R));
    Stopwatch watch;
    auto solver = make_solver({nx, ny, nx}, {true, false, true}, 1.0, {0, 0, 0});
    ParticleSet particles;
    const double x = 0.5 * nx - 0.4, z = 0.5 * nx + 0.3;
    const double y0 = -0.5 + R + (2 * R + 0.2);
    particles.add(1, {x, y0, z}, {0, -U, 0}, R);
    SphereCoupling coupling(*solver);
    LubricationCorrection lub(LubricationParameters{});
    const auto wall = plane_wall({0, -0.5, 0}, {0, 1, 0});
    const PeriodicBox box = PeriodicBox::from(solver->decomposition());
    std::vector<Sample> history;
    double lub_seconds = 0.0;
    for (long t = 0;; ++t) {
      const double y = y0 - U * t;
      const double gap = y + 0.5 - R;
      if (gap < 0.005 * R) break;
      particles.set_position(0, {x, y, z});
      coupling.step(particles.view());
      Stopwatch lub_watch;
      double F[3] = {0, 0, 0};
      lub.add_forces(particles.view(), box, wall, F);
      lub_seconds += lub_watch.seconds();
      const double scale = 6 * kPi * mu * R * U;
      history.push_back({gap / R, coupling.force(0)[1] / scale, (coupling.force(0)[1] + F[1]) / scale});
    }
    const double lattice_seconds = watch.seconds() - lub_seconds;
    for (bool corrected : {true, false}) {
      double sum2 = 0.0;
      std::string note = "lambda/lambda_B-1 at delta/a=";
      for (int i = 0; i < kPoints; ++i) {
        const double e = lambda_at(history, kDeltas[i], corrected) / kBrenner[i] - 1.0;
        sum2 += e * e;
        char part[40];
        std::snprintf(part, sizeof part, "%s%g:%+.3f", i ? "," : "", kDeltas[i], e);
        note += part;
      }
      Row row;
      row.case_name = "lubrication";
      row.option = corrected ? "with correction" : "without correction";
      row.resolution = d;
      row.error = std::sqrt(sum2 / kPoints);
      row.reference = "Brenner1961 delta/a=1..0.01";
      row.wall_seconds = lattice_seconds + (corrected ? lub_seconds : 0.0);
      row.value = lambda_at(history, 0.01, corrected);
      row.reference_value = kBrenner[kPoints - 1];
      row.steps = static_cast<long>(history.size());
      // The option without the correction is the same lattice run: counted once in totals.
      row.note = note + (corrected ? "" : ";shared_run=1");
      rows.push_back(row);
      std::fprintf(stderr, "lubrication %-18s d=%2d  rms error %.3f  lambda(0.01) %.2f (ref %.2f)  %ld steps  %.2f s\n",
                   row.option.c_str(), d, row.error, row.value, row.reference_value, row.steps,
                   row.wall_seconds);
    }
  }
}

}  // namespace accuracy
