// libFuzzer target: the argument parsers of pair_style/pair_coeff lbm/dashdot and fix
// wall/voxel, without LIGGGHTS. The first byte chooses the parser (odd: wall/voxel, even:
// dash-dot; the seeds start with "w " and "p "), the words after it are the arguments. Bad
// input must give lbm::InputError; accepted coefficients must lie in their ranges.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "dashdot/dashdot_arguments.h"
#include "fuzz_words.h"
#include "lbm/input_error.h"
#include "wall_voxel/wall_voxel_arguments.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  const std::vector<std::string> words = fuzz_words(data + 1, size - 1);
  try {
    if (data[0] & 1) {
      const lbm_pore::WallVoxelArguments a = lbm_pore::parse_wall_voxel_arguments(words);
      const auto& p = a.params;
      if (!(p.normal.k_n > 0 && p.adhesion.k_a >= 0 && p.friction.mu >= 0 && p.friction.k_t > 0 &&
            p.normal.damping_ratio <= 1 && std::isfinite(a.source.spacing)))
        __builtin_trap();
    } else {
      contact::PairContactParams p;
      lbm_pore::parse_dashdot_coefficients(words, p, "pair_style lbm/dashdot");
      if (!(p.normal.k_n > 0 && p.cohesion.k_c >= 0 && p.normal.damping_ratio >= 0 &&
            p.normal.damping_ratio <= 1))
        __builtin_trap();
    }
  } catch (const lbm::InputError&) {
  }
  return 0;
}
