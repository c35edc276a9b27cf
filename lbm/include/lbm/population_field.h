#pragma once
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/d3q19.h"
#include "lbm/huge_page_allocator.h"
#include "lbm/real.h"

namespace lbm {

// The 19 populations of every cell of a block (ghosts included), structure of arrays:
// population q of cell c is data[q * num_cells + c]. SoA keeps the stream-collide loop
// over x contiguous for every q, so it vectorises. The storage is on huge pages where the
// system gives them (huge_page_allocator.h).
class PopulationField {
 public:
  using Storage = std::vector<Real, HugePageAllocator<Real>>;

  PopulationField() = default;
  explicit PopulationField(const BlockLayout& layout)
      : n_(layout.num_cells()), data_(D3Q19::Q * layout.num_cells(), Real(0)) {}

  std::size_t num_cells() const { return n_; }
  Real* q(int q) { return data_.data() + q * n_; }
  const Real* q(int q) const { return data_.data() + q * n_; }
  Real& at(int q, std::size_t cell) { return data_[q * n_ + cell]; }
  Real at(int q, std::size_t cell) const { return data_[q * n_ + cell]; }
  Storage& raw() { return data_; }
  const Storage& raw() const { return data_; }

 private:
  std::size_t n_ = 0;
  Storage data_;
};

}  // namespace lbm
