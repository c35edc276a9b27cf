#pragma once
// The loop every moving-wall scheme runs over its links (declared in
// lbm/moving_wall/moving_wall_scheme.h); each scheme's source file instantiates it, so the
// per-link formula is inlined and no link branches on the scheme.
#include "lbm/link_boundary.h"
#include "lbm/moving_wall/moving_wall_scheme.h"

namespace lbm::moving_wall {

template <class Scheme>
void apply(const std::vector<BoundaryLink>& links, const Scheme& scheme, const BlockLayout& layout,
           PopulationField& f, std::vector<std::array<double, 3>>* momentum) {
  using L = D3Q19;
  if (momentum) momentum->resize(links.size());
  for (std::size_t l = 0; l < links.size(); ++l) {
    const BoundaryLink& link = links[l];
    const int q = link.q;
    const std::ptrdiff_t offset = layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
    const double back = scheme.returning_population(link, offset, f);
    f.at(L::opposite(q), link.fluid_cell + offset) = static_cast<Real>(back);
    if (momentum) {
      const double m = f.at(q, link.fluid_cell) + back;
      (*momentum)[l] = {m * L::c[q][0], m * L::c[q][1], m * L::c[q][2]};
    }
  }
}

}  // namespace lbm::moving_wall
