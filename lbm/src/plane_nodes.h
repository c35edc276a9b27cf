#pragma once
// The fluid nodes of one lattice plane, visited in a fixed order, with a hook that runs a
// few nodes ahead. The open faces and the plane diagnostics (pressure, flux) read every
// node of an x-normal plane right after the stream-collide kernel has streamed the
// populations to memory; on such a plane each population of each node is a cache line of
// its own, 19 lines a node, and the hook asks for the lines of the node kAhead places
// further along the row while this one is computed (prefetch_node, prefetch_pulled).
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/d3q19.h"
#include "lbm/node_type.h"
#include "lbm/population_field.h"
#include "lbm/thread_team.h"

namespace lbm::detail {

constexpr int kPlaneAhead = 4;

// visit(cell) for every fluid node of rows [first_row, last_row) of local plane `plane`
// normal to `axis`: a row runs along the first tangential axis, rows along the second;
// ahead(cell) first for the node kPlaneAhead places further along the row. A visit that
// takes two arguments gets the node's position in the plane too, row * row length + place
// in the row (a slot of its own in a buffer of the plane's size).
template <typename Visit, typename Ahead>
void for_plane_rows(const BlockLayout& layout, const std::vector<std::uint8_t>& node_type,
                    int axis, int plane, int first_row, int last_row, Visit& visit, Ahead& ahead) {
  const int t1 = (axis + 1) % 3, t2 = (axis + 2) % 3;  // tangential axes
  int ijk[3] = {0, 0, 0};
  ijk[axis] = plane;
  const std::size_t origin = layout.cell(ijk[0], ijk[1], ijk[2]);
  const std::ptrdiff_t step1 = layout.offset(t1 == 0, t1 == 1, t1 == 2);
  const std::ptrdiff_t step2 = layout.offset(t2 == 0, t2 == 1, t2 == 2);
  const int n1 = layout.size(t1);
  for (int s2 = first_row; s2 < last_row; ++s2)
    for (int s1 = 0; s1 < n1; ++s1) {
      const std::size_t cell = origin + s2 * step2 + s1 * step1;
      if (s1 + kPlaneAhead < n1) ahead(cell + kPlaneAhead * step1);
      if (node_type[cell] != kFluid) continue;
      if constexpr (std::is_invocable_v<Visit&, std::size_t, std::size_t>)
        visit(cell, std::size_t(s2) * std::size_t(n1) + std::size_t(s1));
      else
        visit(cell);
    }
}

// Every fluid node of the plane, the first tangential axis innermost (sums over a plane add
// in this order).
template <typename Visit, typename Ahead>
void for_plane_fluid_nodes(const BlockLayout& layout, const std::vector<std::uint8_t>& node_type,
                           int axis, int plane, Visit visit, Ahead ahead) {
  for_plane_rows(layout, node_type, axis, plane, 0, layout.size((axis + 2) % 3), visit, ahead);
}

// The same split over the OpenMP threads by rows, for a visit that reads and writes only
// slots of its own node (then the order of the visits changes no bit). Planes of fewer than
// kMinParallelPlaneNodes nodes stay on one thread.
constexpr int kMinParallelPlaneNodes = 512;
template <typename Visit, typename Ahead>
void for_plane_fluid_nodes_in_parallel(const BlockLayout& layout,
                                       const std::vector<std::uint8_t>& node_type, int axis,
                                       int plane, Visit visit, Ahead ahead) {
  const int rows = layout.size((axis + 2) % 3);
  const bool split = rows * layout.size((axis + 1) % 3) >= kMinParallelPlaneNodes;
#pragma omp parallel if (split)
  {
    const auto [t, nt] = lbm::team_member();
    for_plane_rows(layout, node_type, axis, plane, rows * t / nt, rows * (t + 1) / nt, visit, ahead);
  }
}

// The 19 populations of `cell`.
inline void prefetch_node(const PopulationField& f, std::size_t cell) {
  for (int q = 0; q < D3Q19::Q; ++q) __builtin_prefetch(f.q(q) + cell);
}

// The 19 populations `cell` pulls, f_q(cell - c_q), for writing (the open faces write five).
inline void prefetch_pulled(const PopulationField& f, std::size_t cell, const std::ptrdiff_t* off) {
  for (int q = 0; q < D3Q19::Q; ++q) __builtin_prefetch(f.q(q) + cell - off[q], 1);
}

}  // namespace lbm::detail
