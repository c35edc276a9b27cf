// libFuzzer target: the raw voxel-file reader (lbm::read_raw_voxels) on arbitrary bytes. A
// malformed file must give lbm::InputError; anything else escaping (std::bad_alloc, another
// exception), a sanitizer report, or a read beyond the input is a bug.
#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

#include "lbm/input_error.h"
#include "lbm/voxel_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const lbm::VoxelGeometry g = lbm::read_raw_voxels(in, "fuzz.raw");
    // A geometry read must be consistent with its header and have a fluid voxel.
    if (g.num_voxels() != std::size_t(g.dims()[0]) * g.dims()[1] * g.dims()[2] ||
        g.count_solid() == g.num_voxels())
      __builtin_trap();
  } catch (const lbm::InputError&) {
  }
  return 0;
}
