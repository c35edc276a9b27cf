// Case 3: a sphere of radius a approaching a plane wall at constant speed U, total force
// (momentum exchange + optional lubrication correction) against Brenner (1961):
// F = 6 pi mu a U lambda(delta/a), delta the gap. The set-up (box, speed, start and end) is
// cases/sphere_wall_approach.h, which tests/coupling/test_lubrication.cpp runs at d = 8.
// Error: rms over the 7 tabulated gaps delta/a = 1 ... 0.01 of lambda/lambda_Brenner - 1.
// One lattice run gives both options: the correction is added on top of the same force.
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "accuracy.h"
#include "cases/sphere_wall_approach.h"

namespace accuracy {

void run_lubrication(const Options& options, std::vector<Row>& rows) {
  const std::vector<int> diameters = options.quick ? std::vector<int>{6, 8}
                                                   : std::vector<int>{6, 8, 12, 16};
  for (int d : diameters) {
    Stopwatch watch;
    const cases::WallApproach run = cases::sphere_approaching_wall(d);
    const double lattice_seconds = watch.seconds() - run.lubrication_seconds;
    for (bool corrected : {true, false}) {
      double sum2 = 0.0;
      std::string note = "lambda/lambda_B-1 at delta/a=";
      const std::vector<cases::LambdaSample>& history = corrected ? run.corrected : run.lattice;
      for (int i = 0; i < cases::kBrennerPoints; ++i) {
        const double e =
            cases::lambda_at(history, cases::kBrennerDelta[i]) / cases::kBrennerLambda[i] - 1.0;
        sum2 += e * e;
        char part[40];
        std::snprintf(part, sizeof part, "%s%g:%+.3f", i ? "," : "", cases::kBrennerDelta[i], e);
        note += part;
      }
      Row row;
      row.case_name = "lubrication";
      row.option = corrected ? "with correction" : "without correction";
      row.resolution = d;
      row.error = std::sqrt(sum2 / cases::kBrennerPoints);
      row.reference = "Brenner1961 delta/a=1..0.01";
      row.wall_seconds = lattice_seconds + (corrected ? run.lubrication_seconds : 0.0);
      row.value = cases::lambda_at(history, 0.01);
      row.reference_value = cases::kBrennerLambda[cases::kBrennerPoints - 1];
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
