#pragma once
#include <array>
#include <cstddef>
#include <vector>

#include "lbm/block_layout.h"
#include "lbm/d3q19.h"
#include "lbm/huge_page_allocator.h"
#include "lbm/real.h"

namespace lbm {

// The 19 populations of every cell of a block (ghosts included), structure of arrays: one
// array per population, so the stream-collide loop over x is contiguous for every q and
// vectorises. The storage is on huge pages where the system gives them
// (huge_page_allocator.h).
//
// One field, streamed in place (the AA pattern: Bailey, Myre, Walsh, Lilja & Saar 2009,
// "Accelerating lattice Boltzmann fluid flow simulations using graphics processors"): a
// step writes each node's output into the slots it read its input from, so no second
// field is needed and a step moves 2 x 19 values per node through 19 streams, not 38. The
// price is that where a value lives alternates between two placements from step to step:
//   kReversed: population q of cell x in array -q at x (after a step that reads and writes
//              only its node's own slots),
//   kForward:  population q of cell x in array q at x + c_q (after a step that writes each
//              value into the node it travels to, and so reads from the neighbours).
// q(), at() and index() hide that: they address population q of cell x of the current
// placement, so every stage outside the kernel sees the same post-collision populations
// f*_q(x) as before. Each array has `pad` spare values before and after its cells, so that
// kForward's shift stays inside the array for every cell, ghosts included.
class PopulationField {
 public:
  using Storage = std::vector<Real, HugePageAllocator<Real>>;
  enum class Placement { kReversed, kForward };

  PopulationField() = default;
  explicit PopulationField(const BlockLayout& layout);

  std::size_t num_cells() const { return n_; }
  // Population q of cell c is q(q)[c] (c from 0 to num_cells() - 1).
  Real* q(int q) { return data_.data() + base_[int(placement_)][q]; }
  const Real* q(int q) const { return data_.data() + base_[int(placement_)][q]; }
  Real& at(int q, std::size_t cell) { return data_[index(placement_, q, cell)]; }
  Real at(int q, std::size_t cell) const { return data_[index(placement_, q, cell)]; }
  // Where population q of cell c would live under `placement`, as an index into raw().
  std::size_t index(Placement placement, int q, std::size_t cell) const {
    return std::size_t(base_[int(placement)][q] + std::ptrdiff_t(cell));
  }
  // The 19 arrays' cell-0 pointers under `placement` (for the kernel, which reads under one
  // placement and writes under the other).
  std::array<Real*, D3Q19::Q> arrays(Placement placement);

  Placement placement() const { return placement_; }
  // Relabels the storage: for the kernel, which has just written every value under
  // `placement`. Nothing is moved.
  void set_placement(Placement placement) { placement_ = placement; }

  // The whole storage, padding included: its layout depends on placement().
  Storage& raw() { return data_; }
  const Storage& raw() const { return data_; }

 private:
  std::size_t n_ = 0;
  std::ptrdiff_t base_[2][D3Q19::Q] = {};  // [placement][q]: where q's cell 0 is in data_
  Placement placement_ = Placement::kReversed;
  Storage data_;
};

inline PopulationField::Placement other(PopulationField::Placement p) {
  using P = PopulationField::Placement;
  return p == P::kReversed ? P::kForward : P::kReversed;
}

}  // namespace lbm
