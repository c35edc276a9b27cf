#include "fix_lbm_pore.h"

#include "fix_lbm_pore_internal.h"

#include <mpi.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <limits>

#include "atom.h"
#include "comm.h"
#include "contact/short_range_attraction.h"
#include "contact/voxel_surface.h"
#include "coupling/lattice_frame.h"
#include "coupling/lubrication/lubrication.h"
#include "coupling/periodic_box.h"
#include "coupling/sphere_coupling.h"
#include "coupling/unit_conversion.h"
#include "domain.h"
#include "error.h"
#include "fix_gravity.h"
#include "force.h"
#include "lbm/checkpoint.h"
#include "lbm/collide_stream.h"
#include "lbm/decomposition.h"
#include "lbm/fluid_solver.h"
#include "lbm/input_error.h"
#include "plugin_common/stop_run.h"
#include "lbm/macroscopic.h"
#include "lbm/node_type.h"
#include "lbm/pore_scene.h"
#include "lbm/stability.h"
#include "lbm/voxel_file.h"
#include "lbm/vtk_output.h"
#include "memory.h"
#include "modify.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;
using namespace lbm_pore::slots;
using namespace lbm_pore::limits;

namespace {
int cells(double length, double dx) { return static_cast<int>(std::lround(length / dx)); }
}  // namespace

FixLbmPore::FixLbmPore(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  std::vector<std::string> words(arg + 3, arg + narg);
  try {
    options_ = lbm_pore::parse_pore_options(words);
    build_geometry();
  } catch (const lbm::InputError& e) {
    const std::string what = e.what();  // the parser's messages already name the command
    error->all(FLERR, (what.rfind("fix lbm/pore", 0) == 0 ? what : "fix lbm/pore: " + what).c_str());
  }
  if (!atom->radius_flag)
    error->all(FLERR, "fix lbm/pore needs per-atom radii: use atom_style granular (or sphere)");
  vector_flag = 1;
  size_vector = kNumDiagnostics;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  restart_peratom = 1;
  nevery = 1;
  comm_forward = 6;  // velocity, angular velocity
  comm_reverse = kSummedPerAtom;
  diagnostics_.assign(kNumDiagnostics, 0.0);
  grow_arrays(atom->nmax);
  atom->add_callback(0);  // grow/copy/exchange
  atom->add_callback(1);  // restart
  for (int i = 0; i < atom->nmax; ++i)
    for (int k = 0; k < kLoadsPerAtom; ++k) loads_[i][k] = 0.0;
}

FixLbmPore::~FixLbmPore() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(loads_);
}

int FixLbmPore::setmask() { return FixConst::POST_FORCE | FixConst::END_OF_STEP; }

void FixLbmPore::init() {
  coupling::UnitInputs in;
  in.dx = options_.dx;
  in.rho = options_.rho;
  in.nu = options_.nu;
  in.dt_dem = update->dt;
  in.n_dem = options_.n_dem;
  try {
    auto units = std::make_unique<coupling::UnitConversion>(in);
    if (solver_ && std::abs(units->tau() - units_->tau()) > 1e-12)
      throw lbm::InputError("the DEM time step or n_dem changed between runs (tau " +
                            std::to_string(units_->tau()) + " -> " + std::to_string(units->tau()) +
                            "); the fluid's relaxation time is fixed once the lattice exists");
    units_ = std::move(units);
    if (!solver_) build_lattice();
  } catch (const lbm::InputError& e) {
    error->all(FLERR, (std::string("fix lbm/pore: ") + e.what()).c_str());
  }
  if (!resume_checkpoint_.empty()) {
    try {
      lbm::read_checkpoint(*solver_, resume_checkpoint_);
      fluid_steps_ = solver_->time_step();
      resumed_ = true;
    } catch (const lbm::InputError& e) {
      error->all(FLERR, (std::string("fix lbm/pore: restart: ") + e.what()).c_str());
    }
    resume_checkpoint_.clear();
  }
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "fix lbm/pore needs ghost velocities: add 'communicate single vel yes'");
  if (force->newton_pair)
    error->all(FLERR, "fix lbm/pore needs 'newton off' (granular pair styles in LIGGGHTS)");
  // The lubrication and bond search need every pair whose gap is below the lubrication
  // cutoff: the neighbor list holds pairs closer than the contact distance plus the skin.
  const double lubrication_reach = options_.lubrication_cutoff * options_.dx;
  if (options_.lubrication && neighbor->skin < lubrication_reach) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "fix lbm/pore: the neighbor skin %g is smaller than the lubrication cutoff "
                  "lubrication_cutoff * dx = %g: raise it ('neighbor %g bin') or lower "
                  "lubrication_cutoff",
                  neighbor->skin, lubrication_reach, lubrication_reach);
    error->all(FLERR, text);
  }
  const int request = neighbor->request(this);
  neighbor->requests[request]->pair = 0;
  neighbor->requests[request]->fix = 1;
  neighbor->requests[request]->half = 0;
  neighbor->requests[request]->gran = 1;
  print_setup();
}

void FixLbmPore::init_list(int, NeighList* list) { list_ = list; }

// Buoyancy: the fluid carries no body force (it is driven through its boundaries), so its
// pressure holds no hydrostatic part and the particles feel no Archimedes force from it.
// With fix gravity on, each particle gets -rho_f V g in addition, which makes the net
// weight (rho_p - rho_f) V g.
void FixLbmPore::find_gravity() {
  has_gravity_ = false;
  for (int a = 0; a < 3; ++a) gravity_[a] = 0.0;
  for (int i = 0; i < modify->nfix; ++i) {
    if (std::strcmp(modify->fix[i]->style, "gravity") != 0) continue;
    auto* gravity = static_cast<FixGravity*>(modify->fix[i]);
    double g[3];
    gravity->get_gravity(g);
    for (int a = 0; a < 3; ++a) gravity_[a] += g[a];
    has_gravity_ = true;
  }
  if (has_gravity_ && comm->me == 0) {
    char text[300];
    std::snprintf(text, sizeof text,
                  "fix lbm/pore: fix gravity found: buoyancy -rho V g added to each particle, "
                  "g = (%g, %g, %g)\n",
                  gravity_[0], gravity_[1], gravity_[2]);
    if (screen) std::fputs(text, screen);
    if (logfile) std::fputs(text, logfile);
  }
}

void FixLbmPore::build_geometry() {
  const double dx = options_.dx;
  std::array<double, 3> origin;
  for (int a = 0; a < 3; ++a)
    origin[a] = options_.origin_given ? options_.origin[a] : domain->boxlo[a] + 0.5 * dx;
  if (options_.scene == lbm_pore::PoreOptions::Scene::kPore) {
    lbm::PoreSceneSpec spec;
    spec.inlet_length = cells(options_.inlet_length, dx);
    spec.free_length = cells(options_.free_length, dx);
    spec.pore_length = cells(options_.pore_length, dx);
    spec.outlet_length = cells(options_.outlet_length, dx);
    spec.width = cells(options_.width, dx);
    spec.pore_diameter = options_.pore_diameter / dx;
    pore_diameter_lattice_ = spec.pore_diameter;
    geometry_ = std::make_shared<lbm::VoxelGeometry>(lbm::make_pore_scene(spec, dx, origin));
    const auto r = lbm::regions_of(spec);
    pore_.axis = 0;
    // "Located inside the pore radius" (paper Sec. III): the pore's cylinder, extended
    // upstream through the free region so a clog sitting in the pore's mouth counts too.
    pore_.start = r.inlet_end - 0.5;
    pore_.end = r.pore_end - 0.5;
    pore_.centre = {r.axis_y, r.axis_z};
    pore_.diameter = spec.pore_diameter;
    inlet_x_ = r.inlet_end - 0.5;
    outlet_x_ = r.outlet_begin - 0.5;
  } else {
    const auto file = lbm::load_voxel_file(options_.voxel_file);
    if (std::abs(file.spacing() - dx) > 1e-9 * dx)
      throw lbm::InputError("scene voxels: the file's spacing " + std::to_string(file.spacing()) +
                            " differs from dx " + std::to_string(dx));
    // The lattice sits where the box (or 'origin') says; the file's own origin is ignored.
    auto placed = std::make_shared<lbm::VoxelGeometry>(file.dims(), dx, origin);
    const auto& d = file.dims();
    // The pore of an arbitrary geometry: its narrowest open cross-section, as the
    // equivalent circle sqrt(4 A / pi); deposits count anywhere in the lattice.
    double narrowest = 1e300;
    for (int i = 0; i < d[0]; ++i) {
      int open = 0;
      for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j) {
          const bool solid = file.is_solid(i, j, k);
          placed->set_solid(i, j, k, solid);
          open += !solid;
        }
      narrowest = std::min(narrowest, double(open));
    }
    geometry_ = placed;
    pore_diameter_lattice_ = std::sqrt(4.0 * narrowest / M_PI);
    pore_.axis = 0;
    pore_.start = -0.5;
    pore_.end = d[0] - 0.5;
    pore_.centre = {0.5 * (d[1] - 1), 0.5 * (d[2] - 1)};
    pore_.diameter = 1e30;
    inlet_x_ = 0.5;
    outlet_x_ = d[0] - 1.5;
  }
  surface_ = std::make_unique<contact::VoxelSurface>(*geometry_);
}

// Builds the lattice frame and the fluid solver on LIGGGHTS's own subdomains (each rank
// owns the nodes inside its subdomain).
void FixLbmPore::build_lattice() {
  const double dx = options_.dx;
  frame_ = std::make_unique<coupling::LatticeFrame>();
  frame_->dx = dx;
  frame_->dims = geometry_->dims();
  frame_->origin = geometry_->origin();
  // The lattice must fill the simulation box: every node's cell inside it.
  for (int a = 0; a < 3; ++a) {
    const double lattice_lo = frame_->origin[a] - 0.5 * dx;
    const double lattice_hi = lattice_lo + frame_->dims[a] * dx;
    if (std::abs(lattice_lo - domain->boxlo[a]) > 0.5 * dx ||
        std::abs(lattice_hi - domain->boxhi[a]) > 0.5 * dx) {
      char text[400];
      std::snprintf(text, sizeof text,
                    "scene: the lattice spans [%g, %g] on axis %c but the simulation box is "
                    "[%g, %g]; make the box match the scene (dims %d x %d x %d cells of dx = %g) "
                    "or set 'origin'",
                    lattice_lo, lattice_hi, "xyz"[a], domain->boxlo[a], domain->boxhi[a],
                    frame_->dims[0], frame_->dims[1], frame_->dims[2], dx);
      throw lbm::InputError(text);
    }
  }
  for (int a = 1; a < 3; ++a)
    if (options_.lateral_periodic != (domain->periodicity[a] != 0))
      throw lbm::InputError(std::string("lateral: the fluid is ") +
                            (options_.lateral_periodic ? "periodic" : "walled") + " along " +
                            "xyz"[a] + " but the LIGGGHTS boundary there is " +
                            (domain->periodicity[a] ? "periodic" : "not periodic") +
                            "; use 'boundary f p p' with 'lateral periodic' or 'boundary f f f' "
                            "with 'lateral wall'");
  if (domain->periodicity[0])
    throw lbm::InputError("the flow axis x must not be periodic: use 'boundary f ...' (the "
                          "fluid enters at x-lo and leaves at x-hi)");

  lbm::FluidParameters p;
  p.tau = units_->tau();
  p.magic = options_.magic;
  p.periodic = {false, options_.lateral_periodic, options_.lateral_periodic};
  lbm::FlowDrive drive;
  drive.axis = 0;
  if (options_.drive == lbm_pore::PoreOptions::Drive::kVelocity) {
    drive.kind = lbm::FlowDrive::kInletVelocity;
    drive.inlet_velocity = units_->velocity_to_lattice(options_.drive_value);
    if (std::abs(drive.inlet_velocity) > kMaxLatticeSpeed) {
      char text[400];
      std::snprintf(text, sizeof text,
                    "velocity: %g is %.3g in lattice units, above the stable limit %.2f "
                    "(lattice Mach %.2f); lower 'velocity', lower n_dem or the DEM time step, "
                    "or refine dx",
                    options_.drive_value, drive.inlet_velocity, kMaxLatticeSpeed,
                    drive.inlet_velocity / kSoundSpeed);
      throw lbm::InputError(text);
    }
  } else {
    drive.kind = lbm::FlowDrive::kPressureLoss;
    drive.pressure_loss = units_->pressure_to_lattice(options_.drive_value);
    // A density difference of 10 % is far outside the weakly compressible regime.
    if (std::abs(drive.pressure_loss) > 0.1 / 3.0) {
      char text[400];
      std::snprintf(text, sizeof text,
                    "pressure_loss: %g is a lattice density difference of %.3g, above the "
                    "weakly compressible limit 0.1; lower 'pressure_loss' or n_dem, or refine dx",
                    options_.drive_value, 3.0 * drive.pressure_loss);
      throw lbm::InputError(text);
    }
  }

  lbm::Decomposition d;
  d.global.hi = frame_->dims;
  d.periodic = p.periodic;
  d.comm = lbm::Communicator(world);
  bool at_lower[3], at_upper[3];
  for (int a = 0; a < 3; ++a) {
    at_lower[a] = comm->myloc[a] == 0;
    at_upper[a] = comm->myloc[a] == comm->procgrid[a] - 1;
    for (int side = 0; side < 2; ++side) {
      const bool edge = side == 0 ? at_lower[a] : at_upper[a];
      d.neighbor[a][side] = (edge && !d.periodic[a]) ? -1 : comm->procneigh[a][side];
    }
  }
  d.owned = frame_->owned_box(domain->sublo, domain->subhi, at_lower, at_upper);
  for (int a = 0; a < 3; ++a)
    if (d.owned.size(a) < 1)
      throw lbm::InputError("the subdomain of rank " + std::to_string(comm->me) +
                            " holds no lattice node on axis " + std::string(1, "xyz"[a]) +
                            ": use fewer ranks along that axis (processors command)");
  solver_ = std::make_unique<lbm::FluidSolver>(*geometry_, p, drive, d);

  coupling::SphereCouplingOptions co;
  co.wall_scheme = lbm::moving_wall::parse(options_.boundary);
  coupling_ = std::make_unique<coupling::SphereCoupling>(*solver_, co);
  coupling::LubricationParameters lp;
  lp.rho = 1.0;
  lp.nu = units_->nu_lattice();
  lp.cutoff = options_.lubrication_cutoff;
  lubrication_ = std::make_unique<coupling::LubricationCorrection>(lp);
  inlet_counter_ = std::make_unique<coupling::PlaneCrossingCounter>(0, inlet_x_);
  outlet_counter_ = std::make_unique<coupling::PlaneCrossingCounter>(0, outlet_x_);

  if (options_.vtk_every > 0)
    vtk_ = std::make_unique<lbm::VtkSeriesWriter>(options_.vtk_directory, "fluid");
}

void FixLbmPore::print_setup() const {
  if (comm->me != 0) return;
  const auto& dims = frame_->dims;
  const auto& drive = solver_->drive();
  char text[1500];
  int n = std::snprintf(
      text, sizeof text,
      "fix lbm/pore: lattice %d x %d x %d nodes (dx = %g), %s\n"
      "fix lbm/pore: DEM step %g, fluid step %g = %d DEM steps; pore diameter %.2f cells\n",
      dims[0], dims[1], dims[2], options_.dx, units_->summary().c_str(), update->dt,
      units_->dt_lbm(), options_.n_dem, pore_diameter_lattice_);
  if (drive.kind == lbm::FlowDrive::kInletVelocity)
    n += std::snprintf(text + n, sizeof text - n,
                       "fix lbm/pore: inlet velocity %g = %.4g lattice, lattice Mach %.3g\n",
                       options_.drive_value, drive.inlet_velocity,
                       std::abs(drive.inlet_velocity) / kSoundSpeed);
  else
    n += std::snprintf(text + n, sizeof text - n,
                       "fix lbm/pore: pressure loss %g = %.4g lattice (density difference %.3g)\n",
                       options_.drive_value, drive.pressure_loss, 3.0 * drive.pressure_loss);
  n += std::snprintf(text + n, sizeof text - n,
                     "fix lbm/pore: moving walls %s, lubrication %s (cutoff %g cells)\n",
                     options_.boundary.c_str(), options_.lubrication ? "on" : "off",
                     options_.lubrication_cutoff);
  if (screen) std::fputs(text, screen);
  if (logfile) std::fputs(text, logfile);
}

void FixLbmPore::setup(int vflag) {
  // After every fix's init(): fix gravity sets its acceleration there.
  find_gravity();
  run_start_ = now();
  run_fluid_steps_ = 0;
  time_fluid_ = time_lubrication_ = time_diagnostics_ = 0.0;
  if (resumed_) resume_mapping();
  gather_particles(false);
  find_walls();
  update_particle_diagnostics();
  update_diagnostics();
  if (vtk_ && fluid_steps_ == 0) vtk_->write(*solver_, 0.0);
  post_force(vflag);
}

// The hydrodynamic load of the last fluid step acts unchanged on every DEM substep (paper,
// "Coupling of Fluid and Particles"); the lubrication correction and buoyancy follow the
// particles every substep.
void FixLbmPore::post_force(int) {
  double** f = atom->f;
  double** v = atom->v;
  double** torque = atom->torque;
  const int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double* radius = atom->radius;
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    own_slot(i);
    // F - C (v - v_step): the fluid resists a velocity change within the substeps at once.
    const double C = loads_[i][kCoefficient];
    for (int a = 0; a < 3; ++a) f[i][a] += loads_[i][a] - C * (v[i][a] - loads_[i][kStepVelocity + a]);
    if (torque)
      for (int a = 0; a < 3; ++a) torque[i][a] += loads_[i][3 + a];
    if (has_gravity_) {
      const double volume = 4.0 / 3.0 * M_PI * radius[i] * radius[i] * radius[i];
      for (int a = 0; a < 3; ++a) f[i][a] -= options_.rho * volume * gravity_[a];
    }
  }
  if (options_.lubrication && list_) {
    const double start = now();
    add_lubrication(f);
    time_lubrication_ += now() - start;
  }
}

// Pair and wall lubrication on the owned atoms, from the fix's granular half neighbor list
// (newton off: an owned-ghost pair is listed on both ranks and each side adds its own half).
void FixLbmPore::add_lubrication(double** f) {
  double** x = atom->x;
  double** v = atom->v;
  const double* radius = atom->radius;
  const int* mask = atom->mask;
  const int nlocal = atom->nlocal;
  const double dx = options_.dx;
  const double to_lattice_velocity = units_->dt_lbm() / dx;
  const double force_unit = units_->force_unit();
  const double cutoff = options_.lubrication_cutoff * dx;
  for (int ii = 0; ii < list_->inum; ++ii) {
    const int i = list_->ilist[ii];
    if (!(mask[i] & groupbit)) continue;
    const int* neighbors = list_->firstneigh[i];
    for (int jj = 0; jj < list_->numneigh[i]; ++jj) {
      const int j = neighbors[jj] & NEIGHMASK;
      if (!(mask[j] & groupbit)) continue;
      const coupling::Vec3 d{(x[j][0] - x[i][0]) / dx, (x[j][1] - x[i][1]) / dx,
                             (x[j][2] - x[i][2]) / dx};
      const double gap = std::sqrt(coupling::dot(d, d)) * dx - radius[i] - radius[j];
      if (gap >= cutoff) continue;
      const coupling::Vec3 vi{v[i][0] * to_lattice_velocity, v[i][1] * to_lattice_velocity,
                              v[i][2] * to_lattice_velocity};
      const coupling::Vec3 vj{v[j][0] * to_lattice_velocity, v[j][1] * to_lattice_velocity,
                              v[j][2] * to_lattice_velocity};
      const auto F = lubrication_->pair_force(radius[i] / dx, radius[j] / dx, d, vi, vj);
      for (int a = 0; a < 3; ++a) f[i][a] += F[a] * force_unit;
      if (j < nlocal)
        for (int a = 0; a < 3; ++a) f[j][a] -= F[a] * force_unit;
    }
  }
  // The nearest wall was found at the last fluid step; within a fluid step a particle moves
  // less than half a cell, so the distance follows from its displacement along that normal.
  for (int i = 0; i < nlocal; ++i) {
    if (!(mask[i] & groupbit)) continue;
    const double* load = loads_[i];
    if (load[kWallKnown] <= 0.0) continue;
    double distance = load[kWallDistance];
    for (int a = 0; a < 3; ++a) distance += load[kWallNormal + a] * (x[i][a] - load[kPreviousPosition + a]);
    if (distance - radius[i] >= cutoff) continue;
    coupling::WallDistance wall;
    wall.distance = std::max(distance, 0.0) / dx;
    wall.normal = {load[kWallNormal], load[kWallNormal + 1], load[kWallNormal + 2]};
    const coupling::Vec3 vi{v[i][0] * to_lattice_velocity, v[i][1] * to_lattice_velocity,
                            v[i][2] * to_lattice_velocity};
    const auto F = lubrication_->wall_force(radius[i] / dx, vi, wall);
    for (int a = 0; a < 3; ++a) f[i][a] += F[a] * force_unit;
  }
}

// The nearest wall of every owned particle, within the lubrication reach plus the farthest a
// particle may move in a fluid step; used by add_lubrication until the next fluid step.
void FixLbmPore::find_walls() {
  if (!options_.lubrication) return;
  double** x = atom->x;
  const double* radius = atom->radius;
  const double reach = (options_.lubrication_cutoff + kMaxShiftPerFluidStep) * options_.dx;
  for (int i = 0; i < atom->nlocal; ++i) {
    if (!(atom->mask[i] & groupbit)) continue;
    double* load = loads_[i];
    surface_->find({x[i][0], x[i][1], x[i][2]}, radius[i] + reach, wall_points_);
    load[kWallKnown] = wall_points_.empty() ? 0.0 : 1.0;
    if (wall_points_.empty()) continue;
    const auto nearest = std::min_element(wall_points_.begin(), wall_points_.end(),
                                           [](const auto& a, const auto& b) { return a.distance < b.distance; });
    load[kWallDistance] = nearest->distance;
    for (int a = 0; a < 3; ++a) load[kWallNormal + a] = nearest->normal[a];
  }
}

void FixLbmPore::end_of_step() {
  if (update->ntimestep % options_.n_dem != 0) return;
  fluid_step();
}

// Lattice-unit copies of the group's owned atoms and ghosts. The fluid sees each sphere move
// with its mean velocity over the last fluid step, (x - x_previous) / dt_lbm, the velocity
// that matches how far the mapping moved it: the instantaneous velocity of a particle in a
// stiff contact oscillates within the substeps, and sampling it once per fluid step feeds
// that noise into the fluid. `advance` is false at setup, where no step has passed.
void FixLbmPore::gather_particles(bool advance) {
  double** x = atom->x;
  double** v = atom->v;
  const double dt_lbm = units_->dt_lbm();
  for (int i = 0; i < atom->nlocal; ++i) {
    own_slot(i);
    double* load = loads_[i];
    if (advance && load[kHasPrevious] > 0.0) {
      double d[3] = {x[i][0] - load[kPreviousPosition], x[i][1] - load[kPreviousPosition + 1],
                     x[i][2] - load[kPreviousPosition + 2]};
      domain->minimum_image(d);  // an atom wrapped through a periodic face
      for (int a = 0; a < 3; ++a) load[kWallVelocity + a] = d[a] / dt_lbm;
    } else {
      for (int a = 0; a < 3; ++a) load[kWallVelocity + a] = v[i][a];
    }
    for (int a = 0; a < 3; ++a) load[kPreviousPosition + a] = x[i][a];
    load[kHasPrevious] = 1.0;
  }
  comm->forward_comm_fix(this);
  wall_velocity_rows_.resize(atom->nlocal + atom->nghost);
  for (int i = 0; i < atom->nlocal + atom->nghost; ++i) wall_velocity_rows_[i] = loads_[i] + kWallVelocity;
  lbm_pore::AtomArrays atoms;
  atoms.nlocal = atom->nlocal;
  atoms.nghost = atom->nghost;
  atoms.mask = atom->mask;
  atoms.groupbit = groupbit;
  atoms.tag = atom->tag;
  atoms.x = atom->x;
  atoms.v = wall_velocity_rows_.data();
  atoms.omega = atom->omega_flag ? atom->omega : nullptr;
  atoms.radius = atom->radius;
  particles_.gather(atoms, *frame_, dt_lbm);
  view_of_atom_.assign(atom->nlocal + atom->nghost, -1);
  for (std::size_t p = 0; p < particles_.size(); ++p) view_of_atom_[particles_.atom(p)] = int(p);
}

long long FixLbmPore::global_particle_count() const {
  long long local = static_cast<long long>(particles_.num_owned()) +
                    static_cast<long long>(coupling_->mapping().moving_cells().size());
  long long total = 0;
  MPI_Allreduce(&local, &total, 1, MPI_LONG_LONG, MPI_SUM, world);
  return total;
}

void FixLbmPore::fluid_step() {
  const double start = now();
  gather_particles(true);
  const double walls_start = now();
  find_walls();
  const double walls_time = now() - walls_start;
  time_lubrication_ += walls_time;
  check_particle_speed();
  // Without particles (and none left to unmap) the step is the pure fluid step: a scene pays
  // only for what it uses.
  if (global_particle_count() == 0)
    solver_->step();
  else
    coupling_->step(particles_.view());
  store_loads();
  ++fluid_steps_;
  ++run_fluid_steps_;
  time_fluid_ += now() - start - walls_time;
  const double diagnostics_start = now();
  // A full scan of the lattice costs a sizeable part of a step: the NaN/runaway guard runs
  // every kCheckEvery fluid steps (a blow-up takes many steps to reach the particles), the
  // fluid diagnostics only when thermo output asks for them.
  if (fluid_steps_ % kCheckEvery == 0) check_fluid_state();
  fluid_diagnostics_stale_ = true;
  update_particle_diagnostics();
  if (vtk_ && fluid_steps_ % options_.vtk_every == 0)
    vtk_->write(*solver_, units_->time_to_physical(double(fluid_steps_)));
  time_diagnostics_ += now() - diagnostics_start;
}

// The loads of the step, in script units, onto the atoms they belong to; ghosts' shares go
// back to their owners (LIGGGHTS reverse communication, which also folds periodic images).
void FixLbmPore::store_loads() {
  const int ntotal = atom->nlocal + atom->nghost;
  for (int i = 0; i < atom->nlocal; ++i)
    for (int a = 0; a < 3; ++a) {
      own_slot(i);
      loads_[i][kPreviousForce + a] = loads_[i][a];
      loads_[i][kPreviousVelocity + a] = loads_[i][kStepVelocity + a];
    }
  for (int i = 0; i < ntotal; ++i)
    for (int k = 0; k < kPreviousForce; ++k) loads_[i][k] = 0.0;
  const auto& loads = coupling_->loads();
  if (loads.force.size() != particles_.size()) return;  // pure fluid step: no loads
  const double force_unit = units_->force_unit();
  const double torque_unit = units_->torque_to_physical(1.0);
  // C converts lattice velocity to lattice force: force_unit * dt_lbm / dx per script velocity.
  const double coefficient_unit = force_unit * units_->dt_lbm() / options_.dx;
  for (std::size_t p = 0; p < particles_.size(); ++p) {
    const int i = particles_.atom(p);
    for (int a = 0; a < 3; ++a) {
      loads_[i][a] = loads.force[p][a] * force_unit;
      loads_[i][3 + a] = loads.torque[p][a] * torque_unit;
    }
    loads_[i][kCoefficient] = loads.velocity_coefficient[p] * coefficient_unit;
  }
  comm->reverse_comm_fix(this);
  double** v = atom->v;
  const double* rmass = atom->rmass;
  for (int i = 0; i < atom->nlocal; ++i) {
    double* load = loads_[i];
    for (int a = 0; a < 3; ++a) load[kStepVelocity + a] = v[i][a];
    // The force's response to the particle's velocity, measured between the last two steps
    // (secant: -dF.dv / |dv|^2). Where a particle nearly touches another or a wall, the fluid
    // in the gap makes it several times the moving-wall term of the links, and the explicit
    // coupling then oscillates with period two fluid steps and grows (C dt / m > 2).
    // Applied as F - C (v - v_step) within the substeps, a C close to the true one damps that
    // mode at any strength; bounded below by the wall term and above by a few masses.
    double dv2 = 0.0, dFdv = 0.0;
    for (int a = 0; a < 3; ++a) {
      const double dv = load[kStepVelocity + a] - load[kPreviousVelocity + a];
      dv2 += dv * dv;
      dFdv += (load[a] - load[kPreviousForce + a]) * dv;
    }
    const double c_max = rmass ? kMaxCoefficientMasses * rmass[i] / units_->dt_lbm() : load[kCoefficient];
    const double secant = dv2 > 0.0 ? -dFdv / dv2 : 0.0;
    load[kCoefficient] = std::clamp(secant, std::min(load[kCoefficient], c_max), c_max);
  }
}

// After read_restart: the checkpoint holds the node types of the step it was written at,
// with zeros inside the particles. The mapping object starts empty, so the moving nodes
// become fluid at rest and the particles are mapped afresh; where the restart was written
// at a fluid step (a multiple of n_dem) the same nodes are covered again and the
// continuation is exact.
void FixLbmPore::resume_mapping() {
  resumed_ = false;
  auto& types = solver_->node_types();
  auto& f = solver_->populations();
  for (std::size_t cell = 0; cell < types.size(); ++cell) {
    if (types[cell] != lbm::kMoving) continue;
    types[cell] = lbm::kFluid;
    for (int q = 0; q < lbm::D3Q19::Q; ++q) f.at(q, cell) = lbm::equilibrium(q, 1.0, {0.0, 0.0, 0.0});
  }
  gather_particles(false);
  coupling_->map_and_refill(particles_.view());
}

const coupling::LatticeFrame& FixLbmPore::frame() const { return *frame_; }
