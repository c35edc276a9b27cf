#pragma once
// The hydrodynamic load between two fluid steps (paper Sec. II.D, "Coupling of Fluid and
// Particles"): the momentum-exchange force and torque of a fluid step (Eq. 2) act on each of
// the N_DEM DEM substeps until the next fluid step. Two additions make that explicit
// coupling usable:
//  - the fluid resists a velocity change within the substeps at once (Nguyen & Ladd 2002,
//    implicit particle update): F(v) = F_step - C (v - v_step), with C the force-velocity
//    coefficient estimated from the last two fluid steps (the secant -dF.dv / |dv|^2),
//    bounded below by the moving-wall term of the links and above by a few particle masses
//    per fluid step. Near contact the fluid in the gap makes C several times the link term,
//    and without it the coupling oscillates with period two fluid steps and grows
//    (C dt / m > 2 at rho_p / rho_f = 2.3);
//  - buoyancy: the fluid is driven through its boundaries and carries no body force, so its
//    pressure holds no hydrostatic part; with gravity g each particle gets -rho_f V g, which
//    makes the net weight (rho_p - rho_f) V g.
// Units are the host's (any consistent system): the model only combines what it is given.
#include "coupling/particle_view.h"

namespace coupling {

// What the model remembers of one particle between fluid steps.
struct SubstepLoadState {
  Vec3 force{0.0, 0.0, 0.0};   // of the last fluid step, summed over the particle's images
  Vec3 torque{0.0, 0.0, 0.0};  // about its centre, likewise
  double coefficient = 0.0;    // C: link term when stored, the secant estimate once finished
  Vec3 step_velocity{0.0, 0.0, 0.0};  // the particle's velocity at the last fluid step
  Vec3 previous_force{0.0, 0.0, 0.0};     // ... and the force and velocity of the step before,
  Vec3 previous_velocity{0.0, 0.0, 0.0};  // from which the secant is taken
};

struct SubstepLoadParameters {
  double dt_fluid = 1.0;         // fluid time step: C <= max_coefficient_masses m / dt_fluid
  // C is kept below this many particle masses per fluid step: enough to stabilise the stiff
  // near-contact mode (C dt / m up to ~4 measured) without freezing a particle's response.
  double max_coefficient_masses = 4.0;
  // The part of a fluid step's load each substep applies: 1, the load held over the N_DEM
  // substeps (the default: over a fluid step the particle takes the momentum the fluid gave
  // it), or 1 / N_DEM, the paper's "the DEM takes into account a fraction of the
  // hydrodynamic force in each time step" read literally (the fluid's push N_DEM times
  // weaker). Buoyancy is not the fluid step's and is applied whole either way.
  double share = 1.0;
  bool buoyancy = false;         // a gravity field is present
  double fluid_density = 1.0;
  Vec3 gravity{0.0, 0.0, 0.0};
};

// The load on one particle at one DEM substep. Kept as parts so a host adds each as it is:
// the hydrodynamic force, buoyancy (zero without gravity) and the torque.
struct SubstepLoad {
  Vec3 hydrodynamic{0.0, 0.0, 0.0};
  Vec3 buoyancy{0.0, 0.0, 0.0};
  Vec3 torque{0.0, 0.0, 0.0};
};

class SubstepLoadModel {
 public:
  explicit SubstepLoadModel(const SubstepLoadParameters& parameters) : parameters_(parameters) {}

  // share (F_step - C (v - v_step)), -rho_f V g, and share times the step's torque, for a
  // particle of velocity v.
  SubstepLoad at_substep(const SubstepLoadState& state, const Vec3& velocity, double radius) const;

  // A fluid step in three moves, because the host sums the images of a particle in between:
  //  1. start_fluid_step on every slot (owned particles keep the step that ends as the
  //     previous one; every slot's force, torque, C and step velocity are cleared);
  //  2. the host adds the new force, torque and link coefficient into the slots and sums
  //     ghost images onto their owners;
  //  3. finish_fluid_step on each owned particle with its velocity and mass (mass <= 0: not
  //     known, C stays the link term).
  static void start_fluid_step(SubstepLoadState& state, bool owned);
  void finish_fluid_step(SubstepLoadState& state, const Vec3& velocity, double mass) const;

  const SubstepLoadParameters& parameters() const { return parameters_; }

 private:
  SubstepLoadParameters parameters_;
};

}  // namespace coupling
