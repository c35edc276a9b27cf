#pragma once
#include <string>

#include "lbm/fluid_solver.h"

namespace lbm {

// The fluid state a resumed run needs: this rank's populations (owned nodes), node types
// and the time step, in a binary file per rank (`<path>.<rank>`). The header records the
// global and owned boxes and the storage precision, so a file is only read back into the
// same lattice and precision; anything else is an InputError naming the file and the
// mismatch. A run on another decomposition (another number of ranks, another processor
// grid) reads the part of every rank's file that it owns. Moving-particle nodes are stored as they are; the coupling rebuilds its
// own state from the particles.
void write_checkpoint(const FluidSolver& solver, const std::string& path);
void read_checkpoint(FluidSolver& solver, const std::string& path);

// Deletes this rank's older checkpoints of a run: of the files `<prefix>.<step>.<rank>` in
// prefix's folder, all but the `keep` with the highest steps (keep <= 0: none deleted). A
// host writing restart files in turn (restart.a, restart.b) keeps 2: the two checkpoints
// its restart files name, even when a kill destroys the restart file being written. Files
// of other ranks, other prefixes and unfinished `.partial` files are left alone. Returns
// how many files it deleted.
int prune_checkpoints(const std::string& prefix, int rank, int keep);

// After read_checkpoint: the checkpoint holds the node types of the step it was written at,
// with zeros inside the particles, while a new mapping starts empty. Turns every moving node
// into fluid at rest (equilibrium at rho = 1, u = 0), so the host maps the particles afresh;
// written at a fluid step, the same nodes are covered again and the continuation is exact.
void release_moving_nodes(FluidSolver& solver);

}  // namespace lbm
