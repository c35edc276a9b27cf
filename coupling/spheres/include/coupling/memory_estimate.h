#pragma once
// Memory SphereCoupling's per-node arrays take, so a host can print it beside the fluid's
// (lbm::FluidSolver::bytes_per_node) and a reader sees what a lattice node costs in a
// coupled run. Kept beside the coupling, whose members it counts, not in a host.

namespace coupling {

// Bytes per lattice node, at most, with `threads` OpenMP threads (below 1: one): the sphere
// mapping's owner and shell per cell (two ints), one moving-wall moment cache table per
// thread (a stamp and the node's moments), and, where a rank or periodic neighbour exists,
// the refill's ghost densities (a double) and the ghost nodes' moments (four doubles).
double coupling_bytes_per_node(int threads);

}  // namespace coupling
