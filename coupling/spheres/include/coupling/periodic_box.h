#pragma once
#include <array>
#include <cmath>

#include "coupling/particle_view.h"
#include "lbm/decomposition.h"

namespace coupling {

// The global lattice box and its periodic axes: minimum-image displacements, so a serial
// periodic run needs no ghost images of particles. With the host's ghost images present
// (LIGGGHTS), the owner is mapped first and wins; the images then add nothing.
struct PeriodicBox {
  Vec3 length{0.0, 0.0, 0.0};
  std::array<bool, 3> periodic{false, false, false};

  static PeriodicBox from(const lbm::Decomposition& d) {
    PeriodicBox box;
    for (int a = 0; a < 3; ++a) box.length[a] = d.global.size(a);
    box.periodic = d.periodic;
    return box;
  }
  // b - a, wrapped to the nearest image on periodic axes. Within a quarter of the length the
  // wrap is zero (the rounded quotient is 0 even after the division's round-off), so the
  // division and rounding are skipped there: the same values, for a fraction of the cost.
  Vec3 displacement(const Vec3& a, const Vec3& b) const {
    Vec3 d{b[0] - a[0], b[1] - a[1], b[2] - a[2]};
    for (int k = 0; k < 3; ++k)
      if (periodic[k] && std::abs(d[k]) >= 0.25 * length[k])
        d[k] -= length[k] * std::round(d[k] / length[k]);
    return d;
  }
};

inline double dot(const Vec3& a, const Vec3& b) { return a[0] * b[0] + a[1] * b[1] + a[2] * b[2]; }
inline Vec3 cross(const Vec3& a, const Vec3& b) {
  return {a[1] * b[2] - a[2] * b[1], a[2] * b[0] - a[0] * b[2], a[0] * b[1] - a[1] * b[0]};
}

}  // namespace coupling
