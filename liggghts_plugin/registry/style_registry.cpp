#include "style_registry.h"

#include <string>

#include "private_access.h"

// LIGGGHTS headers (SYSTEM include path, they are not -Wall clean).
#include "error.h"
#include "force.h"
#include "lammps.h"
#include "modify.h"

// Our styles.
#include "dashdot/compute_lbm_bonds.h"
#include "dashdot/pair_lbm_dashdot.h"
#include "insert_gap/fix_insert_pack_gap.h"
#include "lbm_pore/fix_lbm_pore.h"
#include "plugin_common/restart_version.h"
#include "wall_voxel/fix_wall_voxel.h"

namespace lbm_pore {

template struct StealMemberPointer<ModifyFixMapTag, &LAMMPS_NS::Modify::fix_map>;
template struct StealMemberPointer<ModifyComputeMapTag, &LAMMPS_NS::Modify::compute_map>;

namespace {

template <class T>
LAMMPS_NS::Pair* create_pair(LAMMPS_NS::LAMMPS* lmp) { return new T(lmp); }
template <class T>
LAMMPS_NS::Fix* create_fix(LAMMPS_NS::LAMMPS* lmp, int narg, char** arg) {
  return new T(lmp, narg, arg);
}
template <class T>
LAMMPS_NS::Compute* create_compute(LAMMPS_NS::LAMMPS* lmp, int iarg, int narg, char** arg) {
  return new T(lmp, iarg, narg, arg);
}

struct PairStyle { const char* name; LAMMPS_NS::Force::PairCreator create; };
struct FixStyle { const char* name; FixCreator create; };
struct ComputeStyle { const char* name; ComputeCreator create; };

// ---- The style list: add new styles here (one line each). ----
const PairStyle kPairStyles[] = {
    {"lbm/dashdot", &create_pair<LAMMPS_NS::PairLbmDashdot>},
};
const FixStyle kFixStyles[] = {
    {"wall/voxel", &create_fix<LAMMPS_NS::FixWallVoxel>},
    {"lbm/pore", &create_fix<LAMMPS_NS::FixLbmPore>},
    {"insert/pack/gap", &create_fix<LAMMPS_NS::FixInsertPackGap>},
    // Not for input scripts: liggghts-lbm adds it to every run (plugin_common/restart_version.h).
    {lbm_pore::kRestartVersionFixStyle, &lbm_pore::create_restart_version_fix},
};
const ComputeStyle kComputeStyles[] = {
    {"lbm/bonds", &create_compute<LAMMPS_NS::ComputeLbmBonds>},
};
// ---------------------------------------------------------------

template <class Map, class Creator>
void insert_style(LAMMPS_NS::LAMMPS* lmp, Map& map, const char* kind, const char* name,
                  Creator create) {
  if (!map.emplace(name, create).second)
    lmp->error->all(FLERR, (std::string("liggghts-lbm: ") + kind + " style '" + name +
                            "' already exists in LIGGGHTS")
                               .c_str());
}

}  // namespace

void register_lbm_pore_styles(LAMMPS_NS::LAMMPS* lmp) {
  auto& pairs = *lmp->force->pair_map;
  auto& fixes = *(lmp->modify->*member_pointer(ModifyFixMapTag{}));
  auto& computes = *(lmp->modify->*member_pointer(ModifyComputeMapTag{}));
  for (const auto& s : kPairStyles) insert_style(lmp, pairs, "pair", s.name, s.create);
  for (const auto& s : kFixStyles) insert_style(lmp, fixes, "fix", s.name, s.create);
  for (const auto& s : kComputeStyles) insert_style(lmp, computes, "compute", s.name, s.create);
}

}  // namespace lbm_pore
