#include "entry_guard.h"

#include <cstring>
#include <exception>
#include <new>
#include <string>

#include "error.h"
#include "fix.h"
#include "lbm/input_error.h"
#include "modify.h"

namespace lbm_pore {

namespace {
std::string prefixed(const char* command, const std::string& what) {
  return what.rfind(command, 0) == 0 ? what : std::string(command) + ": " + what;
}
}  // namespace

void report_current_exception(LAMMPS_NS::Error* error, const char* command, ErrorScope scope) {
  std::string message;
  bool input = false;
  try {
    throw;
  } catch (const lbm::InputError& e) {
    message = prefixed(command, e.what());
    input = true;
  } catch (const std::bad_alloc&) {
    message = prefixed(
        command,
        "out of memory; lower the lattice size (raise dx, shrink the scene) or run on more "
        "ranks or machines");
  } catch (const std::exception& e) {
    message = prefixed(command, std::string("internal error: ") + e.what());
  } catch (...) {
    message = prefixed(command, "internal error: an exception of unknown type");
  }
  if (input && scope == ErrorScope::kAllRanks)
    error->all(FLERR, message.c_str());
  else
    error->one(FLERR, message.c_str());
}

void refuse_second_instance(LAMMPS_NS::Modify* modify, LAMMPS_NS::Error* error,
                            const LAMMPS_NS::Fix* self) {
  for (int i = 0; i < modify->nfix; ++i) {
    const LAMMPS_NS::Fix* other = modify->fix[i];
    if (!other || other == self || std::strcmp(other->style, self->style) != 0 ||
        std::strcmp(other->id, self->id) == 0)
      continue;
    const std::string message = std::string("fix ") + self->style + ": fix '" + other->id +
                                "' is a fix " + self->style +
                                " already; one owns the fluid and the geometry of a run ('unfix " +
                                other->id + "' first to replace it)";
    error->all(FLERR, message.c_str());
  }
}

}  // namespace lbm_pore
