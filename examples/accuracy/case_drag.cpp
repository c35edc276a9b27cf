// Case 2: drag on a fixed sphere in a periodic simple-cubic array (chi = d/L = 0.5) driven by
// a body force g, against Sangani & Acrivos (1982), K(0.5) = 2.8420: F = 6 pi mu a K U with
// U the superficial velocity and F = g L^3 in steady state; the set-up is
// tests/coupling/test_drag_array.cpp's (cases/sphere_array_drag.h), run up to 30000 steps.
// Error: |K/K_ref - 1|.
#include <cmath>
#include <cstdio>
#include <vector>

#include "accuracy.h"
#include "cases/sphere_array_drag.h"

namespace accuracy {

void run_drag(const Options& options, std::vector<Row>& rows) {
  const std::vector<int> diameters = options.quick ? std::vector<int>{6, 8}
                                                   : std::vector<int>{6, 8, 12, 16};
  using lbm::MovingWallScheme;
  for (MovingWallScheme scheme :
       {MovingWallScheme::kMeiLuoShyy, MovingWallScheme::kBouzidi, MovingWallScheme::kBounceBack}) {
    if (options.quick && scheme == MovingWallScheme::kBounceBack) continue;
    for (int d : diameters) {
      Stopwatch watch;
      const cases::DragArrayRun r = cases::drag_in_sphere_array(d, scheme, 30000);
      Row row;
      row.case_name = "drag";
      row.option = lbm::moving_wall::label(scheme);
      row.resolution = d;
      row.error = std::abs(r.K / cases::kDragKRef - 1.0);
      row.reference = "Sangani-Acrivos1982 K(chi=0.5)";
      row.wall_seconds = watch.seconds();
      row.value = r.K;
      row.reference_value = cases::kDragKRef;
      row.steps = r.steps;
      char note[160];
      std::snprintf(note, sizeof note, "signed_error=%+.4f;F_me/(g*N_fluid)=%.5f",
                    r.K / cases::kDragKRef - 1.0, r.force_balance);
      row.note = note;
      rows.push_back(row);
      std::fprintf(stderr,
                   "drag %-12s d=%2d  K %.4f (ref %.4f) error %+.2f %%  %5ld steps  %.2f s\n",
                   row.option.c_str(), d, r.K, cases::kDragKRef,
                   100 * (r.K / cases::kDragKRef - 1.0), r.steps, row.wall_seconds);
    }
  }
}

}  // namespace accuracy
