#include "parse_number.h"

#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include "error.h"

namespace lbm_pore {

namespace {
std::string range_text(double min, bool min_inclusive, double max) {
  char buffer[128];
  if (max >= 1e300)
    std::snprintf(buffer, sizeof buffer, "a number %s %g", min_inclusive ? ">=" : ">", min);
  else
    std::snprintf(buffer, sizeof buffer, "a number in %s%g, %g]", min_inclusive ? "[" : "(",
                  min, max);
  return buffer;
}
}  // namespace

double parse_number(LAMMPS_NS::Error* error, const char* command, const char* keyword,
                    const char* text, double min, bool min_inclusive, double max) {
  char* end = nullptr;
  errno = 0;
  const double value = std::strtod(text, &end);
  const bool parsed = end != text && *end == '\0' && errno == 0 && std::isfinite(value);
  const bool in_range = parsed && (min_inclusive ? value >= min : value > min) && value <= max;
  if (!in_range) {
    const std::string message = std::string(command) + ": " + keyword + " must be " +
                                range_text(min, min_inclusive, max) + " (got '" + text + "')";
    error->all(FLERR, message.c_str());
  }
  return value;
}

int parse_integer(LAMMPS_NS::Error* error, const char* command, const char* keyword,
                  const char* text, int min, int max) {
  char* end = nullptr;
  errno = 0;
  const long value = std::strtol(text, &end, 10);
  if (end == text || *end != '\0' || errno != 0 || value < min || value > max) {
    char message[256];
    std::snprintf(message, sizeof message, "%s: %s must be an integer in [%d, %d] (got '%s')",
                  command, keyword, min, max, text);
    error->all(FLERR, message);
  }
  return static_cast<int>(value);
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
