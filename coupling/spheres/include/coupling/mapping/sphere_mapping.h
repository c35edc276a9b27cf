#pragma once
// Mapping: which lattice nodes the spheres cover (waLBerla's mapping/ stage).
#include <cstddef>
#include <cstdint>
#include <vector>

#include "coupling/particle_view.h"
#include "coupling/periodic_box.h"
#include "lbm/block_layout.h"

namespace coupling {

// What changed since the last mapping. Cells are local linear indices (ghosts included).
struct MappingChange {
  std::vector<std::size_t> covered;          // fluid nodes a sphere now covers
  std::vector<std::size_t> uncovered;        // moving nodes no sphere covers any more
  std::vector<int> uncovered_particle;       // the sphere that just left each (index in view)
};

// A node belongs to a sphere when its centre lies strictly inside: |x_node - X|^2 < R^2
// (minimum image on periodic axes). Only kFluid and kMoving nodes change type; a sphere
// overlapping a static wall leaves the wall voxels solid. Where spheres overlap, the one
// with the lower index takes the node (owned particles come first in the view).
class SphereMapping {
 public:
  SphereMapping(const lbm::BlockLayout& layout, const PeriodicBox& box);

  // Maps the particles of `view` onto every local cell (ghost layer included). Leaves
  // node_type unchanged: commit() applies the change after the refill has read the old
  // state. The work is proportional to the spheres' volume (plus the cells they covered
  // last step), never to the lattice. The second form reuses `change`'s storage.
  MappingChange update(const ParticleView& view, const std::vector<std::uint8_t>& node_type);
  void update(const ParticleView& view, const std::vector<std::uint8_t>& node_type,
              MappingChange& change);
  void commit(const MappingChange& change, std::vector<std::uint8_t>& node_type) const;

  // Index (in the last mapped view) of the sphere covering `cell`, or -1.
  int particle_at(std::size_t cell) const { return owner_[cell]; }
  const std::vector<std::size_t>& moving_cells() const { return moving_; }
  // The covered cells of sphere p (index in the last mapped view) that can have fluid
  // neighbours: those within sqrt(2) (the longest link) of its surface, in mapping order.
  // Only they can take links (coupling/boundary/sphere_links.h).
  struct CellRange {
    const std::size_t* first;
    const std::size_t* last;
    const std::size_t* begin() const { return first; }
    const std::size_t* end() const { return last; }
  };
  CellRange surface_cells(std::size_t p) const {
    return {surface_.data() + surface_begin_[p], surface_.data() + surface_begin_[p + 1]};
  }
  std::size_t num_mapped_particles() const { return surface_begin_.empty() ? 0 : surface_begin_.size() - 1; }
  // Global position of a local cell.
  Vec3 node_position(std::size_t cell) const;
  // visit(c) with the local coordinates c[3] (cell (i, j, k) at (i, j, k)) of `centre` and
  // of its periodic images -L and +L on each periodic axis, in z, y, x order of the shifts:
  // the images update() maps (only those reaching the block add cells).
  template <class Visit>
  void for_each_local_image(const Vec3& centre, Visit&& visit) const {
    int shifts[3][3], num_shifts[3];
    for (int a = 0; a < 3; ++a) {
      num_shifts[a] = 0;
      for (int s = -1; s <= 1; ++s)
        if (s == 0 || box_.periodic[a]) shifts[a][num_shifts[a]++] = s;
    }
    const auto& lo = layout_.owned().lo;
    for (int sz = 0; sz < num_shifts[2]; ++sz)
      for (int sy = 0; sy < num_shifts[1]; ++sy)
        for (int sx = 0; sx < num_shifts[0]; ++sx) {
          const int s[3] = {shifts[0][sx], shifts[1][sy], shifts[2][sz]};
          double c[3];
          for (int a = 0; a < 3; ++a) c[a] = centre[a] + s[a] * box_.length[a] - lo[a];
          visit(static_cast<const double*>(c));
        }
  }
  const lbm::BlockLayout& layout() const { return layout_; }
  const PeriodicBox& box() const { return box_; }

 private:
  lbm::BlockLayout layout_;
  PeriodicBox box_;
  std::vector<int> owner_;        // per cell: covering particle or -1
  std::vector<int> shell_;        // per cell: scratch, particle whose shell holds the cell
  std::vector<std::size_t> moving_;  // cells with owner_ >= 0
  std::vector<std::size_t> previous_;  // moving_ of the step before (storage kept)
  std::vector<std::size_t> surface_;   // surface cells, particle by particle
  std::vector<std::size_t> surface_begin_;  // per particle: first index in surface_ (+ end)

  void map_image(int p, const double c[3], double R, const std::vector<std::uint8_t>& node_type,
                 MappingChange& change);
};

}  // namespace coupling
