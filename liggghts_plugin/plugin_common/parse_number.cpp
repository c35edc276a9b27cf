#include "parse_number.h"

#include <cstring>
#include <string>

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

int parse_choice(LAMMPS_NS::Error* error, const char* command, const char* keyword,
                 const char* text, std::initializer_list<const char*> choices) {
  int position = 0;
  std::string valid;
  for (const char* choice : choices) {
    if (std::strcmp(text, choice) == 0) return position;
    if (position > 0) valid += position + 1 == static_cast<int>(choices.size()) ? " or " : ", ";
    valid += choice;
    ++position;
  }
  const std::string message = std::string(command) + ": " + keyword + " must be " + valid +
                              " (got '" + text + "')";
  error->all(FLERR, message.c_str());
  return -1;  // not reached: error->all stops the run
}

}  // namespace lbm_pore
