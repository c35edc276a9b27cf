#pragma once
#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace lbm {

// Static solid/fluid voxels of the whole domain, on the lattice grid: voxel (i,j,k) is the
// lattice node at origin + (i,j,k) * spacing, and a solid voxel fills the cube of side
// `spacing` centred there. Every rank holds the whole geometry (one byte per node), which
// keeps loading simple and lets the wall-contact code query voxels near any particle.
class VoxelGeometry {
 public:
  VoxelGeometry() = default;
  // All fluid. dims must be positive.
  explicit VoxelGeometry(std::array<int, 3> dims, double spacing = 1.0,
                         std::array<double, 3> origin = {0.0, 0.0, 0.0});

  const std::array<int, 3>& dims() const { return dims_; }
  double spacing() const { return spacing_; }
  const std::array<double, 3>& origin() const { return origin_; }
  // Moves the geometry (a host places a file's voxels where its box is).
  void place_at(const std::array<double, 3>& origin) { origin_ = origin; }
  std::size_t num_voxels() const { return solid_.size(); }

  bool inside(int i, int j, int k) const {
    return i >= 0 && j >= 0 && k >= 0 && i < dims_[0] && j < dims_[1] && k < dims_[2];
  }
  // Voxels outside the domain are reported as fluid; the boundary conditions of the
  // lattice (walls, periodic, inlet/outlet) decide what lies beyond the box.
  bool is_solid(int i, int j, int k) const {
    return inside(i, j, k) && solid_[index(i, j, k)] != 0;
  }
  void set_solid(int i, int j, int k, bool solid) { solid_[index(i, j, k)] = solid ? 1 : 0; }
  std::size_t count_solid() const;

  // x fastest, then y, then z (the layout of the raw voxel file and of VTK images).
  std::size_t index(int i, int j, int k) const {
    return (static_cast<std::size_t>(k) * dims_[1] + j) * dims_[0] + i;
  }
  const std::vector<std::uint8_t>& data() const { return solid_; }

 private:
  std::array<int, 3> dims_{0, 0, 0};
  double spacing_ = 1.0;
  std::array<double, 3> origin_{0.0, 0.0, 0.0};
  std::vector<std::uint8_t> solid_;
};

}  // namespace lbm
