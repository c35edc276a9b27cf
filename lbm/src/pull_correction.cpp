#include "lbm/pull_correction.h"

#include <algorithm>

#include "lbm/d3q19.h"

namespace lbm {

void apply_pull_corrections(const PullCorrections& c, std::size_t first, std::size_t last,
                            Real* const* pulled) {
  using L = D3Q19;
  const std::uint32_t* const end = c.cell + c.count;
  for (const std::uint32_t* e = std::lower_bound(c.cell, end, first); e != end && *e < last;) {
    const std::size_t x = *e;
    const std::uint32_t* node_end = e + 1;
    while (node_end != end && *node_end == x) ++node_end;
    const double* const d = c.defect + (e - c.cell);
    const std::ptrdiff_t n = node_end - e;
    // As LinkMassRestorer::remove_node: each population takes the entries' shares in turn
    // (the populations independent of each other: the entries in the outer loop, so that the
    // 19 subtractions of one entry go in vectors).
    const std::size_t i = x - first;
    Real value[L::Q];
#pragma GCC unroll 19
    for (int p = 0; p < L::Q; ++p) value[p] = pulled[p][i];
    for (std::ptrdiff_t k = 0; k < n; ++k) {
      const double dk = d[k];
#pragma GCC unroll 19
      for (int p = 0; p < L::Q; ++p) value[p] = static_cast<Real>(value[p] - L::w[p] * dk);
    }
#pragma GCC unroll 19
    for (int p = 0; p < L::Q; ++p) pulled[p][i] = value[p];
    e = node_end;
  }
}

}  // namespace lbm
