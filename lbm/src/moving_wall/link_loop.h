#pragma once
// The loop every moving-wall scheme runs over its links (declared in
// lbm/moving_wall/moving_wall_scheme.h); each scheme's source file instantiates it, so the
// per-link formula is inlined and no link branches on the scheme.
#ifdef _OPENMP
#include <omp.h>
#endif

#include "lbm/link_boundary.h"
#include "lbm/moving_wall/moving_wall_scheme.h"

namespace lbm::moving_wall {

// A scheme without per-thread state runs as it is on every thread (Mei-Luo-Shyy has its own
// overload, for its cache table).
template <class Scheme>
const Scheme& for_thread(const Scheme& scheme, int /*t*/) {
  return scheme;
}

// Links [first, last); `momentum` and `populations`, if non-null, already sized.
template <class Scheme>
void apply_range(const std::vector<BoundaryLink>& links, std::size_t first, std::size_t last,
                 const Scheme& scheme, const BlockLayout& layout, PopulationField& f,
                 std::vector<std::array<double, 3>>* momentum,
                 std::vector<LinkPopulations>* populations) {
  using L = D3Q19;
  std::ptrdiff_t offsets[L::Q];  // cell-index step of c_q, once per call
  for (int q = 0; q < L::Q; ++q) offsets[q] = layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
  for (std::size_t l = first; l < last; ++l) {
    const BoundaryLink& link = links[l];
    const int q = link.q;
    const std::ptrdiff_t offset = offsets[q];
    const double back = scheme.returning_population(link, offset, f);
    Real& slot = f.at(L::opposite(q), link.fluid_cell + offset);
    slot = static_cast<Real>(back);
    if (populations) (*populations)[l] = {f.at(q, link.fluid_cell), slot};
    if (momentum) {
      const double m = f.at(q, link.fluid_cell) + back;
      (*momentum)[l] = {m * L::c[q][0], m * L::c[q][1], m * L::c[q][2]};
    }
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
#ifdef _OPENMP
    const int t = omp_get_thread_num(), nt = omp_get_num_threads();
#else
    const int t = 0, nt = 1;
#endif
    apply_range(links, n * std::size_t(t) / std::size_t(nt), n * std::size_t(t + 1) / std::size_t(nt),
                for_thread(scheme, t), layout, f, momentum, populations);
  }
}

}  // namespace lbm::moving_wall
