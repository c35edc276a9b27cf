#include "parse_number.h"

#include "error.h"
#include "lbm/input_error.h"
#include "number_text.h"

namespace lbm_pore {

double parse_number(LAMMPS_NS::Error* error, const char* command, const char* keyword,
                    const char* text, double min, bool min_inclusive, double max) {
  try {
    return number_in_range(command, keyword, text, min, min_inclusive, max);
  } catch (const lbm::InputError& e) {
    error->all(FLERR, e.what());
  }
  return 0.0;  // not reached: error->all does not return
}

int parse_integer(LAMMPS_NS::Error* error, const char* command, const char* keyword,
                  const char* text, int min, int max) {
  try {
    return integer_in_range(command, keyword, text, min, max);
  } catch (const lbm::InputError& e) {
    error->all(FLERR, e.what());
  }
  return 0;  // not reached
}

}  // namespace lbm_pore
