#pragma once
// From fix lbm/pore's parsed keywords to the objects lbm/ and coupling/ build on: the voxel
// geometry and where its pore is, the drive in lattice units, the checks that the script's
// box and boundaries match the fluid's. No LIGGGHTS dependency (the fix passes its box).
#include <array>
#include <memory>

#include "coupling/diagnostics/pore_monitor.h"
#include "coupling/unit_conversion.h"
#include "lbm/fluid_solver.h"
#include "lbm/voxel_geometry.h"
#include "lbm_pore_options.h"

namespace lbm_pore {

struct SceneSetup {
  std::shared_ptr<const lbm::VoxelGeometry> geometry;
  coupling::PoreMonitorSetup monitor;  // the pore and the counting planes, lattice units
};

// The paper's scene from its lengths, or a voxel file placed with node 0 at `origin`
// (default: half a cell inside the box's lower corner). Throws lbm::InputError.
SceneSetup build_scene(const PoreOptions& options, const double* box_lo);

// The drive along +x in lattice units; throws lbm::InputError naming 'velocity' or
// 'pressure_loss' when it exceeds the scheme's limits (lbm/stability.h).
lbm::FlowDrive drive_of(const PoreOptions& options, const coupling::UnitConversion& units);

// The fluid's lateral boundaries and LIGGGHTS's periodicity (domain->periodicity) must agree,
// and the flow axis x must not be periodic. Throws lbm::InputError saying what to change.
void check_boundaries(const PoreOptions& options, const int* periodicity);

// The speed below which a bonded particle counts as deposited (lattice units): the
// 'deposit_speed' keyword, else a fraction of the inlet velocity, else the default.
double deposit_speed_threshold(const PoreOptions& options, const coupling::UnitConversion& units,
                               const lbm::FlowDrive& drive);

}  // namespace lbm_pore
