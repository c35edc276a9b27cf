#include "pore_scene_setup.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

#include "lbm/input_error.h"
#include "lbm/pore_scene.h"
#include "lbm/stability.h"
#include "lbm/voxel_file.h"

namespace lbm_pore {

namespace {
int cells(double length, double dx) { return static_cast<int>(std::lround(length / dx)); }
}  // namespace

SceneSetup build_scene(const PoreOptions& o, const double* box_lo) {
  const double dx = o.dx;
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
    scene.monitor = coupling::pore_scene_monitor(spec);
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
  if (drive.kind == lbm::FlowDrive::kInletVelocity)
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

coupling::BurstUnits burst_units(const std::string& unit_style) {
  coupling::BurstUnits units;
  units.pressure = "P_out";
  if (unit_style == "si" || unit_style == "cgs") {
    units.time = "s";
    units.length = unit_style == "si" ? "m" : "cm";
    units.volume = units.length + "^3";
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
                          double pore_diameter) {
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
  std::snprintf(text + n, sizeof text - n, "fix lbm/pore: moving walls %s, lubrication %s (cutoff %g cells)\n",
                o.boundary.c_str(), o.lubrication ? "on" : "off", o.lubrication_cutoff);
  return text;
}

}  // namespace lbm_pore
