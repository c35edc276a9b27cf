// LinkMassRestorer (link_mass.h): the correction's 19 writes per link. A file of its own so
// that it can be built without contraction (lbm/CMakeLists.txt): its products w_p delta_l
// have always been rounded before the subtraction (the compiler computed them once for both
// branches of the open-ghost test), and the fast path below, whose product and subtraction
// sit in one block, must round them the same way.
#include "lbm/moving_wall/link_mass.h"

#include <cstring>

#include "lbm/d3q19.h"
#include "lbm/node_type.h"

namespace lbm::moving_wall {

namespace {
using L = D3Q19;

// The types of four consecutive cells as one word.
std::uint32_t four_types(const std::uint8_t* first) {
  std::uint32_t v;
  std::memcpy(&v, first, sizeof v);
  return v;
}
// Non-zero if a byte of v has both low bits set. Of the node types only kOpen (3) has.
std::uint32_t maybe_open(std::uint32_t v) { return v & (v >> 1) & 0x01010101u; }
static_assert(kOpen == 3 && kFluid < 3 && kSolid < 3 && kMoving < 3, "maybe_open() tests bits 0 and 1");
}  // namespace

LinkMassRestorer::LinkMassRestorer(const BlockLayout& layout,
                                   const std::vector<std::uint8_t>& node_type, PopulationField& f,
                                   Deferral deferral)
    : rest_(f.q(0)), type_(node_type.data()), deferral_(deferral) {
  // Taken once: through a Real& the field's own pointer and size would be reloaded after
  // every store, 19 times per link.
  for (int p = 0; p < L::Q; ++p) {
    from_[p] = -layout.offset(L::c[p][0], L::c[p][1], L::c[p][2]);
    // Inside the field's one array (an offset is smaller than a direction's share of it),
    // and so is slot_[p] + x for every cell x whose neighbour x - c_p is a cell.
    slot_[p] = f.q(p) + from_[p];
  }
  row_[0] = layout.offset(0, 1, 0);
  row_[1] = -row_[0];
  row_[2] = layout.offset(0, 0, 1);
  row_[3] = -row_[2];
  for (int e = 0; e < 4; ++e) edge_[e] = layout.offset(0, e & 1 ? 1 : -1, e & 2 ? 1 : -1);
}

bool LinkMassRestorer::next_to_open(std::size_t x) const {
  // Population p reaches x from x - c_p in the next (pull) streaming. Nodes next to an open
  // face are few: their sources' types are tested first, and the others' 19 slots written
  // without a test in between (the same writes, each slot once).
  // The 19 sources x + c are five rows of three along the first axis (x and x +- 1, and
  // the same beside x along the second and third axes) and the four edge neighbours
  // x +- e_2 +- e_3. Each row is read as a word of four types (its fourth cell lies
  // within the block: before the next row or edge neighbour), the edge neighbours are
  // packed into one: six tests instead of 19. A fourth cell that happens to be open only
  // sends x to the exact loop, which gives the same writes.
  const std::uint8_t* const t = type_ + x;
  const std::uint32_t edges = std::uint32_t(t[edge_[0]]) | std::uint32_t(t[edge_[1]]) << 8 |
                              std::uint32_t(t[edge_[2]]) << 16 | std::uint32_t(t[edge_[3]]) << 24;
  const std::uint32_t open =
      maybe_open(four_types(t - 1)) | maybe_open(four_types(t + row_[0] - 1)) |
      maybe_open(four_types(t + row_[1] - 1)) | maybe_open(four_types(t + row_[2] - 1)) |
      maybe_open(four_types(t + row_[3] - 1)) | maybe_open(edges);
  return open != 0;
}

void LinkMassRestorer::remove(std::size_t x, double d) const {
  if (next_to_open(x)) {
    remove_next_to_open(x, d);
    return;
  }
#pragma GCC unroll 19
  for (int p = 0; p < L::Q; ++p) {
    Real& slot = slot_[p][x];
    slot = static_cast<Real>(slot - L::w[p] * d);
  }
}

void LinkMassRestorer::remove_node(std::size_t x, const double* defect, const std::uint32_t* first,
                                   const std::uint32_t* last) const {
  const bool open = next_to_open(x);
  if (deferral_.defects) {
    double* const deferred = deferral_.defects + (first - deferral_.ids);
    for (const std::uint32_t* l = first; l != last; ++l) deferred[l - first] = open ? 0.0 : defect[*l];
  }
  if (open) {
    for (const std::uint32_t* l = first; l != last; ++l) remove_next_to_open(x, defect[*l]);
    return;
  }
  if (deferral_.defects) return;
  // Each slot takes the links' shares one after the other, as remove() per link would.
#pragma GCC unroll 19
  for (int p = 0; p < L::Q; ++p) {
    Real value = slot_[p][x];
    for (const std::uint32_t* l = first; l != last; ++l)
      value = static_cast<Real>(value - L::w[p] * defect[*l]);
    slot_[p][x] = value;
  }
}

void LinkMassRestorer::remove_next_to_open(std::size_t x, double d) const {
  double at_rest = 0.0;
  for (int p = 0; p < L::Q; ++p) {
    // A ghost beyond an open face is written after this stage (the open boundary fills
    // it): its share goes on x's own rest population, so that x's mass changes by the
    // whole defect and the budget's books (PoreMonitor) stay exact.
    if (type_[x + from_[p]] == kOpen) {
      at_rest += L::w[p] * d;
      continue;
    }
    Real& slot = slot_[p][x];
    slot = static_cast<Real>(slot - L::w[p] * d);
  }
  if (at_rest != 0.0) rest_[x] = static_cast<Real>(rest_[x] - at_rest);
}

}  // namespace lbm::moving_wall
