#pragma once
// fix lbm/pore's per-atom states (AtomCouplingState) in LIGGGHTS's atom slots, owned atoms
// first and then ghosts, and the fix's loops over them: the velocity the fluid sees, the
// nearest walls, the substep loads and a fluid step's loads, and the flat buffers LIGGGHTS's
// communication moves them in. No LIGGGHTS dependency: the fix passes its atom arrays.
#include <vector>

#include "atom_coupling_state.h"
#include "contact/voxel_surface.h"
#include "coupling/force/momentum_exchange.h"
#include "coupling/force/substep_load.h"
#include "coupling/lubrication/lubrication_kernel.h"
#include "coupling/unit_conversion.h"
#include "lattice_particles.h"

namespace lbm_pore {

class AtomStates {
 public:
  // Doubles per atom of the forward communication (the velocity the fluid sees, the angular
  // velocity) and of the reverse one (a fluid step's loads, AtomCouplingState::kSummed).
  static constexpr int kForward = 6;
  static constexpr int kReverse = AtomCouplingState::kSummed;

  int size() const { return static_cast<int>(states_.size()); }
  void resize(int nmax) { states_.resize(static_cast<std::size_t>(nmax)); }
  AtomCouplingState& operator[](int i) { return states_[static_cast<std::size_t>(i)]; }
  const AtomCouplingState& operator[](int i) const { return states_[static_cast<std::size_t>(i)]; }
  // A new atom in slot i (tag its atom's tag) starts with no load and no previous position:
  // the slot may hold a former atom's values.
  void reset(int i, double tag);
  // The state of the atom in slot i, reset first where the slot held another atom: not
  // every LIGGGHTS insertion calls reset (set_arrays), so the slot records its atom's tag.
  AtomCouplingState& own(int i, double tag);

  // At a fluid step, for each owned atom: the velocity the fluid sees it move with
  // (coupling::StepMotion; minimum_image(double d[3]) wraps a displacement through periodic
  // faces). `advance` is false at a run's start, where no step has passed.
  template <class MinimumImage>
  void step_motion(const AtomArrays& atoms, double dt_fluid, bool advance, MinimumImage&& minimum_image) {
    for (int i = 0; i < atoms.nlocal; ++i) {
      AtomCouplingState& s = own(i, atoms.tag[i]);
      s.fluid_velocity = s.motion.step(atoms.x[i], atoms.v[i], dt_fluid, advance, minimum_image);
    }
  }
  // `atoms` with the velocity the fluid sees in place of v, for LatticeParticles::gather
  // (owned atoms and ghosts: after the forward communication). Valid until the next call.
  AtomArrays seen_by_fluid(const AtomArrays& atoms);

  // The nearest wall of each owned atom of the group within its radius + `reach` (host
  // units), followed along its normal until the next search; other atoms have none.
  void find_walls(const AtomArrays& atoms, const contact::VoxelSurface& surface, double reach,
                  std::vector<contact::SurfacePoint>& scratch);

  // Every DEM substep, each owned atom of the group: the substep load model's hydrodynamic
  // force on f and into `hydrodynamic` (the per-atom output; zero for the other atoms), its
  // torque where `torque` is given, its buoyancy where `buoyancy`.
  void add_substep_loads(const coupling::SubstepLoadModel& model, const AtomArrays& atoms, double** f,
                         double** torque, bool buoyancy, double** hydrodynamic);

  // Then, with lubrication: the kernel's pair forces (`pairs`, of the group) and wall forces
  // (each owned atom of the group from its followed nearest wall) on f, and what they added
  // into `hydrodynamic` too.
  void add_lubrication(const coupling::LubricationKernel& kernel, const AtomArrays& atoms,
                       const std::vector<coupling::ParticlePair>& pairs, double** f, double** hydrodynamic);

  // For the pore monitor at a fluid step, per particle p of `particles`: whether it touches
  // the wall (on_wall[p], owned particles; from the followed nearest walls where
  // `walls_followed`, else by a search of `surface`: coupling::touches_wall) and whether it
  // is bonded (bonded[p]: its atom has a cohesive bond, bonded_atoms per atom, or it touches
  // the wall), and the fluid's force along the flow (x) on each owned particle
  // (fluid_along_flow[p], 0 for the others). Returns its sum over the owned particles.
  double mark_deposits(const LatticeParticles& particles, const AtomArrays& atoms,
                       const std::vector<char>& bonded_atoms, bool walls_followed,
                       const contact::VoxelSurface& surface, std::vector<contact::SurfacePoint>& scratch,
                       std::vector<char>& bonded, std::vector<char>& on_wall,
                       std::vector<double>& fluid_along_flow) const;

  // A fluid step's loads in the three moves of SubstepLoadModel: every slot starts the step;
  // the coupling's loads on the particles of `particles` (lattice units, indexed like its
  // view) go to their atoms' slots in host units; the host sums the ghosts' shares onto
  // their owners (reverse communication) and each owned atom finishes the step with its
  // velocity and mass (rmass null: not known).
  void start_fluid_step(int nlocal, int ntotal);
  void store_loads(const LatticeParticles& particles, const coupling::HydrodynamicLoads& loads,
                   const coupling::UnitConversion& units);
  void finish_fluid_step(const coupling::SubstepLoadModel& model, const AtomArrays& atoms, const double* rmass);

  // Forward communication, owner -> ghosts (omega null: zeros sent, nothing received), and
  // reverse, ghosts' loads summed onto their owners; LIGGGHTS's buffer layouts. The packs
  // return the doubles per atom.
  int pack_forward(int n, const int* list, double* const* omega, double* buf) const;
  void unpack_forward(int n, int first, double* const* omega, const double* buf);
  int pack_reverse(int n, int first, double* buf) const;
  void unpack_reverse(int n, const int* list, const double* buf);

  // Exchange of an atom between ranks: its state alone (AtomCouplingState::kDoubles).
  int pack_exchange(int i, double* buf) const;
  int unpack_exchange(int i, const double* buf);

  // Restart files, per atom: the entry's size (kRestart) first, then the state. An entry of
  // the previous layout (AtomCouplingState::kDoubles1) reads too; unpack_restart returns
  // false, and reads nothing, for any other size.
  static constexpr int kRestart = AtomCouplingState::kDoubles + 1;
  int pack_restart(int i, double* buf) const;
  bool unpack_restart(int i, const double* entry);

 private:
  std::vector<AtomCouplingState> states_;
  std::vector<double*> fluid_velocity_rows_;  // rows of states_ for seen_by_fluid
  std::vector<double> force_before_;          // scratch: f before the lubrication
};

}  // namespace lbm_pore
