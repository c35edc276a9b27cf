#pragma once
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/d3q19.h"
#include "lbm/real.h"

namespace lbm {

// The 19 populations of every cell of a block (ghosts included), structure of arrays:
// population q of cell c is data[q * num_cells + c]. SoA keeps the stream-collide loop
// over x contiguous for every q, so it vectorises.
class PopulationField {
 public:
  PopulationField() = default;
  explicit PopulationField(const BlockLayout& layout)
      : n_(layout.num_cells()), data_(D3Q19::Q * layout.num_cells(), Real(0)) {}

  std::size_t num_cells() const { return n_; }
  Real* q(int q) { return data_.data() + q * n_; }
  const Real* q(int q) const { return data_.data() + q * n_; }
  Real& at(int q, std::size_t cell) { return data_[q * n_ + cell]; }
  Real at(int q, std::size_t cell) const { return data_[q * n_ + cell]; }
  std::vector<Real>& raw() { return data_; }
  const std::vector<Real>& raw() const { return data_; }

 private:
  std::size_t n_ = 0;
  std::vector<Real> data_;
};

}  // namespace lbm
