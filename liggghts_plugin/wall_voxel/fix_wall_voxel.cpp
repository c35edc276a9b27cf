#include "fix_wall_voxel.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <optional>
#include <string>

#include "atom.h"
#include "comm.h"
#include "error.h"
#include "lbm/input_error.h"
#include "lbm_pore/fix_lbm_pore.h"
#include "modify.h"
#include "plugin_common/entry_guard.h"
#include "plugin_common/stop_run.h"
#include "update.h"
#include "wall_geometry_source.h"
#include "wall_voxel_arguments.h"

using namespace LAMMPS_NS;

namespace {
constexpr const char* kCommand = "fix wall/voxel";
// Contacts of consecutive steps are the same contact when their normals are this close
// (cos 25 deg): a sphere rolling over an edge turns its normal slowly.
constexpr double kSameContactCosine = 0.9;

// The words of this style's guard messages, in the order of lbm_pore::GuardWording.
const lbm_pore::GuardWording kGuardWording{kCommand, "wall contact time", "the lightest particle",
                                           "its radius", "it passes through the wall", "kw"};
}  // namespace

FixWallVoxel::FixWallVoxel(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg), guards_(lmp, kGuardWording) {
  lbm_pore::WallVoxelArguments args;
  try {
    args = lbm_pore::parse_wall_voxel_arguments(std::vector<std::string>(arg + 3, arg + narg));
  } catch (const lbm::InputError& e) {
    error->all(FLERR, e.what());
  }
  params_ = args.params;
  try {
    use_geometry(args.lbm_fix_id.empty() ? lbm_pore::acquire_wall_geometry(args.source)
                                         : geometry_of_lbm_fix(args.lbm_fix_id.c_str()));
  } catch (...) {  // lbm::InputError naming the file or keyword; std::bad_alloc as a last resort
    lbm_pore::report_current_exception(error, kCommand, lbm_pore::ErrorScope::kAllRanks);
  }

  vector_flag = 1;
  size_vector = 6;
  global_freq = 1;
  extvector = -1;  // contacts and forces extensive; the time step limit and overlap ratio not
  extlist = new int[6]{1, 1, 1, 1, 0, 0};

  grow_arrays(atom->nmax);
  atom->add_callback(0);
}

FixWallVoxel::~FixWallVoxel() {
  atom->delete_callback(id, 0);
  delete[] extlist;
  extlist = nullptr;
}

int FixWallVoxel::setmask() { return FixConst::POST_FORCE; }

// The geometry fix lbm/pore owns, so the walls the particles touch are the fluid's walls.
std::shared_ptr<const lbm::VoxelGeometry> FixWallVoxel::geometry_of_lbm_fix(const char* fix_id) {
  const int index = modify->find_fix(fix_id);
  if (index < 0)
    error->all(FLERR, (std::string(kCommand) + ": lbm: no fix with ID '" + fix_id +
                       "' (define fix lbm/pore before fix wall/voxel)").c_str());
  auto* lbm_fix = dynamic_cast<FixLbmPore*>(modify->fix[index]);
  if (!lbm_fix)
    error->all(FLERR, (std::string(kCommand) + ": lbm: fix '" + fix_id + "' is " +
                       modify->fix[index]->style + ", not lbm/pore").c_str());
  return lbm_fix->shared_geometry();
}

void FixWallVoxel::use_geometry(std::shared_ptr<const lbm::VoxelGeometry> geometry) {
  geometry_ = std::move(geometry);
  surface_ = std::make_unique<contact::VoxelSurface>(*geometry_);
}

void FixWallVoxel::init() {
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "fix wall/voxel needs per-atom radius and mass (atom_style granular or sphere)");
  check_time_step();
  guards_.start_run();
}

// Called at init and whenever the global atom count changes (insertion), by every rank.
void FixWallVoxel::check_time_step() {
  const std::optional<double> min_mass = guards_.lightest_mass(groupbit);
  if (!min_mass) return;  // no particles yet
  lbm_pore::TimeStepFinding found;
  found.stiffness_name = contact::wall_tangential_spring_is_stiffer(params_) ? "kt" : "kw";
  found.stiffness = contact::wall_stiffest_spring(params_).k_n;
  found.lightest_mass = *min_mass;
  found.limit = contact::wall_time_step_limit(params_, *min_mass);
  guards_.check_time_step(found);
}

void FixWallVoxel::stop_on_non_finite(int i, const char* what) {
  char text[400];
  std::snprintf(text, sizeof text,
                "fix wall/voxel: particle %d has a non-finite %s at step " BIGINT_FORMAT
                " (position %g %g %g, force so far %g %g %g): the run is unstable; stopping before the "
                "NaN spreads",
                atom->tag[i], what, update->ntimestep, atom->x[i][0], atom->x[i][1], atom->x[i][2],
                atom->f[i][0], atom->f[i][1], atom->f[i][2]);
  lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, text);
}

void FixWallVoxel::setup(int vflag) { post_force(vflag); }

void FixWallVoxel::post_force(int /*vflag*/) {
  double** x = atom->x;
  double** v = atom->v;
  double** f = atom->f;
  const double* radius = atom->radius;
  const double* rmass = atom->rmass;
  const int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double dt = update->dt;
  std::fill(local_stats_, local_stats_ + 5, 0.0);
  stats_reduced_ = false;
  // Particles inserted during the run may be lighter than those checked at init; all ranks
  // take this branch together, one reduction per insertion.
  if (guards_.atom_count_changed()) check_time_step();
  double worst_overlap = 0.0;
  int worst_i = -1;

  constexpr int kStride = kMaxContacts * kHistoryPerContact;
  double fresh[kStride];
  for (int i = 0; i < nlocal; ++i) {
    double* history = &history_[static_cast<std::size_t>(i) * kStride];
    if (!(mask[i] & groupbit)) continue;
    // A NaN centre would send the surface search out of bounds; a NaN force (from the pair,
    // the fluid or a fix before this one) would make the position NaN at the next step.
    if (!std::isfinite(x[i][0] + x[i][1] + x[i][2] + f[i][0] + f[i][1] + f[i][2]))
      stop_on_non_finite(i, std::isfinite(x[i][0] + x[i][1] + x[i][2]) ? "force" : "position");
    const double reach = contact::wall_contact_reach(params_, radius[i]);
    const contact::Vec3 centre{x[i][0], x[i][1], x[i][2]};
    surface_->find(centre, reach, points_);
    if (points_.empty()) {
      std::fill(history, history + kStride, 0.0);
      continue;
    }
    std::fill(fresh, fresh + kStride, 0.0);
    bool used[kMaxContacts] = {};
    int stored = 0;
    contact::Vec3 total;
    for (const contact::SurfacePoint& point : points_) {
      contact::WallContactInput in;
      in.normal = point.normal;
      in.gap = point.distance - radius[i];
      in.radius = radius[i];
      in.mass = rmass[i];
      in.velocity = {v[i][0], v[i][1], v[i][2]};
      in.dt = dt;
      // The same contact as last step: the stored normal that points the same way.
      for (int s = 0; s < kMaxContacts; ++s) {
        const double* slot = history + s * kHistoryPerContact;
        const contact::Vec3 old_normal{slot[0], slot[1], slot[2]};
        if (!used[s] && contact::dot(old_normal, point.normal) > kSameContactCosine) {
          used[s] = true;
          in.spring = {slot[3], slot[4], slot[5]};
          break;
        }
      }
      const contact::WallContactResult result = contact::wall_contact_force(params_, in);
      total += result.force;
      if (in.gap < 0.0 && -in.gap > worst_overlap * radius[i]) {
        worst_overlap = -in.gap / radius[i];
        worst_i = i;
      }
      if (result.active) {
        local_stats_[0] += 1.0;
        if (stored < kMaxContacts) {
          double* slot = fresh + stored * kHistoryPerContact;
          slot[0] = point.normal.x; slot[1] = point.normal.y; slot[2] = point.normal.z;
          slot[3] = result.spring.x; slot[4] = result.spring.y; slot[5] = result.spring.z;
          ++stored;
        }
      }
    }
    std::copy(fresh, fresh + kStride, history);
    f[i][0] += total.x;
    f[i][1] += total.y;
    f[i][2] += total.z;
    if (!std::isfinite(total.x + total.y + total.z)) stop_on_non_finite(i, "wall force");
    local_stats_[1] += total.x;
    local_stats_[2] += total.y;
    local_stats_[3] += total.z;
  }
  local_stats_[4] = worst_overlap;
  if (guards_.overlap_needs_report(worst_overlap)) {
    char subject[200];
    std::snprintf(subject, sizeof subject, "particle %d at (%g %g %g) overlaps the wall",
                  atom->tag[worst_i], x[worst_i][0], x[worst_i][1], x[worst_i][2]);
    guards_.report_overlap(worst_overlap, subject);
  }
}

double FixWallVoxel::compute_vector(int index) {
  if (index == 4) return guards_.time_step_limit();
  if (!stats_reduced_) {
    MPI_Allreduce(local_stats_, global_stats_, 4, MPI_DOUBLE, MPI_SUM, world);
    MPI_Allreduce(&local_stats_[4], &global_stats_[4], 1, MPI_DOUBLE, MPI_MAX, world);
    stats_reduced_ = true;
  }
  return index == 5 ? global_stats_[4] : global_stats_[index];
}

void FixWallVoxel::grow_arrays(int nmax) {
  history_.resize(static_cast<std::size_t>(nmax) * kMaxContacts * kHistoryPerContact, 0.0);
}

void FixWallVoxel::copy_arrays(int i, int j, int /*delflag*/) {
  constexpr int kStride = kMaxContacts * kHistoryPerContact;
  std::copy_n(&history_[static_cast<std::size_t>(i) * kStride], kStride,
              &history_[static_cast<std::size_t>(j) * kStride]);
}

int FixWallVoxel::pack_exchange(int i, double* buf) {
  constexpr int kStride = kMaxContacts * kHistoryPerContact;
  std::copy_n(&history_[static_cast<std::size_t>(i) * kStride], kStride, buf);
  return kStride;
}

int FixWallVoxel::unpack_exchange(int nlocal, double* buf) {
  constexpr int kStride = kMaxContacts * kHistoryPerContact;
  std::copy_n(buf, kStride, &history_[static_cast<std::size_t>(nlocal) * kStride]);
  return kStride;
}
