// Case 1: Poiseuille flow in a circular pipe driven by a body force, relative L2 error of
// u_x against u(r) = g (R^2 - r^2) / (4 mu), for interpolated (Bouzidi) and half-way
// bounce-back links on the curved wall. The set-up is tests/lbm/test_poiseuille.cpp's
// (cases/pipe_poiseuille.h): the pipe axis is periodic and 2 nodes long, the wall links are
// cut at the exact radius, and each resolution is the mean over R, R +- 7.5 % (curved-wall
// errors oscillate with how the wall cuts the lattice).
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "accuracy.h"
#include "cases/pipe_poiseuille.h"

namespace accuracy {

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
      for (double f : cases::kPipeRadiusFactors) {
        const cases::PipeRun r = cases::pipe_poiseuille(f * R, s.scheme);
        sum += r.l2_error;
        steps += r.steps;
        std::snprintf(note, sizeof note, "%sL2(R=%.2f)=%.3e", parts.empty() ? "" : ";", f * R,
                      r.l2_error);
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
