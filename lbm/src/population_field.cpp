#include "lbm/population_field.h"

#include <algorithm>
#include <cstdlib>

namespace lbm {

namespace {
// Values per 64-byte line: the arrays start on line boundaries.
constexpr std::size_t kLine = 64 / sizeof(Real);
std::size_t round_up(std::size_t v) { return (v + kLine - 1) / kLine * kLine; }
}  // namespace

PopulationField::PopulationField(const BlockLayout& layout) : n_(layout.num_cells()) {
  using L = D3Q19;
  // kForward keeps cell x's population q at x + c_q: a cell on the block's outer ghost
  // layer reaches one link beyond the cells, at most |offset(0, 1, 1)| values.
  std::ptrdiff_t reach = 0;
  for (int q = 0; q < L::Q; ++q)
    reach = std::max(reach, std::abs(layout.offset(L::c[q][0], L::c[q][1], L::c[q][2])));
  const std::size_t pad = round_up(std::size_t(reach));
  const std::size_t stride = pad + round_up(n_) + pad;
  for (int q = 0; q < L::Q; ++q) {
    const std::ptrdiff_t array_of_q = std::ptrdiff_t(q) * std::ptrdiff_t(stride) + std::ptrdiff_t(pad);
    const std::ptrdiff_t array_of_opposite =
        std::ptrdiff_t(L::opposite(q)) * std::ptrdiff_t(stride) + std::ptrdiff_t(pad);
    base_[int(Placement::kReversed)][q] = array_of_opposite;
    base_[int(Placement::kForward)][q] = array_of_q + layout.offset(L::c[q][0], L::c[q][1], L::c[q][2]);
  }
  data_.assign(L::Q * stride, Real(0));
}

std::array<Real*, D3Q19::Q> PopulationField::arrays(Placement placement) {
  std::array<Real*, D3Q19::Q> a{};
  for (int q = 0; q < D3Q19::Q; ++q) a[std::size_t(q)] = data_.data() + base_[int(placement)][q];
  return a;
}

}  // namespace lbm
