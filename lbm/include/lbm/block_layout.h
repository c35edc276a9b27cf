#pragma once
#include <array>
#include <cstddef>

namespace lbm {

// A box of lattice nodes in global indices, half-open: lo <= x < hi on each axis.
struct Box {
  std::array<int, 3> lo{0, 0, 0};
  std::array<int, 3> hi{0, 0, 0};
  int size(int axis) const { return hi[axis] - lo[axis]; }
  long long volume() const { return 1LL * size(0) * size(1) * size(2); }
  bool contains(int x, int y, int z) const {
    return x >= lo[0] && x < hi[0] && y >= lo[1] && y < hi[1] && z >= lo[2] && z < hi[2];
  }
};

// Index arithmetic of one rank's block: the owned box plus one ghost layer on every side.
// Local coordinates run from -1 to n (owned nodes 0..n-1); cells are stored x fastest.
// This is the only place that knows the memory layout of a block.
class BlockLayout {
 public:
  static constexpr int kGhost = 1;

  BlockLayout() = default;
  explicit BlockLayout(const Box& owned)
      : owned_(owned),
        n_{owned.size(0), owned.size(1), owned.size(2)},
        p_{n_[0] + 2 * kGhost, n_[1] + 2 * kGhost, n_[2] + 2 * kGhost} {}

  const Box& owned() const { return owned_; }
  int size(int axis) const { return n_[axis]; }        // owned nodes along axis
  int padded(int axis) const { return p_[axis]; }      // with ghosts
  std::size_t num_cells() const { return std::size_t(p_[0]) * p_[1] * p_[2]; }

  // Local (i,j,k) in [-1, n] -> linear cell index.
  std::size_t cell(int i, int j, int k) const {
    return (std::size_t(k + kGhost) * p_[1] + std::size_t(j + kGhost)) * p_[0] +
           std::size_t(i + kGhost);
  }
  // Linear offset of the neighbour at (dx,dy,dz).
  std::ptrdiff_t offset(int dx, int dy, int dz) const {
    return (std::ptrdiff_t(dz) * p_[1] + dy) * p_[0] + dx;
  }
  // Inverse of cell(): local coordinates of a linear index.
  std::array<int, 3> coords(std::size_t cell) const {
    const int i = int(cell % p_[0]);
    const int j = int((cell / p_[0]) % p_[1]);
    const int k = int(cell / (std::size_t(p_[0]) * p_[1]));
    return {i - kGhost, j - kGhost, k - kGhost};
  }
  bool is_owned(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < n_[0] && j < n_[1] && k < n_[2];
  }
  std::array<int, 3> to_global(int i, int j, int k) const {
    return {i + owned_.lo[0], j + owned_.lo[1], k + owned_.lo[2]};
  }

 private:
  Box owned_;
  std::array<int, 3> n_{0, 0, 0};
  std::array<int, 3> p_{0, 0, 0};
};

}  // namespace lbm
