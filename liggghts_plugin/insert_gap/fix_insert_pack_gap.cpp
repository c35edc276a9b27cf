#include "fix_insert_pack_gap.h"

#include <cstring>

#include "atom.h"
#include "error.h"
#include "fix_particledistribution_discrete.h"
#include "particleToInsert.h"
#include "plugin_common/parse_number.h"

namespace LAMMPS_NS {

namespace {
constexpr const char* kCommand = "fix insert/pack/gap";
constexpr const char* kBaseStyle = "insert/pack";
constexpr const char* kStyle = "insert/pack/gap";
}

FixInsertPackGap::Arguments::Arguments(LAMMPS* lmp, int narg, char** arg) {
  bool found = false;
  for (int i = 0; i < narg; ++i) {
    if (i >= 3 && std::strcmp(arg[i], "min_gap") == 0) {
      if (found) lmp->error->all(FLERR, "fix insert/pack/gap: min_gap given twice");
      if (i + 1 >= narg) lmp->error->all(FLERR, "fix insert/pack/gap: min_gap needs a value (a length >= 0)");
      gap = lbm_pore::parse_number(lmp->error, kCommand, "min_gap", arg[i + 1], 0.0, true, 1e300);
      found = true;
      ++i;
      continue;
    }
    words.push_back(arg[i]);
  }
  // insert/pack parses its keywords (and refuses unknown ones) only under its own style
  // name: the base is built as insert/pack, and the style renamed after (the constructor).
  if (words.size() > 2) words[2] = const_cast<char*>(kBaseStyle);
  if (!found)
    lmp->error->all(FLERR, "fix insert/pack/gap: min_gap G is required (the smallest surface gap, "
                           "a length >= 0; the paper's 0.25 d)");
}

FixInsertPackGap::FixInsertPackGap(LAMMPS* lmp, int narg, char** arg)
    : FixInsertPackGap(lmp, Arguments(lmp, narg, arg)) {}

FixInsertPackGap::FixInsertPackGap(LAMMPS* lmp, const Arguments& args)
    : FixInsertPack(lmp, int(args.words.size()), const_cast<char**>(args.words.data())), gap_(args.gap) {
  // The fix's own name again, in messages and in restart files (which match a fix to its
  // record by ID and style).
  delete[] style;
  style = new char[std::strlen(kStyle) + 1];
  std::strcpy(style, kStyle);
}

int FixInsertPackGap::load_xnear(int ninsert_this_local) {
  // The neighbour list of the insertion bins its spheres by maxrad: it grows by G/2 for this
  // step's insertion (x_v_omega puts it back), and the radii of the particles already there
  // by G/2 while they are entered (put back bit for bit right after).
  maxrad_unchanged_ = maxrad;
  maxrad += 0.5 * gap_;
  const int nall = atom->nlocal + atom->nghost;
  std::vector<double> radius(atom->radius, atom->radius + nall);
  for (int i = 0; i < nall; ++i) atom->radius[i] += 0.5 * gap_;
  const int near = FixInsertPack::load_xnear(ninsert_this_local);
  std::copy(radius.begin(), radius.end(), atom->radius);
  return near;
}

void FixInsertPackGap::x_v_omega(int ninsert_this_local, int& ninserted_this_local,
                                 int& ninserted_spheres_this_local, double& mass_inserted_this_local) {
  // The particles of this step, G/2 larger while they are placed; insert() later creates
  // them with the radius and mass of their template.
  // Their bounding radius too: insert/pack keeps a particle that far from its rank's
  // sub-domain borders, which is what keeps apart two particles placed on either side of a
  // periodic or rank boundary (the neighbour list sees no images of this step's particles).
  ParticleToInsert** list = fix_distribution->pti_list;
  std::vector<double> radius;
  for (int i = 0; i < ninsert_this_local; ++i) {
    radius.push_back(list[i]->r_bound_ins);
    list[i]->r_bound_ins += 0.5 * gap_;
    for (int s = 0; s < list[i]->nparticles; ++s) {
      radius.push_back(list[i]->radius_ins[s]);
      list[i]->radius_ins[s] += 0.5 * gap_;
    }
  }
  FixInsertPack::x_v_omega(ninsert_this_local, ninserted_this_local, ninserted_spheres_this_local,
                           mass_inserted_this_local);
  std::size_t k = 0;
  for (int i = 0; i < ninsert_this_local; ++i) {
    list[i]->r_bound_ins = radius[k++];
    for (int s = 0; s < list[i]->nparticles; ++s) list[i]->radius_ins[s] = radius[k++];
  }
  maxrad = maxrad_unchanged_;
}

}  // namespace LAMMPS_NS
