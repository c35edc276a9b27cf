#include "pore_scene_setup.h"

#include "lbm/moving_wall/moving_wall_scheme.h"

#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <utility>

#include "coupling/memory_estimate.h"
#include "lbm/input_error.h"
#include "lbm/memory_estimate.h"
#include "lbm/pore_scene.h"
#include "lbm/stability.h"
#include "lbm/voxel_file.h"

namespace lbm_pore {

namespace {
// Nodes along one axis are ints (lbm::BlockLayout); more than this cannot be a lattice anyway.
constexpr double kMaxCellsPerAxis = 1 << 30;

int cells(double length, double dx) { return static_cast<int>(std::lround(length / dx)); }

std::string format(double v) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", v);
  return text;
}

// Before any voxel is allocated: the scene's lengths in cells must be ints, and its geometry
// (one byte a node, held by the fix and by the fluid solver on every rank) must fit in memory.
void check_scene_size(const PoreOptions& o) {
  const double dx = o.dx;
  const double length_cells = std::round(o.inlet_length / dx) + std::round(o.free_length / dx) +
                              std::round(o.pore_length / dx) + std::round(o.outlet_length / dx);
  const double width_cells = std::round(o.width / dx);
  const std::string lattice = "scene pore: with dx = " + format(dx) + " the lattice has " +
                              format(length_cells) + " x " + format(width_cells) + " x " +
                              format(width_cells) + " nodes";
  const std::string hint = "raise dx or shorten the scene";
  if (length_cells > kMaxCellsPerAxis || width_cells > kMaxCellsPerAxis)
    throw lbm::InputError(lattice + ", more than 2^30 along an axis; " + hint);
  lbm::check_fits_in_memory(
      2.0 * lbm::geometry_bytes({int(length_cells), int(width_cells), int(width_cells)}),
      lattice + ", whose geometry (a byte per node, twice on every rank)", hint);
}

// The nearest folder of `path` that exists (itself, or its folder for a file, or an ancestor)
// must be a folder this process can create files in: a file of the same name, or a folder that
// refuses writing, would stop the run later, at the first output, after the set-up is paid for.
void check_writable_location(const std::string& keyword, const std::filesystem::path& path,
                             bool path_is_file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  fs::path existing = path_is_file ? path.parent_path() : path;
  if (existing.empty()) existing = ".";
  while (!fs::exists(existing, ec) && existing.has_parent_path() &&
         existing != existing.parent_path())
    existing = existing.parent_path();
  if (!fs::exists(existing, ec)) existing = ".";  // a relative path whose first folder is new
  if (!fs::is_directory(existing, ec))
    throw lbm::InputError(keyword + ": '" + existing.string() +
                          "' exists and is not a directory (for '" + path.string() +
                          "'); give another path");
  // Creating (and removing) a file is the only test that also holds for root and read-only mounts.
  std::string probe = (existing / ".lbm_pore_write_test_XXXXXX").string();
  const int fd = mkstemp(probe.data());
  if (fd < 0)
    throw lbm::InputError(keyword + ": cannot create files in the directory '" + existing.string() +
                          "' (for '" + path.string() + "'): " + std::strerror(errno));
  close(fd);
  std::remove(probe.c_str());
}
}  // namespace

SceneSetup build_scene(const PoreOptions& o, const double* box_lo) {
  const double dx = o.dx;
  if (o.scene == PoreOptions::Scene::kPore) check_scene_size(o);
  std::array<double, 3> origin;
  for (int a = 0; a < 3; ++a) origin[a] = o.origin_given ? o.origin[a] : box_lo[a] + 0.5 * dx;
  SceneSetup scene;
  if (o.scene == PoreOptions::Scene::kPore) {
    lbm::PoreSceneSpec spec;
    spec.inlet_length = cells(o.inlet_length, dx);
    spec.free_length = cells(o.free_length, dx);
    spec.pore_length = cells(o.pore_length, dx);
    spec.outlet_length = cells(o.outlet_length, dx);
    spec.width = cells(o.width, dx);
    spec.pore_diameter = o.pore_diameter / dx;
    scene.geometry = std::make_shared<lbm::VoxelGeometry>(lbm::make_pore_scene(spec, dx, origin));
    scene.monitor = coupling::pore_scene_monitor(
        spec, o.deposits_in_pore_only ? coupling::DepositRegion::kPore : coupling::DepositRegion::kFromInlet);
    return scene;
  }
  auto file = std::make_shared<lbm::VoxelGeometry>(lbm::load_voxel_file(o.voxel_file));
  if (std::abs(file->spacing() - dx) > 1e-9 * dx)
    throw lbm::InputError("scene voxels: the file's spacing " + std::to_string(file->spacing()) +
                          " differs from dx " + std::to_string(dx));
  file->place_at(origin);  // where the box (or 'origin') says; the file's own is ignored
  scene.monitor = coupling::voxel_geometry_monitor(*file);
  scene.geometry = file;
  return scene;
}

void check_output_paths(const PoreOptions& o) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (o.vtk_every > 0) {
    if (fs::exists(o.vtk_directory, ec) && !fs::is_directory(o.vtk_directory, ec))
      throw lbm::InputError("vtk: '" + o.vtk_directory +
                            "' exists and is not a directory; give a directory");
    check_writable_location("vtk", o.vtk_directory, false);
  }
  for (const auto& [keyword, file] :
       {std::pair<std::string, std::string>{"checkpoint", o.checkpoint_prefix},
        std::pair<std::string, std::string>{"burst_file", o.burst_file}}) {
    if (file.empty()) continue;
    if (fs::is_directory(file, ec))
      throw lbm::InputError(keyword + ": '" + file + "' is a directory; give a file name");
    check_writable_location(keyword, file, true);
  }
}

void check_lattice_memory(const PoreOptions& o, const lbm::Box& owned,
                          const std::array<int, 3>& global, const lbm::Communicator& comm) {
  const std::string what = "the lattice of " + std::to_string(global[0]) + " x " +
                           std::to_string(global[1]) + " x " + std::to_string(global[2]) +
                           " nodes (dx = " + format(o.dx) + "; " + std::to_string(owned.size(0)) +
                           " x " + std::to_string(owned.size(1)) + " x " +
                           std::to_string(owned.size(2)) + " on this rank)";
  lbm::check_fits_in_memory_on_every_machine(
      lbm::lattice_bytes({owned.size(0), owned.size(1), owned.size(2)}, global), what,
      "raise dx, shrink the scene or run on more machines", comm);
}

lbm::FlowDrive drive_of(const PoreOptions& o, const coupling::UnitConversion& units) {
  lbm::FlowDrive drive;
  drive.axis = 0;
  const bool by_velocity = o.drive == PoreOptions::Drive::kVelocity;
  drive.kind = by_velocity ? lbm::FlowDrive::kInletVelocity : lbm::FlowDrive::kPressureLoss;
  if (by_velocity)
    drive.inlet_velocity = units.velocity_to_lattice(o.drive_value);
  else
    drive.pressure_loss = units.pressure_to_lattice(o.drive_value);
  const std::string violation = lbm::drive_limit_violation(drive);
  if (violation.empty()) return drive;
  char text[500];
  std::snprintf(text, sizeof text, "%s: %g is %s; lower '%s'%s, or refine dx",
                by_velocity ? "velocity" : "pressure_loss", o.drive_value, violation.c_str(),
                by_velocity ? "velocity" : "pressure_loss",
                by_velocity ? ", lower n_dem or the DEM time step" : " or n_dem");
  throw lbm::InputError(text);
}

std::unique_ptr<coupling::PoreMonitor> pore_monitor_of(const coupling::PoreMonitorSetup& setup,
                                                       const coupling::UnitConversion& units,
                                                       const std::vector<double>& restored_state) {
  auto monitor = std::make_unique<coupling::PoreMonitor>(setup, units);
  try {
    if (!restored_state.empty()) monitor->restore(restored_state);
  } catch (const std::invalid_argument& e) {
    throw lbm::InputError(std::string("restart: ") + e.what());
  }
  return monitor;
}

std::unique_ptr<lbm::CappedVelocityDrive> capped_drive_of(const PoreOptions& o, const coupling::UnitConversion& units,
                                                          lbm::FluidSolver& solver,
                                                          const std::vector<double>& restored_state) {
  if (!(o.max_pressure_loss > 0.0)) return nullptr;
  lbm::FlowDrive pressure = solver.drive();
  pressure.kind = lbm::FlowDrive::kPressureLoss;
  pressure.pressure_loss = units.pressure_to_lattice(o.max_pressure_loss);
  const std::string violation = lbm::drive_limit_violation(pressure);
  if (!violation.empty()) {
    char text[500];
    std::snprintf(text, sizeof text, "max_pressure_loss: %g is %s; lower 'max_pressure_loss' or n_dem, or refine dx",
                  o.max_pressure_loss, violation.c_str());
    throw lbm::InputError(text);
  }
  auto capped = std::make_unique<lbm::CappedVelocityDrive>(solver, solver.drive(), pressure.pressure_loss);
  try {
    if (!restored_state.empty()) capped->set_state(restored_state, solver);
  } catch (const std::invalid_argument& e) {
    throw lbm::InputError(std::string("restart: max_pressure_loss: ") + e.what());
  }
  return capped;
}

void check_boundaries(const PoreOptions& o, const int* periodicity) {
  for (int a = 1; a < 3; ++a)
    if (o.lateral_periodic != (periodicity[a] != 0))
      throw lbm::InputError(std::string("lateral: the fluid is ") + (o.lateral_periodic ? "periodic" : "walled") +
                            " along " + "xyz"[a] + " but the LIGGGHTS boundary there is " +
                            (periodicity[a] ? "periodic" : "not periodic") +
                            "; use 'boundary f p p' with 'lateral periodic' or 'boundary f f f' "
                            "with 'lateral wall'");
  if (periodicity[0])
    throw lbm::InputError("the flow axis x must not be periodic: use 'boundary f ...' (the "
                          "fluid enters at x-lo and leaves at x-hi)");
}

double deposit_speed_threshold(const PoreOptions& o, const coupling::UnitConversion& units,
                               const lbm::FlowDrive& drive) {
  if (o.deposit_speed >= 0.0) return units.velocity_to_lattice(o.deposit_speed);
  // velocity 0 (a closed box) has no inlet velocity to take a fraction of: the default then.
  if (drive.kind == lbm::FlowDrive::kInletVelocity && drive.inlet_velocity != 0.0)
    return coupling::kDepositSpeedFraction * std::abs(drive.inlet_velocity);
  return coupling::DepositionCriteria{}.speed_threshold;
}

coupling::BurstCriteria burst_criteria(const PoreOptions& o, const coupling::UnitConversion& units) {
  coupling::BurstCriteria criteria;
  criteria.fraction = o.burst_drop;
  if (o.burst_window > 0.0)
    criteria.window = std::max(1LL, std::llround(o.burst_window / units.dt_lbm()));
  return criteria;
}

void set_monitor_criteria(coupling::PoreMonitorSetup& setup, const PoreOptions& o,
                          const coupling::UnitConversion& units, const lbm::FlowDrive& drive) {
  setup.criteria.speed_threshold = deposit_speed_threshold(o, units, drive);
  setup.bursts = burst_criteria(o, units);
  setup.burst_min_deposited = o.burst_deposits;
}

coupling::SphereCouplingOptions coupling_options(const PoreOptions& o) {
  coupling::SphereCouplingOptions co;
  co.wall_scheme = lbm::moving_wall::parse(o.boundary);
  co.conserve_link_mass = o.mass_correction;
  co.correct_mass_in_kernel = o.mass_correction_in_kernel;
  co.moving_walls_in_kernel = o.moving_walls_in_kernel;
  co.reference_pressure =
      o.keep_reference_pressure ? coupling::ReferencePressure::kKept : coupling::ReferencePressure::kRemoved;
  return co;
}

coupling::SubstepLoadParameters substep_load_parameters(const PoreOptions& o, const coupling::UnitConversion& units,
                                                        const coupling::Vec3* gravity) {
  coupling::SubstepLoadParameters lp;
  lp.dt_fluid = units.dt_lbm();
  lp.share = o.substep_fraction ? 1.0 / o.n_dem : 1.0;
  lp.buoyancy = gravity != nullptr;
  lp.fluid_density = o.rho;
  if (gravity) lp.gravity = *gravity;
  return lp;
}

std::string buoyancy_summary(const coupling::Vec3& g) {
  char text[300];
  std::snprintf(text, sizeof text,
                "fix lbm/pore: fix gravity found: buoyancy -rho V g added to each particle, g = (%g, %g, %g)\n",
                g[0], g[1], g[2]);
  return text;
}

coupling::BurstUnits burst_units(const std::string& unit_style) {
  coupling::BurstUnits units;
  units.pressure = "P_out";
  if (unit_style == "si" || unit_style == "cgs") {
    units.time = "s";
    units.length = unit_style == "si" ? "m" : "cm";
    units.volume = units.length + "^3";
    units.force = unit_style == "si" ? "N" : "dyn";
  }
  return units;
}

coupling::UnitInputs unit_inputs(const PoreOptions& o, double dt_dem) {
  coupling::UnitInputs in;
  in.dx = o.dx;
  in.rho = o.rho;
  in.nu = o.nu;
  in.dt_dem = dt_dem;
  in.n_dem = o.n_dem;
  return in;
}

lbm::FluidParameters fluid_parameters(const PoreOptions& o, const coupling::UnitConversion& units) {
  lbm::FluidParameters p;
  p.tau = units.tau();
  p.magic = o.magic;
  p.periodic = {false, o.lateral_periodic, o.lateral_periodic};
  return p;
}

coupling::LubricationKernel lubrication_kernel(const PoreOptions& o, const coupling::UnitConversion& units) {
  coupling::LubricationParameters lp;
  lp.rho = 1.0;
  lp.nu = units.nu_lattice();
  lp.cutoff = o.lubrication_cutoff;
  return coupling::LubricationKernel(lp, coupling::LubricationScales{o.dx, units.dt_lbm(), units.force_unit()});
}

void check_neighbor_skin(const PoreOptions& o, double skin) {
  const double reach = o.lubrication_cutoff * o.dx;
  if (!o.lubrication || skin >= reach) return;
  char text[300];
  std::snprintf(text, sizeof text,
                "the neighbor skin %g is smaller than the lubrication cutoff lubrication_cutoff * dx = "
                "%g: raise it ('neighbor %g bin') or lower lubrication_cutoff",
                skin, reach, reach);
  throw lbm::InputError(text);
}

std::string setup_summary(const PoreOptions& o, const coupling::UnitConversion& units,
                          const std::array<int, 3>& dims, const lbm::FlowDrive& drive, double dt_dem,
                          double pore_diameter, double bytes_per_node, int threads) {
  char text[1500];
  int n = std::snprintf(text, sizeof text,
                        "fix lbm/pore: lattice %d x %d x %d nodes (dx = %g), %s\n"
                        "fix lbm/pore: DEM step %g, fluid step %g = %d DEM steps; pore diameter %.2f cells\n",
                        dims[0], dims[1], dims[2], o.dx, units.summary().c_str(), dt_dem, units.dt_lbm(),
                        o.n_dem, pore_diameter);
  if (drive.kind == lbm::FlowDrive::kInletVelocity)
    n += std::snprintf(text + n, sizeof text - n, "fix lbm/pore: inlet velocity %g = %.4g lattice, lattice Mach %.3g\n",
                       o.drive_value, drive.inlet_velocity, std::abs(drive.inlet_velocity) / lbm::kSoundSpeed);
  else
    n += std::snprintf(text + n, sizeof text - n,
                       "fix lbm/pore: pressure loss %g = %.4g lattice (density difference %.3g)\n", o.drive_value,
                       drive.pressure_loss, 3.0 * drive.pressure_loss);
  if (o.max_pressure_loss > 0.0) {
    const double ceiling = units.pressure_to_lattice(o.max_pressure_loss);
    n += std::snprintf(text + n, sizeof text - n,
                       "fix lbm/pore: pressure loss at most %g = %.4g lattice (%.3g P_out): the inlet velocity is "
                       "lowered to hold it (max_pressure_loss)\n",
                       o.max_pressure_loss, ceiling, 3.0 * ceiling);
  }
  const bool links_in_kernel =
      o.moving_walls_in_kernel && o.mass_correction && o.mass_correction_in_kernel && o.boundary == "mls";
  n += std::snprintf(text + n, sizeof text - n,
                     "fix lbm/pore: moving walls %s %s (mass correction %s), lubrication %s (cutoff %g cells)\n",
                     o.boundary.c_str(), links_in_kernel ? "in the kernel's pass" : "in the sweep",
                     !o.mass_correction ? "off" : o.mass_correction_in_kernel ? "in the kernel's pass" : "in the sweep",
                     o.lubrication ? "on" : "off", o.lubrication_cutoff);
  if (bytes_per_node > 0.0)
    std::snprintf(text + n, sizeof text - n,
                  "fix lbm/pore: memory %.0f bytes per lattice node (fluid %.0f, particle coupling %.0f)\n",
                  bytes_per_node + coupling::coupling_bytes_per_node(threads), bytes_per_node,
                  coupling::coupling_bytes_per_node(threads));
  return text;
}

}  // namespace lbm_pore
