#include "coupling/lubrication/lubrication.h"

#include <algorithm>
#include <cmath>

#include "lbm/input_error.h"

namespace coupling {

LubricationCorrection::LubricationCorrection(const LubricationParameters& p) : parameters_(p) {
  if (!(p.cutoff > 0.0))
    throw lbm::InputError("lubrication: cutoff = " + std::to_string(p.cutoff) + ", must be > 0 cells");
  if (!(p.roughness > 0.0) || !(p.roughness < 1.0))
    throw lbm::InputError("lubrication: roughness = " + std::to_string(p.roughness) +
                          ", must be in (0, 1) radii");
  if (!(p.nu > 0.0) || !(p.rho > 0.0))
    throw lbm::InputError("lubrication: rho and nu must be > 0");
}

double LubricationCorrection::magnitude(double a, double h, double v, double R_min) const {
  const double hc = parameters_.cutoff;
  if (h >= hc) return 0.0;
  const double h_min = std::min(parameters_.roughness * R_min, 0.5 * hc);
  h = std::max(h, h_min);
  constexpr double kPi = 3.14159265358979323846;
  return 6.0 * kPi * parameters_.rho * parameters_.nu * a * a * v * (1.0 / h - 1.0 / hc);
}

Vec3 LubricationCorrection::pair_force(double Ri, double Rj, const Vec3& d, const Vec3& vi,
                                       const Vec3& vj) const {
  return pair_force(Ri, Rj, d, std::sqrt(dot(d, d)), vi, vj);
}

Vec3 LubricationCorrection::pair_force(double Ri, double Rj, const Vec3& d, double dist,
                                       const Vec3& vi, const Vec3& vj) const {
  if (!(dist > 0.0)) return {0.0, 0.0, 0.0};
  const double h = dist - Ri - Rj;
  if (h >= parameters_.cutoff) return {0.0, 0.0, 0.0};
  const Vec3 n{d[0] / dist, d[1] / dist, d[2] / dist};
  const double approach = dot(Vec3{vi[0] - vj[0], vi[1] - vj[1], vi[2] - vj[2]}, n);
  const double F = magnitude(Ri * Rj / (Ri + Rj), h, approach, std::min(Ri, Rj));
  return {-F * n[0], -F * n[1], -F * n[2]};
}

Vec3 LubricationCorrection::wall_force(double R, const Vec3& v, const WallDistance& wall) const {
  const double h = wall.distance - R;
  if (!(h < parameters_.cutoff)) return {0.0, 0.0, 0.0};
  const double approach = -dot(v, wall.normal);
  const double F = magnitude(R, h, approach, R);
  return {F * wall.normal[0], F * wall.normal[1], F * wall.normal[2]};
}

void LubricationCorrection::add_forces(const ParticleView& view, const PeriodicBox& box,
                                       const WallDistanceFunction& wall, double* force) const {
  for (std::size_t i = 0; i < view.num_owned; ++i) {
    const Vec3 xi = view.x(i), vi = view.v(i);
    const double Ri = view.r(i);
    Vec3 total{0.0, 0.0, 0.0};
    for (std::size_t j = 0; j < view.num_total; ++j) {
      if (j == i) continue;
      const Vec3 d = box.displacement(xi, view.x(j));
      const double reach = Ri + view.r(j) + parameters_.cutoff;
      if (dot(d, d) >= reach * reach) continue;
      const Vec3 F = pair_force(Ri, view.r(j), d, vi, view.v(j));
      for (int a = 0; a < 3; ++a) total[a] += F[a];
    }
    if (wall) {
      const Vec3 F = wall_force(Ri, vi, wall(xi));
      for (int a = 0; a < 3; ++a) total[a] += F[a];
    }
    for (int a = 0; a < 3; ++a) force[3 * i + a] += total[a];
  }
}

WallDistanceFunction plane_wall(const Vec3& point, const Vec3& normal) {
  const double len = std::sqrt(dot(normal, normal));
  const Vec3 n{normal[0] / len, normal[1] / len, normal[2] / len};
  return [point, n](const Vec3& x) {
    WallDistance w;
    w.distance = dot(Vec3{x[0] - point[0], x[1] - point[1], x[2] - point[2]}, n);
    w.normal = n;
    return w;
  };
}

}  // namespace coupling
