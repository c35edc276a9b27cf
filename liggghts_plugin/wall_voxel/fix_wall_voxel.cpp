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
  model_kind_ = args.voxel_sum ? lbm_pore::WallModelKind::kVoxelSum : lbm_pore::WallModelKind::kSmooth;
  try {
    use_geometry(args.lbm_fix_id.empty() ? lbm_pore::acquire_wall_geometry(args.source)
                                         : geometry_of_lbm_fix(args.lbm_fix_id.c_str()));
  } catch (...) {  // lbm::InputError naming the file or keyword; std::bad_alloc as a last resort
    lbm_pore::report_current_exception(error, kCommand, lbm_pore::ErrorScope::kAllRanks);
  }

  vector_flag = 1;
  size_vector = 7;
  global_freq = 1;
  extvector = -1;  // contacts, forces and dropped springs extensive; the limit and ratio not
  extlist = new int[7]{1, 1, 1, 1, 0, 0, 1};
  restart_peratom = 1;

  grow_arrays(atom->nmax);
  atom->add_callback(0);  // grow/copy/exchange
  atom->add_callback(1);  // restart
  // Each migrating atom carries its springs (257 doubles for voxel_sum).
  comm->maxexchange_fix += model_->packed_size();
}

FixWallVoxel::~FixWallVoxel() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
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
  model_ = lbm_pore::make_wall_model(model_kind_, params_, std::move(geometry));
  model_->grow(atom->nmax);
}

void FixWallVoxel::init() {
  if (!atom->radius_flag || !atom->rmass_flag)
    error->all(FLERR, "fix wall/voxel needs per-atom radius and mass (atom_style granular or sphere)");
  check_time_step();
  guards_.start_run();
  springs_warned_ = false;
}

// Called at init and whenever the global atom count changes (insertion), by every rank.
void FixWallVoxel::check_time_step() {
  const std::optional<double> min_mass = guards_.lightest_mass(groupbit);
  if (!min_mass) return;  // no particles yet
  // The voxel sum's stiffness grows with the radius (k_a R per adhering voxel): take the
  // largest radius among the lightest particles.
  double radius = 0.0;
  if (model_kind_ == lbm_pore::WallModelKind::kVoxelSum) {
    double local_radius = 0.0;
    for (int i = 0; i < atom->nlocal; ++i)
      if ((atom->mask[i] & groupbit) && atom->rmass[i] == *min_mass)
        local_radius = std::max(local_radius, atom->radius[i]);
    MPI_Allreduce(&local_radius, &radius, 1, MPI_DOUBLE, MPI_MAX, world);
  }
  guards_.check_time_step(model_->time_step(*min_mass, radius));
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
  atom_force_x_.assign(std::size_t(nlocal), 0.0);
  stats_reduced_ = false;
  // Particles inserted during the run may be lighter than those checked at init; all ranks
  // take this branch together, one reduction per insertion.
  if (guards_.atom_count_changed()) check_time_step();
  double worst_overlap = 0.0;
  int worst_i = -1;
  int dropped = 0, dropped_i = -1;

  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    // A NaN centre would send the voxel search out of bounds; a NaN force (from the pair,
    // the fluid or a fix before this one) would make the position NaN at the next step.
    if (!std::isfinite(x[i][0] + x[i][1] + x[i][2] + f[i][0] + f[i][1] + f[i][2]))
      stop_on_non_finite(i, std::isfinite(x[i][0] + x[i][1] + x[i][2]) ? "force" : "position");
    lbm_pore::WallParticle particle;
    particle.centre = {x[i][0], x[i][1], x[i][2]};
    particle.velocity = {v[i][0], v[i][1], v[i][2]};
    particle.radius = radius[i];
    particle.mass = rmass[i];
    particle.dt = dt;
    const lbm_pore::WallForce wall = model_->apply(i, particle);
    if (!wall.touching) continue;
    if (wall.max_overlap_ratio > worst_overlap) {
      worst_overlap = wall.max_overlap_ratio;
      worst_i = i;
    }
    if (wall.springs_dropped > 0) {
      dropped += wall.springs_dropped;
      dropped_i = i;
    }
    const contact::Vec3& total = wall.force;
    f[i][0] += total.x;
    f[i][1] += total.y;
    f[i][2] += total.z;
    if (!std::isfinite(total.x + total.y + total.z)) stop_on_non_finite(i, "wall force");
    local_stats_[0] += wall.contacts;
    local_stats_[1] += total.x;
    atom_force_x_[std::size_t(i)] = total.x;
    local_stats_[2] += total.y;
    local_stats_[3] += total.z;
  }
  if (dropped > 0) report_dropped_springs(dropped_i, dropped);
  local_stats_[4] = worst_overlap;
  if (guards_.overlap_needs_report(worst_overlap)) {
    char subject[200];
    std::snprintf(subject, sizeof subject, "particle %d at (%g %g %g) overlaps the wall",
                  atom->tag[worst_i], x[worst_i][0], x[worst_i][1], x[worst_i][2]);
    guards_.report_overlap(worst_overlap, subject);
  }
}

// A contact beyond the model's spring capacity still acts but its friction restarts from
// zero every step: never silent (doc/wall_models.md).
void FixWallVoxel::report_dropped_springs(int i, int dropped) {
  local_springs_dropped_ += dropped;
  if (springs_warned_) return;
  springs_warned_ = true;
  char text[600];
  std::snprintf(text, sizeof text,
                "fix wall/voxel: %d wall contact(s) on this rank found no room for their "
                "tangential spring at step " BIGINT_FORMAT " (model %s keeps %d per particle; "
                "particle %d at (%g %g %g) among them): their friction restarts from zero each "
                "step. f_%s[7] counts them; coarser voxels or a stiffer kw (smaller overlaps) "
                "need fewer (warning once per run)",
                dropped, update->ntimestep, lbm_pore::wall_model_name(model_kind_),
                model_->spring_capacity(), atom->tag[i], atom->x[i][0], atom->x[i][1],
                atom->x[i][2], id);
  if (screen)
    error->warning(FLERR, text);
  else
    std::fprintf(stderr, "WARNING on proc %d: %s\n", comm->me, text);
}

// "local_force": this rank's total wall force along x (one value); "atom_wall_force_x": the
// same per local atom, in the atom order of the last post_force.
void* FixWallVoxel::extract(const char* name, int& dim) {
  dim = 1;
  if (std::strcmp(name, "local_force") == 0) return &local_stats_[1];
  if (std::strcmp(name, "atom_wall_force_x") == 0) return atom_force_x_.data();
  dim = 0;
  return nullptr;
}

double FixWallVoxel::compute_vector(int index) {
  if (index == 4) return guards_.time_step_limit();
  if (!stats_reduced_) {
    MPI_Allreduce(local_stats_, global_stats_, 4, MPI_DOUBLE, MPI_SUM, world);
    MPI_Allreduce(&local_stats_[4], &global_stats_[4], 1, MPI_DOUBLE, MPI_MAX, world);
    MPI_Allreduce(&local_springs_dropped_, &global_springs_dropped_, 1, MPI_DOUBLE, MPI_SUM,
                  world);
    stats_reduced_ = true;
  }
  if (index == 6) return global_springs_dropped_;
  return index == 5 ? global_stats_[4] : global_stats_[index];
}
