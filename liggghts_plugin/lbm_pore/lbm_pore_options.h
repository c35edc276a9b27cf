#pragma once
// Keywords of `fix ID group lbm/pore keyword value ...`, parsed without LIGGGHTS so the
// parser is unit-tested on its own. Lengths, velocities, pressures, densities and
// viscosities are in the script's units; the fix converts them with coupling::UnitConversion.
#include <array>
#include <string>
#include <vector>

namespace lbm_pore {

struct PoreOptions {
  // Lattice and fluid.
  double dx = 0.0;            // lattice spacing (required)
  double rho = 1.0;           // fluid density
  double nu = 1.0 / 6.0;      // kinematic viscosity
  int n_dem = 100;            // DEM steps per fluid step
  double magic = 3.0 / 16.0;  // TRT magic parameter
  // Geometry: the paper's scene from lengths, or a voxel file.
  enum class Scene { kNone, kPore, kVoxelFile } scene = Scene::kNone;
  double inlet_length = 0, free_length = 0, pore_length = 0, outlet_length = 0;
  double width = 0, pore_diameter = 0;
  std::string voxel_file;
  bool origin_given = false;
  std::array<double, 3> origin{0.0, 0.0, 0.0};
  bool lateral_periodic = true;
  // Drive (along +x).
  enum class Drive { kVelocity, kPressureLoss } drive = Drive::kVelocity;
  double drive_value = 0.0;
  // > 0 with the velocity drive: the inlet velocity is lowered where the pressure loss would
  // pass this (lbm::CappedVelocityDrive), the paper's imposed pressure on a pore that fills
  // at the inlet velocity first.
  double max_pressure_loss = 0.0;
  // Particle coupling.
  std::string boundary = "mls";  // bounce_back | bouzidi | mls
  // Put back the mass the interpolated links (bouzidi, mls) create at each node every step
  // (lbm/moving_wall/link_mass.h); 'no' only to reproduce runs made before it existed.
  bool mass_correction = true;
  // 'yes' (the default) and 'kernel': that correction taken in the collide-stream's pass
  // (coupling::SphereCouplingOptions::correct_mass_in_kernel); 'sweep': in the moving walls'
  // sweep, slower, the same bits.
  bool mass_correction_in_kernel = true;
  // 'kernel' (the default): the moving walls' links themselves applied in the collide-stream's
  // pass, where the correction is and the scheme is mls (coupling::SphereCouplingOptions::
  // moving_walls_in_kernel); 'sweep': in the sweep before it, slower, the same bits.
  bool moving_walls_in_kernel = true;
  // The momentum exchange keeps each link's reference-pressure share (the paper's Eq. 2 read
  // literally: a particle touching a wall is pressed into it by p0 on its unlinked surface)
  // or removes it (the default; coupling/force/momentum_exchange.h).
  bool keep_reference_pressure = false;
  // Each DEM substep applies the fluid step's whole load ('held', the default) or 1 / n_dem
  // of it ('fraction', the paper's wording read literally; coupling/force/substep_load.h).
  bool substep_fraction = false;
  bool lubrication = true;
  // The paper neglects rotation (translation only): with 'rotation no' the fix adds no
  // torque and the fluid sees the particles without spin (integrate them with fix nve).
  bool rotation = true;
  double lubrication_cutoff = 2.0 / 3.0;  // in lattice cells
  // Where a deposit counts: the pore's cylinder from the end of the inlet region (through
  // the free region, the pore's mouth included) or inside the pore alone.
  bool deposits_in_pore_only = false;
  double deposit_speed = -1.0;            // < 0: 10 % of the inlet velocity (1e-4 lattice with a pressure drive)
  // Erosive bursts (coupling/diagnostics/burst_detector.h): a peak of the pressure loss
  // followed by a fall of at least burst_drop (fraction of the peak) within burst_window
  // (time units; < 0: the detector's default), one row per burst in burst_file ("": none).
  double burst_drop = 0.1;
  double burst_window = -1.0;
  std::string burst_file;
  int burst_deposits = 1;  // deposited particles a peak needs for its fall to be erosive
  // Speeds of the particles in the deposit region (coupling/diagnostics/deposit_speeds.h),
  // summed over each interval of deposit_speeds_every fluid steps into deposit_speeds_file
  // (0 / "": not counted).
  int deposit_speeds_every = 0;
  std::string deposit_speeds_file;
  // Output.
  int vtk_every = 0;
  std::string vtk_directory = "lbm_vtk";
  // Restart companion file prefix ("" = restart file name + ".fluid").
  std::string checkpoint_prefix;
  // Checkpoints kept per rank, the newest by step (0: all, as LIGGGHTS keeps every
  // `restart N file.*`); 2 with restart files written in turn (`restart N a b`).
  int checkpoint_keep = 0;
};

// Parses arg[0..narg) (the words after the style name). Throws lbm::InputError with a
// message naming the keyword and its valid range.
PoreOptions parse_pore_options(const std::vector<std::string>& args);

// The keyword reference printed in errors and the doc page.
const char* pore_options_usage();

}  // namespace lbm_pore
