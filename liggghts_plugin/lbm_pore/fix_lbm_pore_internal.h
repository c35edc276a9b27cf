#pragma once
// Shared by fix lbm/pore's source files (stepping, guards and diagnostics, per-atom data):
// the layout of its per-atom array and the limits of its guards.
#include <mpi.h>
namespace lbm_pore::slots {

// Per atom: force (3), torque (3), velocity coefficient C (1) of the last fluid step, summed
// over ghost images; then the atom's own velocity at that step (3), and the force and
// velocity of the step before (3 + 3), from which C is estimated.
constexpr int kSummedPerAtom = 7;
constexpr int kCoefficient = 6;
constexpr int kStepVelocity = 7;
constexpr int kPreviousForce = 10;
constexpr int kPreviousVelocity = 13;
constexpr int kPreviousPosition = 16;  // position at the last fluid step (own atoms)
constexpr int kHasPrevious = 19;       // 1 once kPreviousPosition holds a position
constexpr int kWallVelocity = 20;      // velocity the fluid sees (owned and ghosts)
constexpr int kTag = 23;               // the atom the slot belongs to
constexpr int kWallNormal = 24;        // nearest wall at the last fluid step: unit normal (3),
constexpr int kWallDistance = 27;      // centre-to-surface distance then,
constexpr int kWallKnown = 28;         // 1 when a wall was within reach
constexpr int kLoadsPerAtom = 29;

}  // namespace lbm_pore::slots

namespace lbm_pore::limits {

// Lattice speeds above this are refused (drive) or stop the run (during it): the scheme
// is accurate only well below the lattice speed of sound c_s = 1/sqrt(3).
constexpr double kMaxLatticeSpeed = 0.3;
constexpr double kSoundSpeed = 0.5773502691896258;
// A particle may move at most this many cells per fluid step: the mapping uncovers at most
// one layer of nodes per step, and the refill assumes so (DESIGN.md, stability guards).
constexpr double kMaxShiftPerFluidStep = 0.5;
// C is kept below this many particle masses per fluid step: enough to stabilise the stiff
// near-contact mode (C dt / m up to ~4 measured), without freezing a particle's response.
constexpr double kMaxCoefficientMasses = 4.0;
// Deposited particles are "at zero or very low velocity, such that moving flocks are not
// counted" (paper Sec. III): slower than this fraction of the inlet velocity. Flocks move with
// the flow, at or above the inlet velocity; particles in a clog creep far slower.
constexpr double kDepositSpeedFraction = 0.1;
constexpr int kCheckEvery = 100;  // fluid steps between NaN/runaway scans of the lattice


inline double now() { return MPI_Wtime(); }

}  // namespace lbm_pore::limits
