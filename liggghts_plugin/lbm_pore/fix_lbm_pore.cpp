#include "fix_lbm_pore.h"

#include <cmath>
#include <cstdio>
#include <cstring>

#include "atom.h"
#include "comm.h"
#include "coupling/lattice_frame.h"
#include "coupling/unit_conversion.h"
#include "domain.h"
#include "error.h"
#include "lbm/checkpoint.h"
#include "lbm/decomposition.h"
#include "lbm/fluid_solver.h"
#include "lbm/input_error.h"
#include "lbm/macroscopic.h"
#include "lbm/pore_scene.h"
#include "lbm/stability.h"
#include "lbm/voxel_file.h"
#include "lbm/vtk_output.h"
#include "update.h"

using namespace LAMMPS_NS;

namespace {
// Lattice speeds above this are refused (drive) or stop the run (during it): the scheme
// is accurate only well below the lattice speed of sound c_s = 1/sqrt(3).
constexpr double kMaxLatticeSpeed = 0.3;
constexpr double kSoundSpeed = 0.5773502691896258;

int cells(double length, double dx) { return static_cast<int>(std::lround(length / dx)); }
}  // namespace

FixLbmPore::FixLbmPore(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  std::vector<std::string> words(arg + 3, arg + narg);
  try {
    options_ = lbm_pore::parse_pore_options(words);
  } catch (const lbm::InputError& e) {
    error->all(FLERR, e.what());
  }
  vector_flag = 1;
  size_vector = kNumDiagnostics;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  nevery = 1;
  diagnostics_.assign(kNumDiagnostics, 0.0);
}

FixLbmPore::~FixLbmPore() = default;

int FixLbmPore::setmask() { return FixConst::POST_FORCE | FixConst::END_OF_STEP; }

void FixLbmPore::init() {
  coupling::UnitInputs in;
  in.dx = options_.dx;
  in.rho = options_.rho;
  in.nu = options_.nu;
  in.dt_dem = update->dt;
  in.n_dem = options_.n_dem;
  try {
    units_ = std::make_unique<coupling::UnitConversion>(in);
    if (!solver_) build_lattice();
  } catch (const lbm::InputError& e) {
    error->all(FLERR, (std::string("fix lbm/pore: ") + e.what()).c_str());
  }
  if (!resume_checkpoint_.empty()) {
    try {
      lbm::read_checkpoint(*solver_, resume_checkpoint_);
      fluid_steps_ = solver_->time_step();
    } catch (const lbm::InputError& e) {
      error->all(FLERR, (std::string("fix lbm/pore: restart: ") + e.what()).c_str());
    }
    resume_checkpoint_.clear();
  }
  print_setup();
}

// Builds the voxel geometry, the lattice frame and the fluid solver on LIGGGHTS's own
// subdomains (each rank owns the nodes inside its subdomain).
void FixLbmPore::build_lattice() {
  const double dx = options_.dx;
  if (options_.scene == lbm_pore::PoreOptions::Scene::kPore) {
    lbm::PoreSceneSpec spec;
    spec.inlet_length = cells(options_.inlet_length, dx);
    spec.free_length = cells(options_.free_length, dx);
    spec.pore_length = cells(options_.pore_length, dx);
    spec.outlet_length = cells(options_.outlet_length, dx);
    spec.width = cells(options_.width, dx);
    spec.pore_diameter = options_.pore_diameter / dx;
    pore_diameter_lattice_ = spec.pore_diameter;
    geometry_ = std::make_unique<lbm::VoxelGeometry>(lbm::make_pore_scene(spec, dx));
  } else {
    geometry_ = std::make_unique<lbm::VoxelGeometry>(lbm::load_voxel_file(options_.voxel_file));
    if (std::abs(geometry_->spacing() - dx) > 1e-9 * dx)
      throw lbm::InputError("scene voxels: the file's spacing " +
                            std::to_string(geometry_->spacing()) + " differs from dx " +
                            std::to_string(dx));
    // The pore diameter of an arbitrary geometry: the narrowest open cross-section's
    // equivalent circle, sqrt(4 A / pi).
    const auto& d = geometry_->dims();
    double narrowest = 1e300;
    for (int i = 0; i < d[0]; ++i) {
      int open = 0;
      for (int k = 0; k < d[2]; ++k)
        for (int j = 0; j < d[1]; ++j) open += !geometry_->is_solid(i, j, k);
      narrowest = std::min(narrowest, double(open));
    }
    pore_diameter_lattice_ = std::sqrt(4.0 * narrowest / M_PI);
  }

  frame_ = std::make_unique<coupling::LatticeFrame>();
  frame_->dx = dx;
  frame_->dims = geometry_->dims();
  for (int a = 0; a < 3; ++a)
    frame_->origin[a] = options_.origin_given ? options_.origin[a] : domain->boxlo[a] + 0.5 * dx;
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

  lbm::FluidParameters p;
  p.tau = units_->tau();
  p.magic = options_.magic;
  p.periodic = {false, options_.lateral_periodic, options_.lateral_periodic};
  lbm::FlowDrive drive;
  drive.axis = 0;
  if (options_.drive == lbm_pore::PoreOptions::Drive::kVelocity) {
    drive.kind = lbm::FlowDrive::kInletVelocity;
    drive.inlet_velocity = units_->velocity_to_lattice(options_.drive_value);
  } else {
    drive.kind = lbm::FlowDrive::kPressureLoss;
    drive.pressure_loss = units_->pressure_to_lattice(options_.drive_value);
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
  inlet_plane_ = 0;
  outlet_plane_ = frame_->dims[0] - 1;

  if (options_.vtk_every > 0) vtk_ = std::make_unique<lbm::VtkSeriesWriter>(options_.vtk_directory, "fluid");
}

void FixLbmPore::print_setup() const {
  if (comm->me != 0) return;
  const auto& dims = frame_->dims;
  const double u_lattice = std::abs(solver_->drive().kind == lbm::FlowDrive::kInletVelocity
                                        ? solver_->drive().inlet_velocity
                                        : 0.0);
  char text[1024];
  std::snprintf(text, sizeof text,
                "fix lbm/pore: lattice %d x %d x %d (dx = %g), %s\n"
                "fix lbm/pore: DEM step %g, fluid step %g = %d DEM steps; inlet lattice Mach %.3g; "
                "pore diameter %.2f cells\n",
                dims[0], dims[1], dims[2], options_.dx, units_->summary().c_str(), update->dt,
                units_->dt_lbm(), options_.n_dem, u_lattice / kSoundSpeed, pore_diameter_lattice_);
  if (screen) std::fputs(text, screen);
  if (logfile) std::fputs(text, logfile);
}

void FixLbmPore::setup(int) {
  update_diagnostics();
  if (vtk_ && fluid_steps_ == 0) vtk_->write(*solver_, 0.0);
}

void FixLbmPore::post_force(int) {
  // The hydrodynamic force of the last fluid step acts on every DEM substep (paper,
  // "Coupling of Fluid and Particles"). Added by the particle coupling stage.
}

void FixLbmPore::end_of_step() {
  if (update->ntimestep % options_.n_dem != 0) return;
  fluid_step();
}

void FixLbmPore::fluid_step() {
  solver_->step();
  ++fluid_steps_;
  check_fluid_state();
  update_diagnostics();
  if (vtk_ && fluid_steps_ % options_.vtk_every == 0)
    vtk_->write(*solver_, units_->time_to_physical(double(fluid_steps_)));
}

// NaN or runaway speed stops the run, naming the step, the node and the likely cause.
void FixLbmPore::check_fluid_state() {
  const auto problem = lbm::check_fluid_state(*solver_, 0.5);
  int local_bad = problem.found ? 1 : 0, any_bad = 0;
  MPI_Allreduce(&local_bad, &any_bad, 1, MPI_INT, MPI_MAX, world);
  if (!any_bad) return;
  if (problem.found) {
    char text[600];
    std::snprintf(text, sizeof text,
                  "fix lbm/pore: fluid became unstable at DEM step " BIGINT_FORMAT
                  " (fluid step %lld), %s. Likely cause: the drive or a particle is too fast "
                  "for the lattice (keep speeds below %.2f in lattice units: lower 'velocity' or "
                  "'pressure_loss', refine dx or lower n_dem) or tau too close to 0.5",
                  update->ntimestep, fluid_steps_, problem.describe().c_str(), kMaxLatticeSpeed);
    error->one(FLERR, text);
  }
  MPI_Barrier(world);
  error->all(FLERR, "fix lbm/pore: fluid became unstable (see the message of the rank that found it)");
}

void FixLbmPore::update_diagnostics() {
  auto& v = diagnostics_;
  v[kPressureLoss] = units_->pressure_to_physical(lbm::pressure_loss(*solver_));
  // plane_flux is in lattice volume per lattice time step.
  const double flux_unit = options_.dx * options_.dx * options_.dx / units_->dt_lbm();
  v[kFluidFluxInlet] = lbm::plane_flux(*solver_, 0, inlet_plane_) * flux_unit;
  v[kFluidFluxOutlet] = lbm::plane_flux(*solver_, 0, outlet_plane_) * flux_unit;
  const double speed = lbm::max_speed(*solver_);
  v[kMaxFluidSpeed] = units_->velocity_to_physical(speed);
  v[kLatticeMach] = speed / kSoundSpeed;
  v[kFluidSteps] = double(fluid_steps_);
}

double FixLbmPore::compute_vector(int index) {
  if (index < 0 || index >= kNumDiagnostics) return 0.0;
  return diagnostics_[index];
}

// Restart: the particles travel in LIGGGHTS's restart file; the fluid goes to a companion
// checkpoint (one file per rank) whose name is stored in the restart file.
void FixLbmPore::write_restart(FILE* fp) {
  std::string prefix = options_.checkpoint_prefix.empty() ? std::string(id) + ".fluid"
                                                          : options_.checkpoint_prefix;
  const std::string path = prefix + "." + std::to_string(update->ntimestep);
  try {
    lbm::write_checkpoint(*solver_, path);
  } catch (const lbm::InputError& e) {
    error->one(FLERR, e.what());
  }
  if (comm->me == 0) {
    const int size = static_cast<int>(path.size()) + 1;
    std::fwrite(&size, sizeof(int), 1, fp);
    std::fwrite(path.c_str(), 1, size, fp);
  }
}

void FixLbmPore::restart(char* buf) {
  // buf holds the path write_restart stored (LIGGGHTS strips its size word).
  resume_checkpoint_ = std::string(buf);
}

const lbm::VoxelGeometry& FixLbmPore::geometry() const { return *geometry_; }
const coupling::LatticeFrame& FixLbmPore::frame() const { return *frame_; }
