#include "lbm/decomposition.h"

#include <string>

#include "lbm/input_error.h"

namespace lbm {

namespace {
std::string axis_name(int axis) { return std::string(1, "xyz"[axis]); }
}  // namespace

Decomposition Decomposition::serial(const Box& global, std::array<bool, 3> periodic) {
  Decomposition d;
  d.global = global;
  d.owned = global;
  d.periodic = periodic;
  // A periodic axis owned by one rank wraps onto itself; HaloExchange then copies within
  // the block instead of sending a message.
  for (int a = 0; a < 3; ++a)
    d.neighbor[a] = periodic[a] ? std::array<int, 2>{0, 0} : std::array<int, 2>{-1, -1};
  return d;
}

Decomposition Decomposition::grid(const Box& global, std::array<bool, 3> periodic,
                                  std::array<int, 3> procs, const Communicator& comm) {
  long long product = 1;
  for (int a = 0; a < 3; ++a) {
    if (procs[a] < 1)
      throw InputError("decomposition: processors along " + axis_name(a) + " = " +
                       std::to_string(procs[a]) + ", must be >= 1");
    if (global.size(a) < 1)
      throw InputError("decomposition: the global lattice has no node along " + axis_name(a));
    // floor(n*p/P) cuts leave every box non-empty exactly when n >= P.
    if (procs[a] > global.size(a))
      throw InputError("decomposition: " + std::to_string(procs[a]) + " processors along " +
                       axis_name(a) + " but only " + std::to_string(global.size(a)) +
                       " lattice nodes: some rank would own no node; use fewer processors "
                       "along " +
                       axis_name(a));
    product *= procs[a];
  }
  if (product != comm.size())
    throw InputError("decomposition: processor grid " + std::to_string(procs[0]) + "x" +
                     std::to_string(procs[1]) + "x" + std::to_string(procs[2]) + " = " +
                     std::to_string(product) + " ranks, but the communicator has " +
                     std::to_string(comm.size()));

  Decomposition d;
  d.global = global;
  d.periodic = periodic;
  d.comm = comm;
  const int rank = comm.rank();
  // Rank order x fastest: rank = px + procs_x * (py + procs_y * pz).
  const std::array<int, 3> stride{1, procs[0], procs[0] * procs[1]};
  const std::array<int, 3> pos{rank % procs[0], (rank / procs[0]) % procs[1],
                               rank / (procs[0] * procs[1])};
  for (int a = 0; a < 3; ++a) {
    const long long n = global.size(a);
    d.owned.lo[a] = global.lo[a] + int(n * pos[a] / procs[a]);
    d.owned.hi[a] = global.lo[a] + int(n * (pos[a] + 1) / procs[a]);
    for (int side = 0; side < 2; ++side) {
      int p = pos[a] + (side == 0 ? -1 : 1);
      if (p < 0 || p >= procs[a]) {
        if (!periodic[a]) {
          d.neighbor[a][side] = -1;
          continue;
        }
        p = (p + procs[a]) % procs[a];
      }
      d.neighbor[a][side] = rank + (p - pos[a]) * stride[a];
    }
  }
  return d;
}

}  // namespace lbm
