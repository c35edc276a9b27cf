#pragma once
// A velocity inlet whose pressure loss has a ceiling: the drive of the paper's imposed
// pressure runs on a pore that fills first (doc/paper.md, pvpflux). The inlet imposes u_max
// while the pressure loss p_in - p_out stays below P_max; once the loss reaches P_max the
// inlet velocity is lowered to hold it there, and it rises again (at most to u_max) when the
// pore opens. Neither plain drive does: P_max through the empty pore drives it far faster
// than u_max (at the paper's size 11-54 times, beyond the lattice's stable speed), and a
// clogging pore at u_max builds any loss.
//
// The inlet stays a velocity inlet throughout. A density inlet at P_max (FlowDrive::
// kPressureLoss) would hold the loss exactly, but with density faces at both ends a
// cross-section without walls (the pore scene's inlet and outlet regions, periodic across the
// flow) keeps a staggered mode no viscosity damps: node momenta alternating plane to plane
// and step to step, 1.5 times the mean flux at the planes on a small pore scene
// (tests/lbm/test_capped_drive.cpp); a velocity face fixes the node's momentum and removes it.
//
// The velocity of the next step balances the mass the box loses through the outlet and
// moves the loss toward P_max over kRelaxationTransits acoustic transits of the box:
//   rho_in u A = M_out + C (P_max - P) / T,  u clamped to [0, u_max],
// M_out the outlet's outflow of a step averaged over one transit (particles crossing the
// outlet make it noisy), C = N_fluid / c_s^2 the mass a unit of lattice pressure puts in the
// box, T = kRelaxationTransits x (transit N_axis / c_s). In steady flow M_out is the inflow
// and the loss is P_max exactly; below P_max the balance asks more than u_max and the clamp
// holds u_max, the plain velocity inlet. As a deposit grows (slowly: M_out is the inflow) that
// lasts until the loss reaches P_max. While a box fills from rest (M_out below the inflow) it
// lasts while C (P_max - P) / T exceeds the difference: C / (T rho A) is 0.33 on the paper's
// scene, so at u_lattice 0.0025 until the loss is within 0.02 P_out of P_max; where u_max is
// large against it (u_lattice 0.02 on the smoke sizes' box of 50 cells) a start from rest
// lowers the velocity early, and it comes back over several T.
#include <vector>

#include "lbm/fluid_solver.h"

namespace lbm {

// The faces of the last step (collective over the solver's communicator): the pressure loss
// p_in - p_out between them (lbm::pressure_loss), the inlet face's mean velocity along the
// drive axis (its mass flux over the mass its nodes' momentum carries: u on a velocity inlet),
// the outlet's outflow of the step (mass, > 0 leaving) and the inlet nodes' density sum.
// The velocity, outflow and sum are 0 where the faces were not set by a step since the last
// reset (a checkpoint read).
struct DriveFaces {
  double pressure_loss = 0.0;
  double inlet_velocity = 0.0;
  double outflow = 0.0;
  double inlet_carried_mass = 0.0;  // sum of rho (rho0 with He & Luo's equilibrium) over the inlet's nodes
};
DriveFaces read_drive_faces(const FluidSolver& solver);

class CappedVelocityDrive {
 public:
  // The relaxation time of the loss toward P_max, in acoustic transits of the box: long
  // against the transit, over which the outflow answers a change of the inflow.
  static constexpr double kRelaxationTransits = 4.0;

  // velocity_drive: a kInletVelocity drive, u_max its inlet velocity (> 0); max_pressure_loss:
  // P_max, lattice pressure units (> 0, within a pressure drive's limit). Throws InputError,
  // naming the limit, on anything else. Starts at u_max.
  CappedVelocityDrive(const FluidSolver& solver, const FlowDrive& velocity_drive, double max_pressure_loss);

  // After a step (collective): reads the faces, sets the solver's inlet velocity for the next
  // step. Returns the faces read.
  DriveFaces update(FluidSolver& solver);

  double inlet_velocity() const { return inlet_velocity_; }  // imposed in the next step
  bool holds_pressure() const { return inlet_velocity_ < max_inlet_velocity(); }
  double max_inlet_velocity() const { return velocity_drive_.inlet_velocity; }
  double max_pressure_loss() const { return max_pressure_loss_; }

  // Everything a restart needs to continue as if uninterrupted, and back (set_state gives the
  // solver its inlet velocity). Throws std::invalid_argument on a vector of another size.
  std::vector<double> state() const;
  void set_state(const std::vector<double>& state, FluidSolver& solver);

 private:
  FlowDrive velocity_drive_;
  double max_pressure_loss_;
  double compliance_;         // C: fluid nodes / c_s^2 (mass per lattice pressure)
  double transit_steps_;      // nodes along the drive axis / c_s
  double inlet_velocity_;
  double mean_outflow_ = 0.0;  // M_out (a box at rest loses nothing)
  void impose(FluidSolver& solver);
};

// The inlet velocity of a drive (lattice units): the capped drive's for the next step (where
// `capped` is given), a velocity inlet's, or a density inlet's mean over its face in the last
// step (read_drive_faces: collective).
double drive_inlet_velocity(const FluidSolver& solver, const CappedVelocityDrive* capped);

}  // namespace lbm
