#pragma once
// fix ID group lbm/pore keyword value ...
// The lattice-Boltzmann fluid inside LIGGGHTS: owns the lattice and the voxel geometry,
// advances the fluid once every n_dem DEM steps on LIGGGHTS's own subdomains, hands the
// hydrodynamic load to the particles, and exposes the paper's diagnostics as a global
// vector. The physics lives in lbm/ and coupling/ (the step pipeline and its policy, the
// substep load model, lubrication, the pore monitor and the guards, the units); this class
// parses, moves data between LIGGGHTS's arrays and those objects (through the plugin's
// LIGGGHTS-free helpers: AtomStates, LatticeParticles, pore_scene_setup.h) and calls them.
#include <memory>
#include <optional>
#include <string>
#include <vector>

#include "atom_states.h"
#include "contact/voxel_surface.h"
#include "coupling/diagnostics/pore_monitor.h"
#include "coupling/diagnostics/run_guards.h"
#include "coupling/diagnostics/run_timer.h"
#include "coupling/force/substep_load.h"
#include "coupling/lubrication/lubrication_kernel.h"
#include "fix.h"
#include "lattice_particles.h"
#include "lbm_pore_options.h"

namespace lbm {
class CappedVelocityDrive;
class FluidSolver;
class VoxelGeometry;
class VtkSeriesWriter;
}  // namespace lbm
namespace coupling {
class UnitConversion;
struct LatticeFrame;
class SphereCoupling;
}  // namespace coupling

namespace LAMMPS_NS {

class FixLbmPore : public Fix {
 public:
  FixLbmPore(class LAMMPS* lmp, int narg, char** arg);
  ~FixLbmPore() override;
  int setmask() override;
  void init() override;
  void setup(int vflag) override;
  void post_integrate() override;
  void post_force(int vflag) override;
  void end_of_step() override;
  // f_ID[1..kCount]: the pore monitor's values (coupling::PoreMonitor::Quantity); f_ID[kCount+1]
  // (kInletVelocityIndex): the inlet velocity of the drive (velocity units).
  static constexpr int kInletVelocityIndex = coupling::PoreMonitor::kCount;
  double compute_vector(int index) override;
  double compute_array(int row, int column) override;
  void post_run() override;
  void init_list(int id, class NeighList* list) override;
  void write_restart(FILE* fp) override;
  void restart(char* buf) override;

  // Per-atom state (lbm_pore::AtomCouplingState): it travels with its atom.
  void grow_arrays(int nmax) override;
  void copy_arrays(int i, int j, int delflag) override;
  void set_arrays(int i) override;
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

 private:
  // Fluid steps between NaN/runaway scans of the lattice: a full scan costs a sizeable part
  // of a step, and a blow-up takes many steps to reach the particles.
  static constexpr int kCheckEvery = 100;
  // Rows of the global array of burst records (f_ID[i][j]); later bursts are still written
  // to the burst file and counted.
  static constexpr int kBurstRows = 1000;

  void build_geometry();
  void build_lattice(std::unique_ptr<coupling::UnitConversion> units);
  void fluid_step();
  void gather_particles(bool advance);
  void store_loads(bool coupled);
  void collect_group_pairs();
  void find_walls();
  void record_particles();
  void start_monitor();
  bool at_fluid_step() const;
  void record_fluid_step();
  void check_fluid_state();
  void check_particle_speed();
  void stop_everywhere(const coupling::GuardVerdict& verdict, const char* what);
  lbm_pore::AtomArrays atom_arrays() const;  // the atom arrays as they are (script units)

  lbm_pore::PoreOptions options_;
  std::unique_ptr<coupling::UnitConversion> units_;
  std::unique_ptr<coupling::LatticeFrame> frame_;
  std::shared_ptr<const lbm::VoxelGeometry> geometry_;
  std::unique_ptr<contact::VoxelSurface> surface_;  // wall distances for lubrication, bonds
  std::unique_ptr<lbm::FluidSolver> solver_;
  std::unique_ptr<lbm::CappedVelocityDrive> capped_drive_;  // 'max_pressure_loss'; null without
  std::unique_ptr<coupling::SphereCoupling> coupling_;
  std::unique_ptr<coupling::SubstepLoadModel> load_model_;
  std::unique_ptr<coupling::LubricationKernel> lubrication_;
  coupling::PoreMonitorSetup monitor_setup_;  // from the geometry, before the lattice exists
  std::unique_ptr<coupling::PoreMonitor> monitor_;
  std::vector<double> restored_state_;        // the monitor's state from a restart file
  std::vector<double> restored_drive_state_;  // the capped drive's (empty: none kept)
  std::unique_ptr<lbm::VtkSeriesWriter> vtk_;
  lbm_pore::LatticeParticles particles_;
  lbm_pore::AtomStates states_;  // per atom (owned and ghosts)
  // Per atom, the per-atom output: the hydrodynamic force of the last substep (the stored
  // load with its velocity correction, plus lubrication), script units.
  double** hydrodynamic_force_ = nullptr;
  std::vector<coupling::ParticlePair> pairs_;       // the group's pairs of the neighbour list
  long long pairs_step_ = -1;                       // the neighbour build pairs_ is from (step)
  std::vector<contact::SurfacePoint> wall_points_;  // scratch of the wall searches
  std::vector<char> bonded_atoms_, bonded_, on_wall_;  // scratch of the deposit count
  class NeighList* list_ = nullptr;
  std::string resume_checkpoint_;  // set by restart(): read once the lattice exists
  bool resumed_ = false;           // the mapping must be rebuilt from the checkpoint
  bool fast_flow_warned_ = false;  // coupling::fast_flow_warning said (once per run)
  long long fluid_steps_ = 0;
  coupling::RunTimer timer_;  // where the time of a run went
};

}  // namespace LAMMPS_NS
