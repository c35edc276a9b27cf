#include "fix_lbm_pore.h"

#include "atom.h"
#include "comm.h"
#include "coupling/diagnostics/particle_probes.h"
#include "coupling/lattice_frame.h"
#include "coupling/sphere_coupling.h"
#include "coupling/step_policy.h"
#include "coupling/unit_conversion.h"
#include "domain.h"
#include "error.h"
#include "force.h"
#include "lbm/checkpoint.h"
#include "lbm/fluid_solver.h"
#include "lbm/input_error.h"
#include "lbm/stability.h"
#include "lbm/vtk_output.h"
#include "memory.h"
#include "modify.h"
#include "liggghts_queries.h"
#include "neigh_list.h"
#include "neigh_request.h"
#include "plugin_common/entry_guard.h"
#include "plugin_common/ranks_error.h"
#include "plugin_common/stop_run.h"
#include "plugin_common/stop_signals.h"
#include "plugin_common/thread_cores.h"
#include "pore_scene_setup.h"
#include "neighbor.h"
#include "update.h"

using namespace LAMMPS_NS;

FixLbmPore::FixLbmPore(LAMMPS* lmp, int narg, char** arg) : Fix(lmp, narg, arg) {
  lbm_pore::refuse_second_instance(modify, error, this);
  std::vector<std::string> words(arg + 3, arg + narg);
  try {
    options_ = lbm_pore::parse_pore_options(words);
    lbm_pore::check_output_paths(options_);
    build_geometry();
  } catch (...) {  // lbm::InputError on every rank, std::bad_alloc and the like: a LIGGGHTS error
    lbm_pore::report_current_exception(error, "fix lbm/pore", lbm_pore::ErrorScope::kAllRanks);
  }
  if (!atom->radius_flag)
    error->all(FLERR, "fix lbm/pore needs per-atom radii: use atom_style granular (or sphere)");
  vector_flag = 1;
  size_vector = kInletVelocityIndex + 1;
  array_flag = 1;  // f_ID[i][j]: burst i, column j (coupling::BurstRecord)
  size_array_rows = kBurstRows;
  size_array_cols = coupling::BurstRecord::kColumns;
  extarray = 0;
  peratom_flag = 1;  // f_ID[1..3]: each atom's hydrodynamic force (dump custom)
  size_peratom_cols = 3;
  peratom_freq = 1;
  global_freq = 1;
  extvector = 0;
  restart_global = 1;
  restart_peratom = 1;
  // LIGGGHTS's insertions call set_arrays for a new atom only where this is set; without it
  // a new atom kept its slot's state (insertion reuses tags, so the tag check misses it).
  create_attribute = 1;
  // end_of_step is then called only at fluid steps: the substeps in between cost no call.
  nevery = options_.n_dem;
  comm_forward = 6;  // velocity, angular velocity
  comm_reverse = lbm_pore::AtomCouplingState::kSummed;
  grow_arrays(atom->nmax);
  atom->add_callback(0);  // grow/copy/exchange
  atom->add_callback(1);  // restart
  // From here on stop signals reach the process only at a fluid step (post_integrate) or
  // at the end of a run (post_run); blocked before any OpenMP worker of the fluid exists.
  lbm_pore::block_stop_signals();
}

FixLbmPore::~FixLbmPore() {
  atom->delete_callback(id, 0);
  atom->delete_callback(id, 1);
  memory->destroy(hydrodynamic_force_);
  lbm_pore::unblock_stop_signals();
}

int FixLbmPore::setmask() { return FixConst::POST_INTEGRATE | FixConst::POST_FORCE | FixConst::END_OF_STEP; }

// Before Neighbor::decide, where LIGGGHTS reads its stop flags: a SIGTERM is taken at a
// fluid step (or the run's last step), on every rank at once (plugin_common/stop_signals.h),
// so the forced restart is written right after the fluid step, as at a multiple of n_dem.
void FixLbmPore::post_integrate() {
  if (at_fluid_step() || update->ntimestep == update->laststep)
    lbm_pore::take_stop_requests(world);
}

void FixLbmPore::init() {
  try {
    auto units = std::make_unique<coupling::UnitConversion>(lbm_pore::unit_inputs(options_, update->dt));
    if (solver_)
      units_->check_same_tau(*units);
    else
      build_lattice(std::move(units));
    lbm_pore::check_neighbor_skin(options_, neighbor->skin);
  } catch (...) {
    lbm_pore::report_current_exception(error, "fix lbm/pore", lbm_pore::ErrorScope::kAllRanks);
  }
  if (!resume_checkpoint_.empty()) {
    // Each rank reads its own file: one missing or truncated file must stop every rank.
    const std::string failure =
        lbm_pore::try_on_every_rank(world, [&] { lbm::read_checkpoint(*solver_, resume_checkpoint_); });
    if (!failure.empty()) error->all(FLERR, ("fix lbm/pore: restart: " + failure).c_str());
    fluid_steps_ = solver_->time_step();
    resumed_ = true;
    resume_checkpoint_.clear();
  }
  if (comm->ghost_velocity == 0)
    error->all(FLERR, "fix lbm/pore needs ghost velocities: add 'communicate single vel yes'");
  if (force->newton_pair)
    error->all(FLERR, "fix lbm/pore needs 'newton off' (granular pair styles in LIGGGHTS)");
  // The lubrication and bond search use a granular neighbour list of their own.
  const int request = neighbor->request(this);
  neighbor->requests[request]->pair = 0;
  neighbor->requests[request]->fix = 1;
  neighbor->requests[request]->half = 0;
  neighbor->requests[request]->gran = 1;
  const lbm_pore::ThreadReport threads = lbm_pore::thread_report(world);
  if (comm->me == 0) {
    lbm_pore::print_to_screen_and_log(screen, logfile,
                                      (lbm_pore::setup_summary(options_, *units_, frame_->dims, solver_->drive(),
                                                               update->dt, monitor_setup_.pore_diameter,
                                                               solver_->bytes_per_node(),
                                                               lbm_pore::thread_cores().threads) +
                                       threads.summary).c_str());
    if (!threads.warning.empty()) error->warning(FLERR, threads.warning.c_str());
  }
}

void FixLbmPore::init_list(int, NeighList* list) { list_ = list; }

void FixLbmPore::build_geometry() {
  auto scene = lbm_pore::build_scene(options_, domain->boxlo);
  geometry_ = scene.geometry;
  monitor_setup_ = scene.monitor;
  surface_ = std::make_unique<contact::VoxelSurface>(*geometry_);
}

// Builds the lattice frame and the fluid solver on LIGGGHTS's own subdomains (each rank
// owns the nodes inside its subdomain), and the coupling objects that work on them.
void FixLbmPore::build_lattice(std::unique_ptr<coupling::UnitConversion> units) {
  units_ = std::move(units);
  frame_ = std::make_unique<coupling::LatticeFrame>(
      coupling::LatticeFrame{geometry_->origin(), options_.dx, geometry_->dims()});
  frame_->check_fills_box(domain->boxlo, domain->boxhi, domain->periodicity);
  lbm_pore::check_boundaries(options_, domain->periodicity);
  const lbm::FluidParameters p = lbm_pore::fluid_parameters(options_, *units_);
  const lbm::FlowDrive drive = lbm_pore::drive_of(options_, *units_);
  const coupling::SubdomainGrid grid{domain->sublo, domain->subhi, comm->myloc, comm->procgrid, comm->procneigh};
  const lbm::Decomposition decomposition =
      coupling::subdomain_decomposition(*frame_, grid, p.periodic, lbm::Communicator(world), comm->me);
  // Collective: every rank refuses together a lattice that does not fit (size and memory named).
  lbm_pore::check_lattice_memory(options_, decomposition.owned, geometry_->dims(), lbm::Communicator(world));
  solver_ = std::make_unique<lbm::FluidSolver>(*geometry_, p, drive, decomposition);
  capped_drive_ = lbm_pore::capped_drive_of(options_, *units_, *solver_, restored_drive_state_);
  coupling_ = std::make_unique<coupling::SphereCoupling>(*solver_, lbm_pore::coupling_options(options_));
  lubrication_ = std::make_unique<coupling::LubricationKernel>(lbm_pore::lubrication_kernel(options_, *units_));
  lbm_pore::set_monitor_criteria(monitor_setup_, options_, *units_, drive);
  const std::string warning = lbm::drive_accuracy_warning(drive);
  if (!warning.empty() && comm->me == 0) error->warning(FLERR, ("fix lbm/pore: pressure_loss: " + warning).c_str());
  start_monitor();
  if (options_.vtk_every > 0)
    vtk_ = std::make_unique<lbm::VtkSeriesWriter>(options_.vtk_directory, "fluid");
}

void FixLbmPore::setup(int vflag) {
  // After every fix's init(): fix gravity sets its acceleration there (buoyancy needs it).
  const std::optional<coupling::Vec3> gravity = lbm_pore::script_gravity(*modify);
  if (gravity && comm->me == 0)
    lbm_pore::print_to_screen_and_log(screen, logfile, lbm_pore::buoyancy_summary(*gravity).c_str());
  load_model_ = std::make_unique<coupling::SubstepLoadModel>(
      lbm_pore::substep_load_parameters(options_, *units_, gravity ? &*gravity : nullptr));
  pairs_step_ = -1;  // the neighbour list was rebuilt (atoms may have been re-sorted)
  timer_.start();
  if (resumed_) {
    resumed_ = false;
    lbm::release_moving_nodes(*solver_);
    gather_particles(false);
    coupling_->map_and_refill(particles_.view());
  }
  gather_particles(false);
  find_walls();
  record_particles();
  monitor_->update_fluid(*solver_, fluid_steps_);
  record_fluid_step();
  if (vtk_ && fluid_steps_ == 0) vtk_->write(*solver_, 0.0);
  post_force(vflag);
}

// The group's pairs of the neighbour list, collected when LIGGGHTS has rebuilt it: the list,
// the atoms' order and their ghosts change only then (neighbor->lastcall is the step of the
// last build; setup() forgets the pairs, for a rebuild at a run's start on the same step).
void FixLbmPore::collect_group_pairs() {
  if (pairs_step_ == neighbor->lastcall || !list_) return;
  pairs_step_ = neighbor->lastcall;
  pairs_ = lbm_pore::group_pairs(*list_, atom->mask, groupbit);
}

lbm_pore::AtomArrays FixLbmPore::atom_arrays() const {
  double** omega = atom->omega_flag && options_.rotation ? atom->omega : nullptr;
  return {atom->nlocal, atom->nghost, atom->mask, groupbit, atom->tag, atom->x, atom->v, omega, atom->radius};
}

// Every DEM substep: the substep load model's force and torque (the load of the last fluid
// step), buoyancy, and the lubrication correction that follows the particles.
void FixLbmPore::post_force(int) {
  const lbm_pore::AtomArrays atoms = atom_arrays();
  states_.add_substep_loads(*load_model_, atoms, atom->f, options_.rotation ? atom->torque : nullptr,
                            load_model_->parameters().buoyancy, hydrodynamic_force_);
  if (!options_.lubrication || !list_) return;
  const coupling::RunTimer::Scope timed(timer_, coupling::RunTimer::kLubrication);
  collect_group_pairs();
  // The per-atom output gets the lubrication too: what it added to f (owned atoms).
  states_.add_lubrication(*lubrication_, atoms, pairs_, atom->f, hydrodynamic_force_);
}

// The nearest wall of every owned particle, within the lubrication reach plus the farthest a
// particle may move in a fluid step; followed along its normal until the next fluid step.
void FixLbmPore::find_walls() {
  if (!options_.lubrication) return;
  const coupling::RunTimer::Scope timed(timer_, coupling::RunTimer::kLubrication);
  const double reach = (options_.lubrication_cutoff + coupling::kMaxShiftPerFluidStep) * options_.dx;
  states_.find_walls(atom_arrays(), *surface_, reach, wall_points_);
}

bool FixLbmPore::at_fluid_step() const { return update->ntimestep % options_.n_dem == 0; }

void FixLbmPore::end_of_step() {
  if (at_fluid_step()) fluid_step();
}

// Lattice-unit copies of the group's owned atoms and ghosts, with the velocity the fluid
// sees each sphere move with (coupling::StepMotion, from its displacements over the last
// fluid steps). `advance` is false at setup, where no step has passed.
void FixLbmPore::gather_particles(bool advance) {
  const lbm_pore::AtomArrays atoms = atom_arrays();
  states_.step_motion(atoms, units_->dt_lbm(), advance, [&](double* d) { domain->minimum_image(d); });
  comm->forward_comm_fix(this);  // to the ghosts
  particles_.gather(states_.seen_by_fluid(atoms), *frame_, *units_);
}

void FixLbmPore::fluid_step() {
  {
    const coupling::RunTimer::Scope timed(timer_, coupling::RunTimer::kFluid);
    gather_particles(true);
    find_walls();
    check_particle_speed();
    const bool coupled = coupling::advance_fluid(*coupling_, particles_.view(), comm->cutghost, options_.dx,
                                                 solver_->decomposition().comm) == coupling::FluidStep::kCoupled;
    if (capped_drive_) capped_drive_->update(*solver_);  // the next step's inlet velocity
    if (coupled)
      monitor_->record_coupling_mass(coupling_->last_surface_mass(),
                                     coupling_->last_mass_change().net_over(solver_->parameters().rho0));
    store_loads(coupled);
    ++fluid_steps_;
    timer_.count_fluid_step();
  }
  const coupling::RunTimer::Scope timed(timer_, coupling::RunTimer::kDiagnostics);
  // A full scan of the lattice costs a sizeable part of a step: the NaN/runaway guard runs
  // every kCheckEvery fluid steps (a blow-up takes many steps to reach the particles), the
  // fluid diagnostics only when thermo output asks for them.
  if (fluid_steps_ % kCheckEvery == 0) check_fluid_state();
  monitor_->fluid_changed();
  record_particles();
  record_fluid_step();
  if (vtk_ && fluid_steps_ % options_.vtk_every == 0)
    vtk_->write(*solver_, units_->time_to_physical(double(fluid_steps_)));
}

// The loads of the step, in script units, onto the atoms they belong to; ghosts' shares go
// back to their owners (LIGGGHTS reverse communication, which also folds periodic images).
void FixLbmPore::store_loads(bool coupled) {
  states_.start_fluid_step(atom->nlocal, atom->nlocal + atom->nghost);
  if (!coupled) return;  // pure fluid step: no loads
  states_.store_loads(particles_, coupling_->loads(), *units_);
  comm->reverse_comm_fix(this);
  states_.finish_fluid_step(*load_model_, atom_arrays(), atom->rmass);
}

const coupling::LatticeFrame& FixLbmPore::frame() const { return *frame_; }
