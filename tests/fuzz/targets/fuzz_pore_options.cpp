// libFuzzer target: the keyword parser of fix lbm/pore (lbm_pore::parse_pore_options) on the
// words of arbitrary text. Bad input must give lbm::InputError; options it accepts must obey
// the documented ranges.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_words.h"
#include "lbm/input_error.h"
#include "lbm_pore_options.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    const lbm_pore::PoreOptions o = lbm_pore::parse_pore_options(fuzz_words(data, size));
    const bool valid = o.dx > 0 && std::isfinite(o.dx) && o.rho > 0 && o.nu > 0 && o.n_dem >= 1 &&
                       o.drive_value >= 0 && std::isfinite(o.drive_value) &&
                       o.pore_diameter <= o.width && o.scene != lbm_pore::PoreOptions::Scene::kNone;
    if (!valid) __builtin_trap();
  } catch (const lbm::InputError&) {
  }
  return 0;
}
