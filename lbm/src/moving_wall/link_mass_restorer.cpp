// LinkMassRestorer (link_mass.h): the correction's 19 writes per link. A file of its own so
// that it can be built without contraction (lbm/CMakeLists.txt): its products w_p delta_l
// have always been rounded before the subtraction (the compiler computed them once for both
// branches of the open-ghost test), and the fast path below, whose product and subtraction
// sit in one block, must round them the same way.
#include "lbm/moving_wall/link_mass.h"

#include "lbm/d3q19.h"
#include "lbm/node_type.h"

namespace lbm::moving_wall {

namespace {
using L = D3Q19;
}  // namespace

LinkMassRestorer::LinkMassRestorer(const BlockLayout& layout,
                                   const std::vector<std::uint8_t>& node_type, PopulationField& f)
    : rest_(f.q(0)), type_(node_type.data()) {
  // Taken once: through a Real& the field's own pointer and size would be reloaded after
  // every store, 19 times per link.
  for (int p = 0; p < L::Q; ++p) {
    from_[p] = -layout.offset(L::c[p][0], L::c[p][1], L::c[p][2]);
    // Inside the field's one array (an offset is smaller than a direction's share of it),
    // and so is slot_[p] + x for every cell x whose neighbour x - c_p is a cell.
    slot_[p] = f.q(p) + from_[p];
  }
}

void LinkMassRestorer::remove(std::size_t x, double d) const {
  // Population p reaches x from x - c_p in the next (pull) streaming. Nodes next to an open
  // face are few: the 19 types are tested first, and the others' 19 slots written without a
  // test in between (the same writes, each slot once).
  const std::uint8_t* const type = type_ + x;
#pragma GCC unroll 19
  for (int p = 0; p < L::Q; ++p)
    if (type[from_[p]] == kOpen) {
      remove_next_to_open(x, d);
      return;
    }
#pragma GCC unroll 19
  for (int p = 0; p < L::Q; ++p) {
    Real& slot = slot_[p][x];
    slot = static_cast<Real>(slot - L::w[p] * d);
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
