// bench_lbm built without Palabos (CMake did not find Debian's libplb-dev): no side-by-side
// case; bench_lbm says so in one line and skips BENCH lbm_vs_palabos.
#include "palabos_trt_case.h"

bool palabos_available() { return false; }

double palabos_trt_omega_minus() { return 0.0; }

std::unique_ptr<PalabosTrtCase> make_palabos_trt_case(int, double, const NodeState&) {
  return nullptr;
}
