#include "coupling/mapping/sphere_mapping.h"

#include <algorithm>
#include <cmath>

#include "lbm/node_type.h"

namespace coupling {

SphereMapping::SphereMapping(const lbm::BlockLayout& layout, const PeriodicBox& box)
    : layout_(layout), box_(box), owner_(layout.num_cells(), -1), shell_(layout.num_cells(), -1) {}

Vec3 SphereMapping::node_position(std::size_t cell) const {
  const auto c = layout_.coords(cell);
  const auto g = layout_.to_global(c[0], c[1], c[2]);
  return {double(g[0]), double(g[1]), double(g[2])};
}

MappingChange SphereMapping::update(const ParticleView& view,
                                    const std::vector<std::uint8_t>& node_type) {
  MappingChange change;
  const std::vector<std::size_t> previous = std::move(moving_);
  moving_.clear();
  for (std::size_t cell : previous) owner_[cell] = -1;

  const auto& lo = layout_.owned().lo;
  const int n[3] = {layout_.size(0), layout_.size(1), layout_.size(2)};
  for (std::size_t p = 0; p < view.num_total; ++p) {
    const Vec3 centre = view.x(p);
    const double R = view.r(p);
    const double R2 = R * R;
    // A sphere moves less than a cell per fluid step, so the nodes it just left lie in
    // the shell R <= d < R + 1.5 (recorded for the refill's wall velocity).
    const double shell2 = (R + 1.5) * (R + 1.5);
    // Periodic images -L, 0, +L on periodic axes; only those reaching this block matter.
    int shifts[3][3], num_shifts[3];
    for (int a = 0; a < 3; ++a) {
      num_shifts[a] = 0;
      for (int s = -1; s <= 1; ++s) {
        if (s != 0 && !box_.periodic[a]) continue;
        shifts[a][num_shifts[a]++] = s;
      }
    }
    for (int sz = 0; sz < num_shifts[2]; ++sz)
      for (int sy = 0; sy < num_shifts[1]; ++sy)
        for (int sx = 0; sx < num_shifts[0]; ++sx) {
          const int s[3] = {shifts[0][sx], shifts[1][sy], shifts[2][sz]};
          double c[3];
          int from[3], to[3];
          bool empty = false;
          for (int a = 0; a < 3; ++a) {
            c[a] = centre[a] + s[a] * box_.length[a] - lo[a];  // local coordinates
            from[a] = std::max(-1, int(std::floor(c[a] - R - 1.5)));
            to[a] = std::min(n[a], int(std::ceil(c[a] + R + 1.5)));
            if (from[a] > to[a]) empty = true;
          }
          if (empty) continue;
          for (int k = from[2]; k <= to[2]; ++k)
            for (int j = from[1]; j <= to[1]; ++j)
              for (int i = from[0]; i <= to[0]; ++i) {
                const double dx = i - c[0], dy = j - c[1], dz = k - c[2];
                const double d2 = dx * dx + dy * dy + dz * dz;
                const std::size_t cell = layout_.cell(i, j, k);
                const std::uint8_t type = node_type[cell];
                if (type != lbm::kFluid && type != lbm::kMoving) continue;
                if (d2 < R2) {
                  if (owner_[cell] >= 0) continue;
                  owner_[cell] = int(p);
                  moving_.push_back(cell);
                  if (type == lbm::kFluid) change.covered.push_back(cell);
                } else if (type == lbm::kMoving && d2 < shell2 && shell_[cell] < 0) {
                  shell_[cell] = int(p);
                }
              }
        }
  }
  for (std::size_t cell : previous) {
    if (owner_[cell] < 0 && node_type[cell] == lbm::kMoving) {
      change.uncovered.push_back(cell);
      change.uncovered_particle.push_back(shell_[cell]);
    }
    shell_[cell] = -1;
  }
  return change;
}

void SphereMapping::commit(const MappingChange& change, std::vector<std::uint8_t>& node_type) const {
  for (std::size_t cell : change.covered) node_type[cell] = lbm::kMoving;
  for (std::size_t cell : change.uncovered) node_type[cell] = lbm::kFluid;
}

}  // namespace coupling
