#pragma once
// fix ID group lbm/pore keyword value ...
// The lattice-Boltzmann fluid inside LIGGGHTS: owns the lattice and the voxel geometry,
// advances the fluid once every n_dem DEM steps on LIGGGHTS's own subdomains, hands the
// hydrodynamic force to the particles, and exposes the paper's diagnostics as a global
// vector. The physics lives in lbm/ and coupling/; this class parses, converts units and
// moves data between LIGGGHTS's arrays and those layers.
#include <memory>
#include <string>
#include <vector>

#include "contact/voxel_surface.h"
#include "coupling/diagnostics/pore_diagnostics.h"
#include "fix.h"
#include "lattice_particles.h"
#include "lbm_pore_options.h"

namespace lbm {
class FluidSolver;
class VoxelGeometry;
class VtkSeriesWriter;
}  // namespace lbm
namespace coupling {
class UnitConversion;
struct LatticeFrame;
class SphereCoupling;
class LubricationCorrection;
}  // namespace coupling

namespace LAMMPS_NS {

class FixLbmPore : public Fix {
 public:
  FixLbmPore(class LAMMPS* lmp, int narg, char** arg);
  ~FixLbmPore() override;
  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void post_force(int vflag) override;
  void end_of_step() override;
  double compute_vector(int index) override;
  void post_run() override;
  void init_list(int id, class NeighList* list) override;
  void write_restart(FILE* fp) override;
  void restart(char* buf) override;

  // Per-atom hydrodynamic load (force, torque) of the last fluid step: it acts on every
  // DEM substep until the next fluid step, so it travels with its atom.
  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  void set_arrays(int i) override;
  void own_slot(int i);  // resets the slot if it belonged to another atom
  int pack_exchange(int i, double* buf) override;
  int unpack_exchange(int nlocal, double* buf) override;
  int pack_restart(int i, double* buf) override;
  void unpack_restart(int nlocal, int nth) override;
  int size_restart(int nlocal) override;
  int maxsize_restart() override;
  // Forward: current ghost velocities for the fluid step. Reverse: loads the fluid put on
  // ghost images go back to their owners.
  int pack_comm(int n, int* list, double* buf, int pbc_flag, int* pbc) override;
  void unpack_comm(int n, int first, double* buf) override;
  int pack_reverse_comm(int n, int first, double* buf) override;
  void unpack_reverse_comm(int n, int* list, double* buf) override;

  // For the voxel wall fix: the geometry (script units: spacing dx, origin of node 0).
  std::shared_ptr<const lbm::VoxelGeometry> shared_geometry() const { return geometry_; }
  const lbm::VoxelGeometry& geometry() const { return *geometry_; }
  const coupling::LatticeFrame& frame() const;

  // Indices of the global vector (1-based in thermo: f_ID[i] = index i-1 here).
  enum Diagnostic {
    kPressureLoss,      // p_in - p_out between the inlet and outlet planes (pressure units)
    kFluidFluxInlet,    // volumetric flux through the inlet plane (volume / time)
    kFluidFluxOutlet,   // ... and the outlet plane
    kParticlesIn,       // particles that crossed the inlet plane downstream (cumulative)
    kParticlesOut,      // particles that crossed the outlet plane (cumulative)
    kDepositedVolume,   // V_dep (volume units)
    kDepositedCount,    // number of deposited particles
    kDepositedLength,   // L_dep = V_dep / (pi D^2 / 4)
    kMaxFluidSpeed,     // largest fluid speed (velocity units)
    kLatticeMach,       // largest speed / lattice speed of sound
    kFluidSteps,        // fluid steps done
    kParticlesInVolume,   // particle volume that crossed the inlet plane (cumulative)
    kParticlesOutVolume,  // ... and the outlet plane
    kHydroForceX,       // total hydrodynamic force on the group along the flow (force units)
    kMaxParticleShift,  // largest particle displacement per fluid step, in cells
    kNumDiagnostics
  };

 private:
  void build_geometry();
  void build_lattice();
  void find_gravity();
  void fluid_step();
  void gather_particles(bool advance);
  void store_loads();
  void add_lubrication(double** f);
  void find_walls();
  void resume_mapping();
  void update_particle_diagnostics();
  void update_diagnostics();
  void print_setup() const;
  void check_fluid_state();
  void check_particle_speed();
  long long global_particle_count() const;

  lbm_pore::PoreOptions options_;
  std::unique_ptr<coupling::UnitConversion> units_;
  std::unique_ptr<coupling::LatticeFrame> frame_;
  std::shared_ptr<const lbm::VoxelGeometry> geometry_;
  std::unique_ptr<contact::VoxelSurface> surface_;  // wall distances for lubrication, bonds
  std::unique_ptr<lbm::FluidSolver> solver_;
  std::unique_ptr<coupling::SphereCoupling> coupling_;
  std::unique_ptr<coupling::LubricationCorrection> lubrication_;
  std::unique_ptr<lbm::VtkSeriesWriter> vtk_;
  lbm_pore::LatticeParticles particles_;
  std::vector<int> view_of_atom_;                   // atom index -> view entry, -1 outside the group
  std::vector<double*> wall_velocity_rows_;         // rows of loads_ at the fluid-seen velocity
  std::vector<contact::SurfacePoint> wall_points_;  // scratch of the wall searches
  std::vector<char> bonded_;                        // scratch of the deposit count
  class NeighList* list_ = nullptr;
  double** loads_ = nullptr;       // per atom, layout in fix_lbm_pore_internal.h (script units)
  int nmax_ = 0;
  double gravity_[3] = {0.0, 0.0, 0.0};  // fix gravity's acceleration, 0 without one
  bool has_gravity_ = false;
  double pore_diameter_lattice_ = 0.0;
  coupling::PoreRegion pore_;
  std::unique_ptr<coupling::PlaneCrossingCounter> inlet_counter_, outlet_counter_;
  double inlet_x_ = 0.0, outlet_x_ = 0.0;  // counting planes, lattice units
  std::vector<double> diagnostics_;
  std::string resume_checkpoint_;  // set by restart(): read once the lattice exists
  bool fluid_diagnostics_stale_ = true;  // fluid fields changed since update_diagnostics()
  bool resumed_ = false;           // the mapping must be rebuilt from the checkpoint
  long long fluid_steps_ = 0;
  // Wall-clock seconds: fluid step with the coupling stages, lubrication, diagnostics.
  double time_fluid_ = 0.0, time_lubrication_ = 0.0, time_diagnostics_ = 0.0;
  double run_start_ = 0.0;
  long long run_fluid_steps_ = 0;
};

}  // namespace LAMMPS_NS
