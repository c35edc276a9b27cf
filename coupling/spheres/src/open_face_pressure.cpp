#include "coupling/force/open_face_pressure.h"

#include <algorithm>
#include <cmath>
#include <optional>
#include <vector>

#include "coupling/boundary/sphere_links.h"
#include "lbm/d3q19.h"

namespace coupling {

namespace {
using L = lbm::D3Q19;

// Global node coordinate `x` on axis a brought onto the lattice: wrapped on a periodic axis,
// clamped onto the nearest plane otherwise (beyond an open face: the face's plane).
int onto_lattice(int x, int a, const lbm::Decomposition& d) {
  const int n = d.global.size(a);
  if (d.periodic[std::size_t(a)]) return ((x % n) + n) % n;
  return std::clamp(x, 0, n - 1);
}

struct FaceLinks {
  const lbm::FluidSolver& solver;
  const lbm::OpenFace& face;
  int side;  // 0 inlet (the lattice's lower end along the drive axis), 1 outlet
  double rho_gauge;

  // The links of sphere p (centre c, radius R) that cross this face: from a node x outside
  // the sphere to x + c_q inside it (the mapping's test, |.|^2 < R^2), with x or x + c_q
  // beyond the face. Their pushes appended to `pushes`; returns how many links.
  std::size_t add(std::size_t p, const Vec3& c, double R, std::vector<OpenFacePush>& pushes) const {
    const lbm::Decomposition& d = solver.decomposition();
    const lbm::BlockLayout& layout = solver.layout();
    const int a = face.axis;
    const int last = d.global.size(a) - 1;
    int from[3], to[3];
    for (int k = 0; k < 3; ++k) {
      from[k] = int(std::floor(c[k] - R - 1.0));
      to[k] = int(std::ceil(c[k] + R + 1.0));
    }
    // A link crosses the face only if one of its ends lies beyond it: x beyond, or x on the
    // face's plane and x + c_q beyond.
    if (side == 0) to[a] = std::min(to[a], 0);
    else from[a] = std::max(from[a], last);
    const double R2 = R * R;
    const double beyond_links = (R + 1.5) * (R + 1.5);
    std::size_t added = 0;
    int x[3];
    for (x[2] = from[2]; x[2] <= to[2]; ++x[2])
      for (x[1] = from[1]; x[1] <= to[1]; ++x[1])
        for (x[0] = from[0]; x[0] <= to[0]; ++x[0]) {
          const Vec3 dx{x[0] - c[0], x[1] - c[1], x[2] - c[2]};
          const double dx2 = dot(dx, dx);
          if (dx2 < R2) continue;  // inside: no link starts here
          // Farther than R + |c_q| (at most sqrt 2) from the centre: no link reaches inside.
          if (dx2 >= beyond_links) continue;
          for (int q = 1; q < L::Q; ++q) {
            const Vec3 dw{dx[0] + L::c[q][0], dx[1] + L::c[q][1], dx[2] + L::c[q][2]};
            if (!(dot(dw, dw) < R2)) continue;
            const int xa = x[a], wa = x[a] + L::c[q][a];
            const bool beyond = side == 0 ? (xa < 0 || wa < 0) : (xa > last || wa > last);
            if (!beyond) continue;
            // The face node the link is nearest to, on the lattice; counted where it is owned.
            int local[3];
            bool owned = true;
            for (int k = 0; k < 3; ++k) {
              local[k] = onto_lattice(x[k], k, d) - d.owned.lo[k];
              owned = owned && local[k] >= 0 && local[k] < layout.size(k);
            }
            if (!owned) continue;
            const double rho_f = face.kind == lbm::OpenFace::kDensity
                                     ? face.value
                                     : solver.open_face_density(layout.cell(local[0], local[1], local[2]));
            const double push = 2.0 * L::w[q] * (rho_f - rho_gauge);
            ++added;
            if (push == 0.0) continue;
            const Vec3 F{push * L::c[q][0], push * L::c[q][1], push * L::c[q][2]};
            const double s = link_fraction(dx, L::c[q], R);
            const Vec3 arm{dx[0] + s * L::c[q][0], dx[1] + s * L::c[q][1], dx[2] + s * L::c[q][2]};
            pushes.push_back({p, F, cross(arm, F)});
          }
        }
    return added;
  }
};
}  // namespace

std::size_t record_open_face_pressure(const ParticleView& view, const lbm::FluidSolver& solver,
                                      double rho_gauge, std::vector<OpenFacePush>& pushes) {
  pushes.clear();
  const std::optional<lbm::OpenFace> faces[2] = {solver.open_face(0), solver.open_face(1)};
  if (!faces[0] && !faces[1]) return 0;  // this rank holds neither face
  const int a = solver.drive().axis;
  const int last = solver.decomposition().global.size(a) - 1;
  std::vector<int> seen;  // the particles near a face already taken (a periodic image repeats one)
  std::size_t added = 0;
  for (std::size_t p = 0; p < view.num_total; ++p) {
    const Vec3 c = view.x(p);
    const double R = view.r(p);
    // Its links reach a node beyond the face only within R + 1 of it.
    const bool near[2] = {faces[0] && c[a] - R - 1.0 < 0.0, faces[1] && c[a] + R + 1.0 > double(last)};
    if (!near[0] && !near[1]) continue;
    const int id = view.identifier(p);
    if (std::find(seen.begin(), seen.end(), id) != seen.end()) continue;
    seen.push_back(id);
    for (int side = 0; side < 2; ++side)
      if (near[side])
        added += FaceLinks{solver, *faces[side], side, rho_gauge}.add(p, c, R, pushes);
  }
  return added;
}

void add_open_face_pushes(const std::vector<OpenFacePush>& pushes, HydrodynamicLoads& loads) {
  for (const OpenFacePush& push : pushes)
    for (int k = 0; k < 3; ++k) {
      loads.force[push.particle][k] += push.force[k];
      loads.torque[push.particle][k] += push.torque[k];
    }
}

std::size_t add_open_face_pressure(const ParticleView& view, const lbm::FluidSolver& solver,
                                   double rho_gauge, HydrodynamicLoads& loads) {
  std::vector<OpenFacePush> pushes;
  const std::size_t added = record_open_face_pressure(view, solver, rho_gauge, pushes);
  add_open_face_pushes(pushes, loads);
  return added;
}

}  // namespace coupling
