#include "compute_lbm_bonds.h"

#include <mpi.h>

#include "error.h"
#include "force.h"
#include "pair_lbm_dashdot.h"
#include "update.h"

using namespace LAMMPS_NS;

ComputeLbmBonds::ComputeLbmBonds(LAMMPS* lmp, int& iarg, int narg, char** arg)
    : Compute(lmp, iarg, narg, arg) {
  if (narg != iarg)
    error->all(FLERR, "compute lbm/bonds: takes no keywords (syntax: compute ID group lbm/bonds)");
  scalar_flag = 1;
  extscalar = 0;
}

void ComputeLbmBonds::init() {
  pair_ = dynamic_cast<PairLbmDashdot*>(force->pair_match("lbm/dashdot", 1));
  if (pair_ == nullptr)
    error->all(FLERR, "compute lbm/bonds needs pair_style lbm/dashdot");
}

double ComputeLbmBonds::compute_scalar() {
  invoked_scalar = update->ntimestep;
  const double local = pair_->local_bond_count();
  MPI_Allreduce(&local, &scalar, 1, MPI_DOUBLE, MPI_SUM, world);
  return scalar;
}
