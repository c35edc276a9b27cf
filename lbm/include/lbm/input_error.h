#pragma once
#include <stdexcept>
#include <string>

namespace lbm {
// Thrown for bad user input (a keyword out of range, a malformed voxel file). The message
// names the keyword or file and the valid range, so a host (the LIGGGHTS fix) can pass it
// straight to its own error mechanism.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message) : std::runtime_error(message) {}
};
}  // namespace lbm
