#include "pair_lbm_dashdot.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include "atom.h"
#include "comm.h"
#include "dashdot_arguments.h"
#include "error.h"
#include "fix.h"
#include "force.h"
#include "group.h"
#include "lbm/input_error.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "plugin_common/stop_run.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
constexpr const char* kStyle = "pair_style lbm/dashdot";

// The words of this style's guard messages, in the order of lbm_pore::GuardWording.
const lbm_pore::GuardWording kGuardWording{kStyle, "contact time", "the lightest particles",
                                           "the smaller radius", "they pass through each other", "kn"};
}  // namespace

PairLbmDashdot::PairLbmDashdot(LAMMPS* lmp) : Pair(lmp), guards_(lmp, kGuardWording) {
  single_enable = 0;
  restartinfo = 0;
}

PairLbmDashdot::~PairLbmDashdot() {
  if (allocated) {
    memory->destroy(setflag);
    memory->destroy(cutsq);
  }
}

void PairLbmDashdot::allocate() {
  allocated = 1;
  const int n = atom->ntypes;
  memory->create(setflag, n + 1, n + 1, "pair:setflag");
  memory->create(cutsq, n + 1, n + 1, "pair:cutsq");
  for (int i = 0; i <= n; ++i)
    for (int j = 0; j <= n; ++j) setflag[i][j] = 0;
  params_.assign(n + 1, std::vector<contact::PairContactParams>(n + 1, defaults_));
  max_radius_.assign(n + 1, 0.0);
}

void PairLbmDashdot::parse_coefficients(int first, int narg, char** arg,
                                        contact::PairContactParams& params,
                                        const char* command) {
  try {
    lbm_pore::parse_dashdot_coefficients(std::vector<std::string>(arg + first, arg + narg), params,
                                         command);
  } catch (const lbm::InputError& e) {
    error->all(FLERR, e.what());
  }
}

void PairLbmDashdot::settings(int narg, char** arg) {
  defaults_ = contact::PairContactParams{};
  parse_coefficients(0, narg, arg, defaults_, kStyle);
}

void PairLbmDashdot::coeff(int narg, char** arg) {
  if (narg < 2) error->all(FLERR, "pair_coeff lbm/dashdot: expected 'pair_coeff I J [kn v] [kc v] [damping v]'");
  if (!allocated) allocate();
  int ilo, ihi, jlo, jhi;
  force->bounds(arg[0], atom->ntypes, ilo, ihi);
  force->bounds(arg[1], atom->ntypes, jlo, jhi);
  contact::PairContactParams params = defaults_;
  parse_coefficients(2, narg, arg, params, "pair_coeff lbm/dashdot");
  int count = 0;
  for (int i = ilo; i <= ihi; ++i)
    for (int j = std::max(jlo, i); j <= jhi; ++j) {
      params_[i][j] = params_[j][i] = params;
      setflag[i][j] = 1;
      ++count;
    }
  if (count == 0) error->all(FLERR, "pair_coeff lbm/dashdot: no atom types in the given range");
}

void PairLbmDashdot::init_style() {
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "pair_style lbm/dashdot needs per-atom radius and mass (atom_style granular or sphere)");
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "pair_style lbm/dashdot needs ghost velocities: add 'communicate single vel yes'");

  // A granular half list: pairs within (Ri + Rj) * contactDistanceFactor + skin.
  const int request = neighbor->request(this);
  neighbor->requests[request]->half = 0;
  neighbor->requests[request]->gran = 1;

  // Cohesion reaches 0.03 (Ri + Rj) beyond contact: widen the neighbour search by that
  // factor (only when some pair is cohesive; "leave out what a scene does not need").
  double range_factor = 0.0;
  for (int i = 1; i <= atom->ntypes; ++i)
    for (int j = i; j <= atom->ntypes; ++j)
      if (params_[i][j].cohesion.k_c > 0.0)
        range_factor = std::max(range_factor, params_[i][j].cohesion.range_factor);
  distance_factor_ = 1.0 + range_factor;
  neighbor->register_contact_dist_factor(distance_factor_);

  find_max_radius_per_type();
  check_time_step();
  guards_.start_run();
}

void PairLbmDashdot::find_max_radius_per_type() {
  // Particles inserted later (fix insert/..., fix pour) announce their largest radius, as the
  // stock granular pair styles use it; particles present now are scanned.
  const int ntypes = atom->ntypes;
  std::vector<double> local(ntypes + 1, 0.0);
  for (int f = 0; f < modify->nfix; ++f) {
    if (!modify->fix[f]->use_rad_for_cut_neigh_and_ghost()) continue;
    for (int t = 1; t <= ntypes; ++t) local[t] = std::max(local[t], modify->fix[f]->max_rad(t));
  }
  for (int i = 0; i < atom->nlocal; ++i)
    local[atom->type[i]] = std::max(local[atom->type[i]], atom->radius[i]);
  MPI_Allreduce(local.data(), max_radius_.data(), ntypes + 1, MPI_DOUBLE, MPI_MAX, world);
}

// The lightest pair of particles present has the shortest contact; refuse a step that
// resolves it with too few steps (t_c of paper Eq. 1 with damping; the shortest over the
// pair coefficients). Called at init and whenever the global atom count changes
// (insertion), by every rank.
void PairLbmDashdot::check_time_step() {
  const std::optional<double> min_mass = guards_.lightest_mass(group->bitmask[group->find("all")]);
  if (!min_mass) return;  // no particles yet
  lbm_pore::TimeStepFinding found;
  found.stiffness_name = "kn";
  found.lightest_mass = *min_mass;
  found.limit.contact_time = 1e300;
  for (int i = 1; i <= atom->ntypes; ++i)
    for (int j = i; j <= atom->ntypes; ++j) {
      const contact::TimeStepLimit limit = contact::pair_time_step_limit(params_[i][j], *min_mass);
      if (limit.contact_time < found.limit.contact_time) {
        found.limit = limit;
        found.stiffness = params_[i][j].normal.k_n;
      }
    }
  guards_.check_time_step(found);
}

double PairLbmDashdot::init_one(int i, int j) {
  if (setflag[i][j] == 0) {
    // Unset pairs take the pair_style defaults (no mixing rule is needed: one set per pair).
    params_[i][j] = params_[j][i] = defaults_;
  }
  return (max_radius_[i] + max_radius_[j]) * distance_factor_;
}

void PairLbmDashdot::compute(int eflag, int vflag) {
  if (eflag || vflag) ev_setup(eflag, vflag);
  else evflag = vflag_fdotr = 0;

  // Particles inserted during the run (fix insert/..., fix pour) may be lighter than those
  // checked at init; all ranks take this branch together, one reduction per insertion.
  if (guards_.atom_count_changed()) check_time_step();

  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const int* type = atom->type;
  const int nlocal = atom->nlocal;
  const int newton_pair = force->newton_pair;
  const int inum = list->inum;
  const int* ilist = list->ilist;
  const int* numneigh = list->numneigh;
  int** firstneigh = list->firstneigh;

  double bonds = 0.0;
  double worst_overlap = 0.0;  // largest overlap / smaller radius, and its pair
  int worst_i = -1, worst_j = -1;
  for (int ii = 0; ii < inum; ++ii) {
    const int i = ilist[ii];
    const double xi = x[i][0], yi = x[i][1], zi = x[i][2];
    if (!std::isfinite(xi + yi + zi)) {
      char text[300];
      std::snprintf(text, sizeof text,
                    "pair_style lbm/dashdot: particle %d has a non-finite position (%g %g %g) at "
                    "step " BIGINT_FORMAT "; the run became unstable before this step",
                    atom->tag[i], xi, yi, zi, update->ntimestep);
      lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, text);
    }
    const double ri = radius[i];
    const int itype = type[i];
    const int* jlist = firstneigh[i];
    const int jnum = numneigh[i];
    for (int jj = 0; jj < jnum; ++jj) {
      const int j = jlist[jj] & NEIGHMASK;
      const double dx = xi - x[j][0], dy = yi - x[j][1], dz = zi - x[j][2];
      const double rsq = dx * dx + dy * dy + dz * dz;
      const double rj = radius[j];
      const double radsum = ri + rj;
      const contact::PairContactParams& params = params_[itype][type[j]];
      const double reach = radsum * (1.0 + params.cohesion.range_factor);
      if (rsq >= reach * reach) continue;
      const double r = std::sqrt(rsq);
      const double inv_r = 1.0 / r;
      contact::PairContactInput in;
      in.gap = r - radsum;
      if (in.gap > 0.0 && params.cohesion.k_c <= 0.0) continue;  // no cohesion: no bond
      in.gap_rate = (dx * (v[i][0] - v[j][0]) + dy * (v[i][1] - v[j][1]) +
                     dz * (v[i][2] - v[j][2])) * inv_r;
      in.radius_i = ri;
      in.radius_j = rj;
      in.effective_mass = contact::pair_effective_mass(rmass[i], rmass[j]);
      const double fpair = contact::pair_normal_force(params, in) * inv_r;
      if (in.gap < 0.0) {
        const double ratio = -in.gap / std::min(ri, rj);
        if (ratio > worst_overlap) { worst_overlap = ratio; worst_i = i; worst_j = j; }
      }
      if (!std::isfinite(fpair)) {
        char text[300];
        std::snprintf(text, sizeof text,
                      "pair_style lbm/dashdot: non-finite contact force between particles %d and "
                      "%d at step " BIGINT_FORMAT " (gap %g, gap rate %g); the run became unstable",
                      atom->tag[i], atom->tag[j], update->ntimestep, in.gap, in.gap_rate);
        lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, text);
      }
      const double fx = dx * fpair, fy = dy * fpair, fz = dz * fpair;
      f[i][0] += fx;
      f[i][1] += fy;
      f[i][2] += fz;
      const bool owns_j = newton_pair || j < nlocal;
      if (owns_j) {
        f[j][0] -= fx;
        f[j][1] -= fy;
        f[j][2] -= fz;
      }
      bonds += owns_j ? 1.0 : 0.5;  // a pair with a ghost is seen by both ranks
      if (evflag) ev_tally_xyz(i, j, nlocal, newton_pair, 0.0, 0.0, fx, fy, fz, dx, dy, dz);
    }
  }
  bond_count_local_ = bonds;
  max_overlap_ratio_ = worst_overlap;
  if (guards_.overlap_needs_report(worst_overlap)) {
    char subject[100];
    std::snprintf(subject, sizeof subject, "particles %d and %d overlap", atom->tag[worst_i],
                  atom->tag[worst_j]);
    guards_.report_overlap(worst_overlap, subject);
  }
  if (vflag_fdotr) virial_fdotr_compute();
}

void* PairLbmDashdot::extract(const char* name, int& dim) {
  dim = 0;
  if (std::strcmp(name, "bonds") == 0) return &bond_count_local_;
  // t_c / 10 (0: no particles yet); callers only read it.
  if (std::strcmp(name, "dt_max") == 0) return const_cast<double*>(&guards_.time_step_limit());
  if (std::strcmp(name, "max_overlap_ratio") == 0) return &max_overlap_ratio_;  // this rank, last step
  return nullptr;
}
