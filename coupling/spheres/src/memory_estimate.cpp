#include "coupling/memory_estimate.h"

#include <algorithm>
#include <cstdint>

#include "lbm/macroscopic.h"

namespace coupling {

double coupling_bytes_per_node(int threads) {
  const double mapping = 2 * sizeof(int);                                          // 8
  const double moment_cache = sizeof(std::uint32_t) + sizeof(lbm::NodeMoments);   // 36
  const double ghost_density = sizeof(double);                                     // 8
  const double ghost_moments = 4 * sizeof(double);                                 // 32
  return mapping + moment_cache * std::max(threads, 1) + ghost_density + ghost_moments;
}

}  // namespace coupling
