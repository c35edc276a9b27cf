#pragma once
// What every entry point of our styles (constructor, init, setup, post_force, ...) needs so
// that nothing ends in "terminate called": turning an exception into a LIGGGHTS error, and
// refusing a second instance of a fix that must be alone in a run.
namespace LAMMPS_NS {
class Error;
class Fix;
class Modify;
}  // namespace LAMMPS_NS

namespace lbm_pore {

enum class ErrorScope {
  kAllRanks,  // the exception comes from input every rank checked alike: error->all
  kThisRank   // it may be thrown on some ranks only (a run-time guard): error->one
};

// Call inside `catch (...)`: reports the exception being handled as a LIGGGHTS error whose
// message starts with `command` ("fix lbm/pore: ..."), once. lbm::InputError gives its own
// message (it names the keyword and the range) on `scope`; std::bad_alloc says the memory ran
// out and what to lower; any other exception its what() on this rank. Does not return.
void report_current_exception(LAMMPS_NS::Error* error, const char* command, ErrorScope scope);

// error->all when `modify` holds another fix of `self`'s style (a fix of the same ID is being
// replaced, so it does not count): e.g. two fix lbm/pore would own two fluids in one box.
void refuse_second_instance(LAMMPS_NS::Modify* modify, LAMMPS_NS::Error* error,
                            const LAMMPS_NS::Fix* self);

}  // namespace lbm_pore
