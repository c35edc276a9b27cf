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
#include "modify.h"
#include "lbm/input_error.h"
#include "plugin_common/stop_run.h"
#include "lbm_pore/fix_lbm_pore.h"
#include "plugin_common/parse_number.h"
#include "update.h"
#include "wall_geometry_source.h"

using namespace LAMMPS_NS;
using lbm_pore::parse_choice;
using lbm_pore::parse_integer;
using lbm_pore::parse_number;

namespace {
constexpr const char* kCommand = "fix wall/voxel";
constexpr double kBig = 1e300;

// The words of this style's guard messages, in the order of lbm_pore::GuardWording.
const lbm_pore::GuardWording kGuardWording{kCommand, "wall contact time", "the lightest particle",
                                           "its radius", "it passes through the wall", "kw"};
}  // namespace

FixWallVoxel::FixWallVoxel(LAMMPS* lmp, int narg, char** arg)
    : Fix(lmp, narg, arg), guards_(lmp, kGuardWording) {
  lbm_pore::WallGeometrySource source;
  std::shared_ptr<const lbm::VoxelGeometry> shared;  // from 'lbm <fix-ID>'
  int iarg = 3;
  while (iarg < narg) {
    const std::string key = arg[iarg];
    auto need = [&](int count) {
      if (iarg + count >= narg)
        error->all(FLERR, (std::string(kCommand) + ": keyword '" + key + "' needs " +
                           std::to_string(count) + " value(s)")
                              .c_str());
    };
    if (key == "lbm") {
      need(1);
      shared = geometry_of_lbm_fix(arg[iarg + 1]);
      iarg += 2;
    } else if (key == "file") {
      need(1);
      source.kind = lbm_pore::WallGeometrySource::Kind::kFile;
      source.path = arg[iarg + 1];
      iarg += 2;
    } else if (key == "pore") {
      source.kind = lbm_pore::WallGeometrySource::Kind::kPoreScene;
      iarg += 1;
    } else if (key == "model") {
      need(1);
      model_kind_ = parse_choice(error, kCommand, "model", arg[iarg + 1], {"smooth", "voxel_sum"}) == 1
                        ? lbm_pore::WallModelKind::kVoxelSum
                        : lbm_pore::WallModelKind::kSmooth;
      iarg += 2;
    } else if (key == "inlet_length" || key == "free_length" || key == "pore_length" ||
               key == "outlet_length" || key == "width") {
      need(1);
      const int value = parse_integer(error, kCommand, key.c_str(), arg[iarg + 1], 1, 1 << 20);
      if (key == "inlet_length") source.pore.inlet_length = value;
      if (key == "free_length") source.pore.free_length = value;
      if (key == "pore_length") source.pore.pore_length = value;
      if (key == "outlet_length") source.pore.outlet_length = value;
      if (key == "width") source.pore.width = value;
      iarg += 2;
    } else if (key == "pore_diameter") {
      need(1);
      source.pore.pore_diameter = parse_number(error, kCommand, "pore_diameter", arg[iarg + 1], 0.0, false, kBig);
      iarg += 2;
    } else if (key == "spacing") {
      need(1);
      source.spacing = parse_number(error, kCommand, "spacing", arg[iarg + 1], 0.0, false, kBig);
      iarg += 2;
    } else if (key == "origin") {
      need(3);
      for (int a = 0; a < 3; ++a)
        source.origin[a] = parse_number(error, kCommand, "origin", arg[iarg + 1 + a], -kBig, true, kBig);
      iarg += 4;
    } else {
      parse_contact_keyword(iarg, narg, arg);
    }
  }
  if (shared && source.kind != lbm_pore::WallGeometrySource::Kind::kNone)
    error->all(FLERR, "fix wall/voxel: give one geometry: 'lbm <fix-ID>', 'file <path>' or 'pore'");
  if (!shared && source.kind == lbm_pore::WallGeometrySource::Kind::kNone)
    error->all(FLERR, "fix wall/voxel: no geometry: give keyword 'lbm <fix-ID>' (the geometry of "
                      "fix lbm/pore), 'file <path>' or 'pore'");
  // Defaults tied to the wall stiffness and damping unless given.
  if (!kt_given_) params_.friction.k_t = contact::default_tangential_stiffness(params_.normal.k_n);
  if (!tangential_damping_given_) params_.friction.damping_ratio = params_.normal.damping_ratio;

  try {
    use_geometry(shared ? shared : lbm_pore::acquire_wall_geometry(source));
  } catch (const lbm::InputError& e) {
    error->all(FLERR, (std::string(kCommand) + ": " + e.what()).c_str());
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

void FixWallVoxel::parse_contact_keyword(int& iarg, int narg, char** arg) {
  const std::string key = arg[iarg];
  if (iarg + 1 >= narg)
    error->all(FLERR, (std::string(kCommand) + ": keyword '" + key + "' needs a value").c_str());
  const char* value = arg[iarg + 1];
  if (key == "kw") {
    params_.normal.k_n = parse_number(error, kCommand, "kw", value, 0.0, false, kBig);
  } else if (key == "ka") {
    params_.adhesion.k_a = parse_number(error, kCommand, "ka", value, 0.0, true, kBig);
  } else if (key == "damping") {
    params_.normal.damping_ratio = parse_number(error, kCommand, "damping", value, 0.0, true, 1.0);
  } else if (key == "mu") {
    params_.friction.mu = parse_number(error, kCommand, "mu", value, 0.0, true, kBig);
  } else if (key == "kt") {
    params_.friction.k_t = parse_number(error, kCommand, "kt", value, 0.0, false, kBig);
    kt_given_ = true;
  } else if (key == "tangential_damping") {
    params_.friction.damping_ratio =
        parse_number(error, kCommand, "tangential_damping", value, 0.0, true, 1.0);
    tangential_damping_given_ = true;
  } else {
    error->all(FLERR, (std::string(kCommand) + ": unknown keyword '" + key +
                       "' (expected lbm, file, pore, inlet_length, free_length, pore_length, "
                       "outlet_length, width, pore_diameter, spacing, origin, model, kw, ka, "
                       "damping, mu, kt or tangential_damping)")
                          .c_str());
  }
  iarg += 2;
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
