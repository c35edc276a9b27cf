#pragma once
// The loops every moving-wall scheme runs over its links (apply, declared in
// lbm/moving_wall/moving_wall_scheme.h, and sweep, in link_sweep.h); each scheme's source
// file instantiates them, so the per-link formula is inlined and no link branches on the
// scheme.

#include <type_traits>

#include "lbm/moving_wall/link_boundary.h"
#include "lbm/moving_wall/link_mass.h"
#include "lbm/moving_wall/link_sweep.h"
#include "lbm/moving_wall/moving_wall_scheme.h"
#include "lbm/thread_team.h"

namespace lbm::moving_wall {

// A scheme without per-thread state runs as it is on every thread (Mei-Luo-Shyy has its own
// overload, for its cache table).
template <class Scheme>
const Scheme& for_thread(const Scheme& scheme, int /*t*/) {
  return scheme;
}

// The cell-index steps of the 19 directions.
struct DirectionOffsets {
  std::ptrdiff_t of[D3Q19::Q];
  explicit DirectionOffsets(const BlockLayout& layout) {
    for (int q = 0; q < D3Q19::Q; ++q) of[q] = layout.offset(D3Q19::c[q][0], D3Q19::c[q][1], D3Q19::c[q][2]);
  }
};

// The two slots a link of direction q touches, by its fluid cell x: f_q(x) (what x sends)
// and f_{-q}(x + c_q) (where the returned population is pulled from). Taken once per call,
// so that a link costs no index arithmetic beyond its cell.
struct LinkSlots {
  const Real* out[D3Q19::Q];
  Real* back[D3Q19::Q];  // f.q(-q) + offset of c_q: inside the field, as is back[q] + x
  LinkSlots(const DirectionOffsets& offsets, PopulationField& f) {
    for (int q = 0; q < D3Q19::Q; ++q) {
      out[q] = f.q(q);
      back[q] = f.q(D3Q19::opposite(q)) + offsets.of[q];
    }
  }
};

// One link; its `momentum` and `populations` entries written where non-null.
template <class Scheme>
inline void apply_link(const BoundaryLink& link, const Scheme& scheme,
                       const DirectionOffsets& offsets, const LinkSlots& slots,
                       PopulationField& f, std::array<double, 3>* momentum,
                       LinkPopulations* populations) {
  using L = D3Q19;
  const int q = link.q;
  const double back = scheme.returning_population(link, offsets.of[q], f);
  Real& slot = slots.back[q][link.fluid_cell];
  slot = static_cast<Real>(back);
  if (populations) *populations = {slots.out[q][link.fluid_cell], slot};
  if (momentum) {
    const double m = slots.out[q][link.fluid_cell] + back;
    *momentum = {m * L::c[q][0], m * L::c[q][1], m * L::c[q][2]};
  }
}

// Links [first, last); `momentum` and `populations`, if non-null, already sized.
template <class Scheme>
void apply_range(const std::vector<BoundaryLink>& links, std::size_t first, std::size_t last,
                 const Scheme& scheme, const BlockLayout& layout, PopulationField& f,
                 std::vector<std::array<double, 3>>* momentum,
                 std::vector<LinkPopulations>* populations) {
  const DirectionOffsets offsets(layout);  // once per call
  const LinkSlots slots(offsets, f);
  for (std::size_t l = first; l < last; ++l)
    apply_link(links[l], scheme, offsets, slots, f, momentum ? &(*momentum)[l] : nullptr,
               populations ? &(*populations)[l] : nullptr);
}

// What the node-major sweep reads once per fluid node for all its links: the scheme's
// node_state where it has one (Mei-Luo-Shyy: the node's moments), else nothing.
struct NoNodeState {};
template <class Scheme>
auto node_state(const Scheme& scheme, const PopulationField& f, std::size_t x, int)
    -> decltype(scheme.node_state(f, x)) {
  return scheme.node_state(f, x);
}
template <class Scheme>
NoNodeState node_state(const Scheme&, const PopulationField&, std::size_t, long) {
  return {};
}
template <class Scheme, class State>
double returning_population(const Scheme& scheme, const BoundaryLink& link, std::ptrdiff_t offset,
                            const PopulationField& f, const State& state) {
  if constexpr (std::is_same_v<State, NoNodeState>)
    return scheme.returning_population(link, offset, f);
  else
    return scheme.returning_population(link, offset, f, state);
}

// The lines a link reads, asked for this many links before it is applied: the lattice is
// out of the caches after the DEM substeps, and the links' nodes are too far apart in each
// of the arrays for the hardware to guess them.
constexpr std::size_t kPrefetchLinks = 16;
// The scheme's own lines of a link (Mei-Luo-Shyy: the moments it reads), where it names them.
template <class Scheme>
auto prefetch_scheme(const Scheme& scheme, const BoundaryLink& link, std::ptrdiff_t offset, int)
    -> decltype(scheme.prefetch(link, offset)) {
  scheme.prefetch(link, offset);
}
template <class Scheme>
void prefetch_scheme(const Scheme&, const BoundaryLink&, std::ptrdiff_t, long) {}

// The links at sorted positions [i, end) of one fluid node x (consecutive, in link order)
// through the scheme, with x's state read once; their populations and defects recorded
// under their link ids. Returns the position after the node's last link.
template <class Scheme>
std::size_t apply_node(const LinkSweep& order, std::size_t i, std::size_t end,
                       const Scheme& scheme, const DirectionOffsets& offsets,
                       const LinkSlots& slots, double rho0, PopulationField& f,
                       LinkPopulations* pops, double* defect) {
  const BoundaryLink* const link = order.sorted_links();
  const std::uint32_t* const id = order.ids();
  const std::size_t x = link[i].fluid_cell;
  const std::size_t num_links = order.first(order.num_blocks());
  const auto state = node_state(scheme, f, x, 0);
  do {
    if (i + kPrefetchLinks < num_links) {
      const BoundaryLink& ahead = link[i + kPrefetchLinks];
      __builtin_prefetch(slots.out[ahead.q] + ahead.fluid_cell);
      __builtin_prefetch(slots.back[ahead.q] + ahead.fluid_cell, 1);
      prefetch_scheme(scheme, ahead, offsets.of[ahead.q], 0);
    }
    const BoundaryLink& k = link[i];
    const int q = k.q;
    const double out = slots.out[q][x];  // not the slot written below (direction -q)
    const Real back = static_cast<Real>(returning_population(scheme, k, offsets.of[q], f, state));
    slots.back[q][x] = back;
    // Member by member: the values stay in registers for the defect.
    LinkPopulations& recorded = pops[id[i]];
    recorded.out = out;
    recorded.back = back;
    defect[id[i]] = link_defect(k, rho0, LinkPopulations{out, back});
  } while (++i != end && link[i].fluid_cell == x);
  return i;
}

// The nodes at sorted positions [i, end) that are (`open`) or are not next to an open face,
// each through apply_node and then restorer.remove_node: with the kernel's deferral, the
// entries of a node away from the open faces are written, and a node next to one is
// corrected at once (its entries 0). For KernelLinks (link_sweep.h): the open faces' nodes
// before the kernel, the others in its pass.
template <class Scheme>
void apply_nodes(const LinkSweep& order, std::size_t i, std::size_t end, bool open,
                 const Scheme& scheme, const DirectionOffsets& offsets, const LinkSlots& slots,
                 double rho0, const LinkMassRestorer& restorer, PopulationField& f,
                 LinkPopulations* pops, double* defect) {
  const std::uint32_t* const cell = order.sorted_cells();
  while (i != end) {
    const std::uint32_t x = cell[i];
    std::size_t node_end = i + 1;
    while (node_end != end && cell[node_end] == x) ++node_end;
    if (restorer.next_to_open(x) == open) {
      apply_node(order, i, node_end, scheme, offsets, slots, rho0, f, pops, defect);
      restorer.remove_node(x, defect, order.ids() + i, order.ids() + node_end);
    }
    i = node_end;
  }
}

// The correction of block c's nodes, node by node: each node's 19 slots written once, with
// the defects of its links taken off in link order (LinkMassRestorer::remove_node).
inline void correct_block(const LinkSweep& order, std::size_t c, const LinkMassRestorer& restorer,
                          const double* defect) {
  const BoundaryLink* const link = order.sorted_links();
  for (std::size_t i = order.first(c), end = order.first(c + 1); i != end;) {
    const std::size_t x = link[i].fluid_cell;
    std::size_t node_end = i + 1;
    while (node_end != end && link[node_end].fluid_cell == x) ++node_end;
    restorer.remove_node(x, defect, order.ids() + i, order.ids() + node_end);
    i = node_end;
  }
}

// Blocks [first, last) of moving_wall::sweep (link_sweep.h) on one thread: block b's nodes
// through the scheme, their links' defects measured, then the correction of block b - lag,
// whose cells no link still to come reads; only blocks in [safe_first, safe_last) are
// corrected here, the others by sweep's second phase.
template <class Scheme>
void sweep_blocks(const LinkSweep& order, const Scheme& scheme, const DirectionOffsets& offsets,
                  const LinkSlots& slots, double rho0, const LinkMassRestorer& restorer,
                  PopulationField& f, LinkPopulations* pops, double* defect, std::size_t first,
                  std::size_t last, std::size_t safe_first, std::size_t safe_last) {
  const std::size_t lag = order.lag();
  for (std::size_t b = first; b < last + lag; ++b) {
    if (b < last)
      for (std::size_t i = order.first(b), end = order.first(b + 1); i != end;)
        i = apply_node(order, i, end, scheme, offsets, slots, rho0, f, pops, defect);
    if (b < first + lag) continue;
    const std::size_t c = b - lag;
    if (c >= safe_first && c < safe_last) correct_block(order, c, restorer, defect);
  }
}

// moving_wall::sweep (link_sweep.h). On one thread sweep_blocks over every block. On more,
// thread t takes the t-th contiguous range of blocks holding n/T of the links, and corrects at
// once only the blocks at least `lag` blocks inside its range: no other thread's links read
// their cells, nor do the thread's own links after them (as on one thread). The blocks within
// `lag` of a range's inner ends are corrected after a barrier, once every link has been read.
// A correction writes only the slots its node pulls, so the order of blocks does not change
// a bit: the result is the one-thread sweep's for any number of threads.
template <class Scheme>
void sweep(const std::vector<BoundaryLink>& links, const LinkSweep& order, const Scheme& scheme,
           const BlockLayout& layout, double rho0, const LinkMassRestorer& restorer,
           PopulationField& f, std::vector<LinkPopulations>& populations,
           std::vector<double>& per_link, int threads) {
  populations.resize(links.size());
  per_link.resize(links.size());
  const DirectionOffsets offsets(layout);
  const LinkSlots slots(offsets, f);
  // The arrays' addresses in locals: through the vectors they would be reloaded after every
  // call into the scheme.
  LinkPopulations* const pops = populations.data();
  double* const defect = per_link.data();
  const std::size_t blocks = order.num_blocks(), lag = order.lag();
  if (threads <= 1) {
    sweep_blocks(order, scheme, offsets, slots, rho0, restorer, f, pops, defect, 0, blocks, 0, blocks);
    return;
  }
#pragma omp parallel num_threads(threads)
  {
    const auto [t, nt] = lbm::team_member();
    const std::size_t first = order.block_of_share(t, nt), last = order.block_of_share(t + 1, nt);
    // The outer ends of the first and last ranges border no other thread.
    const std::size_t safe_first = t == 0 ? first : first + lag;
    const std::size_t safe_last = t + 1 == nt ? last : (last > lag ? last - lag : 0);
    sweep_blocks(order, for_thread(scheme, t), offsets, slots, rho0, restorer, f, pops, defect,
                 first, last, safe_first, safe_last);
#pragma omp barrier
    for (std::size_t c = first; c < last; ++c)
      if (c < safe_first || c >= safe_last) correct_block(order, c, restorer, defect);
  }
}

template <class Scheme>
void apply(const std::vector<BoundaryLink>& links, const Scheme& scheme, const BlockLayout& layout,
           PopulationField& f, std::vector<std::array<double, 3>>* momentum, int threads,
           std::vector<LinkPopulations>* populations) {
  if (momentum) momentum->resize(links.size());
  if (populations) populations->resize(links.size());
  const std::size_t n = links.size();
  if (threads <= 1) {
    apply_range(links, 0, n, scheme, layout, f, momentum, populations);
    return;
  }
#pragma omp parallel num_threads(threads)
  {
    const auto [t, nt] = lbm::team_member();
    apply_range(links, n * std::size_t(t) / std::size_t(nt), n * std::size_t(t + 1) / std::size_t(nt),
                for_thread(scheme, t), layout, f, momentum, populations);
  }
}

// The two loops instantiated for `Scheme` in its own source file (inside namespace
// lbm::moving_wall), so they are compiled with that file's options and inline its formula.
#define LBM_MOVING_WALL_INSTANTIATE_LOOPS(Scheme)                                                \
  template void apply<Scheme>(const std::vector<BoundaryLink>&, const Scheme&,                   \
                              const BlockLayout&, PopulationField&,                              \
                              std::vector<std::array<double, 3>>*, int,                          \
                              std::vector<LinkPopulations>*);                                    \
  template void sweep<Scheme>(const std::vector<BoundaryLink>&, const LinkSweep&, const Scheme&, \
                              const BlockLayout&, double, const LinkMassRestorer&,               \
                              PopulationField&, std::vector<LinkPopulations>&,                   \
                              std::vector<double>&, int);                                        \
  template void apply_nodes<Scheme>(const LinkSweep&, std::size_t, std::size_t, bool,            \
                                    const Scheme&, const DirectionOffsets&, const LinkSlots&,    \
                                    double, const LinkMassRestorer&, PopulationField&,           \
                                    LinkPopulations*, double*)

}  // namespace lbm::moving_wall
