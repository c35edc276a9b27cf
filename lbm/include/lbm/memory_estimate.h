#pragma once
// Memory a lattice or a voxel geometry will take, and the memory this machine has left, so a
// host can refuse a lattice that does not fit (with both figures) before allocating it,
// instead of dying in std::bad_alloc ("terminate called") or under the kernel's OOM killer.
#include <array>
#include <cstddef>
#include <string>

#include "lbm/block_layout.h"
#include "lbm/communicator.h"
#include "lbm/real.h"

namespace lbm {

// Bytes of one rank's FluidSolver on an owned block of `owned` nodes (one ghost layer on every
// side): two population fields of 19 values of `real_bytes` (the solver's f and f_next) and one
// node-type byte per cell, plus the solver's own copy of the whole geometry (one byte per
// voxel of `global`). Wall links and the coupling's sparse lists come on top (a few per cent).
// In double, so a absurd size (1e6^3 nodes) does not overflow.
double lattice_bytes(const std::array<int, 3>& owned, const std::array<int, 3>& global,
                     std::size_t real_bytes = sizeof(Real));

// One byte per voxel (VoxelGeometry).
double geometry_bytes(const std::array<int, 3>& dims);

// Memory this process can still allocate, in bytes: MemAvailable of /proc/meminfo, lowered to
// what the cgroup (a container or batch job limit) leaves when that is smaller; sysconf's
// available pages where /proc is missing; a huge number when nothing can be read.
double available_memory_bytes();

// "12.3 GiB", "512 MiB", "1.5e+06 TiB": for messages.
std::string format_bytes(double bytes);

// Throws InputError "<what> needs <bytes>, more than the <available> of memory available[; <hint>]"
// when `bytes` exceeds available_memory_bytes(). Below 64 MiB it does not ask the system
// (every test builds small geometries).
void check_fits_in_memory(double bytes, const std::string& what, const std::string& hint = "");

// Collective over `comm`: the bytes every rank gives are summed over the ranks on the same
// machine (they share its memory) and checked as above; every rank throws when any machine
// is short (so a host's error on all ranks cannot hang the others), with the figures of the
// machine of this rank or, where this one fits, a message saying another one does not.
void check_fits_in_memory_on_every_machine(double bytes_this_rank, const std::string& what,
                                           const std::string& hint, const Communicator& comm);

}  // namespace lbm
