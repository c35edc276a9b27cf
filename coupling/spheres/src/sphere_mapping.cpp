#include "coupling/mapping/sphere_mapping.h"

#include <algorithm>
#include <cmath>

#include "lbm/node_type.h"

namespace coupling {

namespace {
// Margin of the row ranges and of the surface test, far above the round-off of the squared
// distances (~1e-14 for spheres of a few cells), far below the lattice spacing: the ranges
// are then supersets of the cells the exact tests accept, so the mapping is the same.
constexpr double kMargin = 1e-6;
// Longest D3Q19 link, |c_q| <= sqrt(2).
const double kLongestLink = std::sqrt(2.0);
}  // namespace

SphereMapping::SphereMapping(const lbm::BlockLayout& layout, const PeriodicBox& box)
    : layout_(layout), box_(box), owner_(layout.num_cells(), -1), shell_(layout.num_cells(), -1) {}

Vec3 SphereMapping::node_position(std::size_t cell) const {
  const auto c = layout_.coords(cell);
  const auto g = layout_.to_global(c[0], c[1], c[2]);
  return {double(g[0]), double(g[1]), double(g[2])};
}

// One image of sphere p, centre c in local coordinates. Visits only the rows (j, k) that
// reach the shell and, in each, the x-range of the shell's circle (plus a margin): the work
// is the sphere's volume, not its bounding box's. The cells are tested exactly as a scan
// of the whole box would, in the same order (k, j, i), so the mapping does not change.
void SphereMapping::map_image(int p, const double c[3], double R,
                              const std::vector<std::uint8_t>& node_type, MappingChange& change) {
  const double R2 = R * R;
  // A sphere moves less than a cell per fluid step, so the nodes it just left lie in
  // the shell R <= d < R + 1.5 (recorded for the refill's wall velocity).
  const double reach = R + 1.5;
  const double shell2 = reach * reach;
  // Covered nodes closer to the centre than this have no fluid neighbour (every node within
  // |c_q| of them is inside the sphere too): not surface cells.
  const double inner = R - kLongestLink - kMargin;
  const double inner2 = inner > 0.0 ? inner * inner : -1.0;
  int from[3], to[3];
  for (int a = 0; a < 3; ++a) {
    from[a] = std::max(-1, int(std::floor(c[a] - R - 1.5)));
    to[a] = std::min(layout_.size(a), int(std::ceil(c[a] + R + 1.5)));
    if (from[a] > to[a]) return;
  }
  for (int k = from[2]; k <= to[2]; ++k)
    for (int j = from[1]; j <= to[1]; ++j) {
      const double dy = j - c[1], dz = k - c[2];
      const double rest = shell2 - (dy * dy + dz * dz);
      if (rest < -kMargin) continue;
      const double half = std::sqrt(std::max(rest, 0.0)) + kMargin;
      const int i0 = std::max(from[0], int(std::ceil(c[0] - half)));
      const int i1 = std::min(to[0], int(std::floor(c[0] + half)));
      std::size_t cell = layout_.cell(i0, j, k);
      for (int i = i0; i <= i1; ++i, ++cell) {
        const double dx = i - c[0];
        const double d2 = dx * dx + dy * dy + dz * dz;
        const std::uint8_t type = node_type[cell];
        if (type != lbm::kFluid && type != lbm::kMoving) continue;
        if (d2 < R2) {
          if (owner_[cell] >= 0) continue;
          owner_[cell] = p;
          moving_.push_back(cell);
          if (d2 >= inner2) surface_.push_back(cell);
          if (type == lbm::kFluid) change.covered.push_back(cell);
        } else if (type == lbm::kMoving && d2 < shell2 && shell_[cell] < 0) {
          shell_[cell] = p;
        }
      }
    }
}

MappingChange SphereMapping::update(const ParticleView& view,
                                    const std::vector<std::uint8_t>& node_type) {
  MappingChange change;
  update(view, node_type, change);
  return change;
}

void SphereMapping::update(const ParticleView& view, const std::vector<std::uint8_t>& node_type,
                           MappingChange& change) {
  change.covered.clear();
  change.uncovered.clear();
  change.uncovered_particle.clear();
  // The lists are swapped and cleared, not freed: no allocation once they have grown.
  previous_.swap(moving_);
  moving_.clear();
  surface_.clear();
  surface_begin_.assign(view.num_total + 1, 0);
  for (std::size_t cell : previous_) owner_[cell] = -1;

  for (std::size_t p = 0; p < view.num_total; ++p) {
    const double R = view.r(p);
    for_each_local_image(view.x(p), [&](const double c[3]) { map_image(int(p), c, R, node_type, change); });
    surface_begin_[p + 1] = surface_.size();
  }
  for (std::size_t cell : previous_) {
    if (owner_[cell] < 0 && node_type[cell] == lbm::kMoving) {
      change.uncovered.push_back(cell);
      change.uncovered_particle.push_back(shell_[cell]);
    }
    shell_[cell] = -1;
  }
}

void SphereMapping::commit(const MappingChange& change, std::vector<std::uint8_t>& node_type) const {
  for (std::size_t cell : change.covered) node_type[cell] = lbm::kMoving;
  for (std::size_t cell : change.uncovered) node_type[cell] = lbm::kFluid;
}

}  // namespace coupling
