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

#include "fix.h"
#include "lbm_pore_options.h"

namespace lbm {
class FluidSolver;
class VoxelGeometry;
class VtkSeriesWriter;
}  // namespace lbm
namespace coupling {
class UnitConversion;
struct LatticeFrame;
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
  void write_restart(FILE* fp) override;
  void restart(char* buf) override;

  // For the voxel wall fix: the geometry in lattice units and where it sits.
  const lbm::VoxelGeometry& geometry() const;
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
    kNumDiagnostics
  };

 private:
  void build_lattice();
  void fluid_step();
  void update_diagnostics();
  void print_setup() const;
  void check_fluid_state();

  lbm_pore::PoreOptions options_;
  std::unique_ptr<coupling::UnitConversion> units_;
  std::unique_ptr<coupling::LatticeFrame> frame_;
  std::unique_ptr<lbm::VoxelGeometry> geometry_;
  std::unique_ptr<lbm::FluidSolver> solver_;
  std::unique_ptr<lbm::VtkSeriesWriter> vtk_;
  double pore_diameter_lattice_ = 0.0;
  int inlet_plane_ = 0, outlet_plane_ = 0;
  std::vector<double> diagnostics_;
  std::string resume_checkpoint_;  // set by restart(): read once the lattice exists
  long long fluid_steps_ = 0;
};

}  // namespace LAMMPS_NS
