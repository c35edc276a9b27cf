#pragma once
// fix ID group insert/pack/gap min_gap G <the keywords of insert/pack>
//
// LIGGGHTS's insert/pack (its region, volume fraction, templates, seed and schedule,
// unchanged) with the paper's minimum distance: every particle it inserts keeps a surface
// gap of at least G (length units) from every other particle, inserted in the same step or
// already there. insert/pack itself checks overlap only (gap 0). The check of insert/pack
// is kept and fed inflated spheres: while a step's insertion runs, the particles already in
// the box and the ones being placed count as G/2 larger, so that two accepted spheres are at
// least G apart; the inserted particles get their own radius and mass.
// (liggghts_plugin/doc/fix_insert_pack_gap.txt)
#include <vector>

#include "fix_insert_pack.h"

namespace LAMMPS_NS {

class FixInsertPackGap : public FixInsertPack {
 public:
  FixInsertPackGap(class LAMMPS* lmp, int narg, char** arg);

  double min_gap() const { return gap_; }

 protected:
  // The existing particles near the region, each entered G/2 larger (FixInsert::load_xnear).
  int load_xnear(int ninsert_this_local) override;
  // The particles of this step placed as G/2 larger spheres (FixInsertPack::x_v_omega).
  void x_v_omega(int ninsert_this_local, int& ninserted_this_local,
                 int& ninserted_spheres_this_local, double& mass_inserted_this_local) override;

 private:
  // The arguments without 'min_gap G', and G.
  struct Arguments {
    Arguments(class LAMMPS* lmp, int narg, char** arg);
    std::vector<char*> words;
    double gap = 0.0;
  };
  FixInsertPackGap(class LAMMPS* lmp, const Arguments& args);

  double gap_;
  double maxrad_unchanged_ = 0.0;
};

}  // namespace LAMMPS_NS
