#include "plugin_common/restart_version.h"

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <map>
#include <string>

// LIGGGHTS headers (SYSTEM include path, they are not -Wall clean).
#include "comm.h"
#include "domain.h"
#include "fix.h"
#include "input.h"
#include "lammps.h"
#include "lmptype.h"
#include "modify.h"
#include "output.h"
#include "universe.h"
#include "update.h"

#include "registry/private_access.h"

namespace lbm_pore {

// Input's command map and Output's next restart step are protected and private; the order in
// which Modify calls the fixes at the end and the start of a step is protected
// (registry/private_access.h).
using CommandCreator = void (*)(LAMMPS_NS::LAMMPS*, int, char**);
struct InputCommandMapTag {
  using type = std::map<std::string, CommandCreator>* LAMMPS_NS::Input::*;
  friend type member_pointer(InputCommandMapTag);
};
struct OutputNextRestartTag {
  using type = LAMMPS_NS::bigint LAMMPS_NS::Output::*;
  friend type member_pointer(OutputNextRestartTag);
};
struct ModifyEndOfStepTag {
  using type = int* LAMMPS_NS::Modify::*;
  friend type member_pointer(ModifyEndOfStepTag);
};
struct ModifyPreInitialIntegrateTag {
  using type = int* LAMMPS_NS::Modify::*;
  friend type member_pointer(ModifyPreInitialIntegrateTag);
};
template struct StealMemberPointer<InputCommandMapTag, &LAMMPS_NS::Input::command_map>;
template struct StealMemberPointer<OutputNextRestartTag, &LAMMPS_NS::Output::next_restart>;
template struct StealMemberPointer<ModifyEndOfStepTag, &LAMMPS_NS::Modify::list_end_of_step>;
template struct StealMemberPointer<ModifyPreInitialIntegrateTag,
                                   &LAMMPS_NS::Modify::list_pre_initial_integrate>;

namespace {

constexpr const char* kFixId = "lbm_restart_version";

// The six letters "PUBLIC" within the Universe's version string (which it owns and deletes),
// null until keep_restart_files_stock found them, and the whole string as LIGGGHTS made it.
char* edition = nullptr;
std::string stock_version;

// Only rank 0 of a run writes a restart file's header and compares the version read: the
// other ranks keep "public" throughout, so an error they raise is never followed by the joke.
void show_stock_version(LAMMPS_NS::LAMMPS* lmp) {
  if (edition && lmp->comm->me == 0) std::memcpy(edition, "PUBLIC", 6);
}
void hide_public_edition() {
  if (edition) std::memcpy(edition, "public", 6);
}

// LIGGGHTS's own string for the lifetime of the object. An error within ends the process.
struct StockVersion {
  explicit StockVersion(LAMMPS_NS::LAMMPS* lmp) { show_stock_version(lmp); }
  ~StockVersion() { hide_public_edition(); }
  StockVersion(const StockVersion&) = delete;
  StockVersion& operator=(const StockVersion&) = delete;
};

// Whether read_restart needs LIGGGHTS's own string to read `name` without the warning: the
// file's first record (VERSION = 0, the length, the string) is that string. A file that is
// missing or says otherwise is left to LIGGGHTS with "public" (its error, or its warning for
// a file of another version, comes without the joke). read_restart resolves a name with '*'
// (the newest file) and reads the header of a '%' set from another file: those it reads
// with LIGGGHTS's string.
bool written_by_this_liggghts(const char* name) {
  if (std::strpbrk(name, "*%")) return true;
  FILE* file = std::fopen(name, "rb");
  if (!file) return false;
  int record[2] = {-1, 0};
  std::string version(stock_version.size() + 1, '\0');
  const bool same = std::fread(record, sizeof(int), 2, file) == 2 && record[0] == 0 &&
                    record[1] == static_cast<int>(version.size()) &&
                    std::fread(version.data(), 1, version.size(), file) == version.size() &&
                    std::strcmp(version.c_str(), stock_version.c_str()) == 0;
  std::fclose(file);
  return same;
}

// LIGGGHTS's own creators of the wrapped commands.
CommandCreator stock_read_restart = nullptr;
CommandCreator stock_write_restart = nullptr;
CommandCreator stock_run = nullptr;

void read_restart(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  if (narg < 1 || (lmp->comm->me == 0 && !written_by_this_liggghts(arg[0]))) {
    stock_read_restart(lmp, narg, arg);
    return;
  }
  StockVersion stock(lmp);
  stock_read_restart(lmp, narg, arg);
}

void write_restart(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  StockVersion stock(lmp);
  stock_write_restart(lmp, narg, arg);
}

void run(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  // Without a box the run stops with LIGGGHTS's error; after `clear` the fix is added anew.
  if (lmp->domain->box_exist && lmp->modify->find_fix(kFixId) < 0) {
    std::string id = kFixId, group = "all", style = kRestartVersionFixStyle;
    char* args[] = {id.data(), group.data(), style.data()};
    lmp->modify->add_fix(3, args);
  }
  stock_run(lmp, narg, arg);
  hide_public_edition();
}

// Moves `value` to the front or the back of list[0..n), keeping the others' order.
void move_to_front(int* list, int n, int value) {
  int* at = std::find(list, list + n, value);
  if (at != list + n) std::rotate(list, at, at + 1);
}
void move_to_back(int* list, int n, int value) {
  int* at = std::find(list, list + n, value);
  if (at != list + n) std::rotate(at, at + 1, list + n);
}

class FixRestartVersion : public LAMMPS_NS::Fix {
 public:
  FixRestartVersion(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {}

  int setmask() override {
    return LAMMPS_NS::FixConst::PRE_INITIAL_INTEGRATE | LAMMPS_NS::FixConst::END_OF_STEP |
           LAMMPS_NS::FixConst::POST_RUN;
  }

  // Modify::init builds its lists of fixes in definition order, then calls each fix's init:
  // this fix goes last at the end of a step (after fix lbm/pore's fluid step and every other
  // fix's work) and first at the start of the next.
  void init() override {
    const int self = modify->find_fix(id);
    move_to_back(modify->*member_pointer(ModifyEndOfStepTag{}), modify->n_end_of_step, self);
    move_to_front(modify->*member_pointer(ModifyPreInitialIntegrateTag{}),
                  modify->n_pre_initial_integrate, self);
  }

  // Output::write follows: it writes restart files when the step is Output's next restart
  // step (its own schedule, or LIGGGHTS's forced restart on a signal, which Neighbor::decide
  // made this step's).
  void end_of_step() override {
    if (output->*member_pointer(OutputNextRestartTag{}) == update->ntimestep)
      show_stock_version(lmp);
  }
  void pre_initial_integrate() override { hide_public_edition(); }
  void post_run() override { hide_public_edition(); }
};

}  // namespace

LAMMPS_NS::Fix* create_restart_version_fix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new FixRestartVersion(lmp, narg, arg);
}

void keep_restart_files_stock(LAMMPS_NS::LAMMPS* lmp) {
  if (edition) return;
  char* at = std::strstr(lmp->universe->version, "PUBLIC");
  if (!at) return;
  edition = at;
  stock_version = lmp->universe->version;
  hide_public_edition();
  auto& commands = *(lmp->input->*member_pointer(InputCommandMapTag{}));
  auto wrap = [&commands](const char* name, CommandCreator& stock, CommandCreator wrapper) {
    auto found = commands.find(name);
    if (found == commands.end()) return;
    stock = found->second;
    found->second = wrapper;
  };
  wrap("read_restart", stock_read_restart, &read_restart);
  wrap("write_restart", stock_write_restart, &write_restart);
  wrap("run", stock_run, &run);
}

}  // namespace lbm_pore
