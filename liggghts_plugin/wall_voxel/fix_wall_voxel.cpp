#include "fix_wall_voxel.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <string>

#include "atom.h"
#include "comm.h"
#include "contact/dash_dot.h"
#include "error.h"
#include "modify.h"
#include "lbm/input_error.h"
#include "plugin_common/stop_run.h"
#include "lbm_pore/fix_lbm_pore.h"
#include "plugin_common/parse_number.h"
#include "update.h"
#include "wall_geometry_source.h"

using namespace LAMMPS_NS;
using lbm_pore::parse_integer;
using lbm_pore::parse_number;

namespace {
constexpr const char* kCommand = "fix wall/voxel";
constexpr double kMinStepsPerContact = 10.0;  // dt <= t_c / 10 (REFERENCES.md)
constexpr double kBig = 1e300;
// Contacts of consecutive steps are the same contact when their normals are this close
// (cos 25 deg): a sphere rolling over an edge turns its normal slowly.
constexpr double kSameContactCosine = 0.9;
}  // namespace

FixWallVoxel::FixWallVoxel(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
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
  // Defaults tied to the wall stiffness unless given (LIGGGHTS hooke's k_t = 2/7 k_n).
  if (!kt_given_) params_.friction.k_t = 2.0 / 7.0 * params_.normal.k_n;
  if (!tangential_damping_given_) params_.friction.damping_ratio = params_.normal.damping_ratio;

  try {
    use_geometry(shared ? shared : lbm_pore::acquire_wall_geometry(source));
  } catch (const lbm::InputError& e) {
    error->all(FLERR, (std::string(kCommand) + ": " + e.what()).c_str());
  }

  vector_flag = 1;
  size_vector = 6;
  global_freq = 1;
  extvector = -1;  // contacts and forces extensive; the time step limit and overlap ratio not
  extlist = new int[6]{1, 1, 1, 1, 0, 0};

  grow_arrays(atom->nmax);
  atom->add_callback(0);
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
                       "' (expected file, pore, inlet_length, free_length, pore_length, "
                       "outlet_length, width, pore_diameter, spacing, origin, kw, ka, damping, "
                       "mu, kt or tangential_damping)")
                          .c_str());
  }
  iarg += 2;
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
  overlap_warned_ = false;  // the overlap warning comes once per run
}

// Called at init and whenever the global atom count changes (insertion), by every rank.
void FixWallVoxel::check_time_step() {
  checked_natoms_ = atom->natoms;
  double local_min_mass = kBig;
  for (int i = 0; i < atom->nlocal; ++i)
    if (atom->mask[i] & groupbit) local_min_mass = std::min(local_min_mass, atom->rmass[i]);
  double min_mass = 0.0;
  MPI_Allreduce(&local_min_mass, &min_mass, 1, MPI_DOUBLE, MPI_MIN, world);
  if (min_mass >= kBig) return;  // no particles yet
  // The stiffer of the normal and tangential springs sets the shortest oscillation.
  contact::DashDotParams stiffest = params_.normal;
  stiffest.k_n = std::max(params_.normal.k_n, params_.friction.k_t);
  const double tc = contact::contact_duration(stiffest, min_mass);
  const double dt_max = tc / kMinStepsPerContact;
  const bool was_unset = dt_limit_ == 0.0;
  const bool dropped = dt_max < dt_limit_ * (1.0 - 1e-9);
  dt_limit_ = dt_max;
  if (update->dt > dt_max) {
    // With a fluid, the fluid step n_dem * dt sets tau: keep it, take more DEM steps per fluid step.
    const int factor = static_cast<int>(std::ceil(update->dt / dt_max));
    char fluid_advice[200] = "";
    if (modify->find_fix_style("lbm/pore", 0))
      std::snprintf(fluid_advice, sizeof fluid_advice,
                    "; with fix lbm/pore, multiply n_dem by %d and divide the timestep by %d "
                    "(the fluid step stays the same)",
                    factor, factor);
    const bool kt_sets = params_.friction.k_t > params_.normal.k_n;
    char message[700];
    std::snprintf(message, sizeof message,
                  "fix wall/voxel: timestep %g is too large for %s = %g at step " BIGINT_FORMAT
                  ": the wall contact time of the lightest particle (mass %g) is t_c = %g, and "
                  "a contact needs at least %g steps (timestep <= t_c/%g); use timestep <= %g or a "
                  "smaller %s%s",
                  update->dt, kt_sets ? "kt" : "kw", stiffest.k_n, update->ntimestep, min_mass, tc,
                  kMinStepsPerContact, kMinStepsPerContact, dt_max, kt_sets ? "kt" : "kw",
                  fluid_advice);
    error->all(FLERR, message);
  }
  if (comm->me == 0 && (was_unset || dropped)) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "fix wall/voxel: wall contact time t_c = %g of the lightest particle (mass %g, "
                  "%s = %g); timestep limit t_c/%g = %g (timestep %g)\n",
                  tc, min_mass, params_.friction.k_t > params_.normal.k_n ? "kt" : "kw",
                  stiffest.k_n, kMinStepsPerContact, dt_max, update->dt);
    if (screen) std::fputs(text, screen);
    if (logfile) std::fputs(text, logfile);
  }
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

// Overlap guard: beyond a few percent of R kw is too soft for the forces of the scene; at
// half the radius the particle is passing through the wall.
void FixWallVoxel::check_overlap(double ratio, int i) {
  const int tag = atom->tag[i];
  double** x = atom->x;
  char text[600];
  if (ratio > kStopOverlap) {
    std::snprintf(text, sizeof text,
                  "fix wall/voxel: particle %d at (%g %g %g) overlaps the wall by %.0f %% of its "
                  "radius at step " BIGINT_FORMAT " (limit %.0f %%): it passes through the wall. kw "
                  "is far too soft for the forces in this scene, or the timestep too large: raise "
                  "kw (the timestep limit t_c/10 shrinks with it), lower the drive",
                  tag, x[i][0], x[i][1], x[i][2], 100.0 * ratio, update->ntimestep,
                  100.0 * kStopOverlap);
    lbm_pore::stop_on_this_rank(error, comm->me, screen, logfile, text);
  }
  if (overlap_warned_) return;
  overlap_warned_ = true;
  std::snprintf(text, sizeof text,
                "fix wall/voxel: particle %d at (%g %g %g) overlaps the wall by %.1f %% of its "
                "radius at step " BIGINT_FORMAT " (warning above %.0f %%, once per run): kw is too "
                "soft for the forces in this scene; raise kw (the timestep limit t_c/10 shrinks "
                "with it)",
                tag, x[i][0], x[i][1], x[i][2], 100.0 * ratio, update->ntimestep,
                100.0 * kWarnOverlap);
  if (screen) error->warning(FLERR, text);
  else std::fprintf(stderr, "WARNING on proc %d: %s\n", comm->me, text);
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
  // Particles inserted during the run may be lighter than those checked at init; natoms is
  // the same on every rank, so all take this branch together (one reduction per insertion).
  if (atom->natoms != checked_natoms_) check_time_step();
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
  if (worst_overlap > kWarnOverlap) check_overlap(worst_overlap, worst_i);
}

double FixWallVoxel::compute_vector(int index) {
  if (index == 4) return dt_limit_;
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
