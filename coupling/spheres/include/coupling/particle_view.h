#pragma once
// The particles as the coupling sees them: a non-owning structure of arrays, so a test can
// drive the coupling with a few spheres and the LIGGGHTS fix can point it at atom->x[0],
// atom->v[0], atom->omega[0], atom->radius, atom->f[0], atom->tag without copying.
#include <array>
#include <cstddef>
#include <vector>

namespace coupling {

using Vec3 = std::array<double, 3>;

// All lengths, velocities and forces in lattice units: node (i,j,k) of the global lattice
// sits at (i,j,k). The caller converts units (coupling/units).
// Particles [0, num_owned) are owned by this rank, [num_owned, num_total) are ghosts
// (images of particles owned by other ranks or periodic images). Forces the coupling
// computes for a ghost index belong to its owner: the host sends them back (LIGGGHTS
// reverse communication); the coupling never counts one fluid link twice.
struct ParticleView {
  std::size_t num_owned = 0;
  std::size_t num_total = 0;
  const int* id = nullptr;                 // optional, for diagnostics (flux crossings)
  const double* position = nullptr;        // 3 per particle
  const double* velocity = nullptr;        // 3 per particle
  const double* angular_velocity = nullptr;  // 3 per particle; null = not rotating
  const double* radius = nullptr;          // 1 per particle

  Vec3 x(std::size_t p) const { return {position[3 * p], position[3 * p + 1], position[3 * p + 2]}; }
  Vec3 v(std::size_t p) const { return {velocity[3 * p], velocity[3 * p + 1], velocity[3 * p + 2]}; }
  Vec3 omega(std::size_t p) const {
    if (!angular_velocity) return {0.0, 0.0, 0.0};
    return {angular_velocity[3 * p], angular_velocity[3 * p + 1], angular_velocity[3 * p + 2]};
  }
  double r(std::size_t p) const { return radius[p]; }
  int identifier(std::size_t p) const { return id ? id[p] : int(p); }
  bool is_owned(std::size_t p) const { return p < num_owned; }
  // Velocity of the particle's surface point at x + offset: v + omega x offset.
  Vec3 surface_velocity(std::size_t p, const Vec3& offset) const {
    Vec3 u = v(p);
    if (angular_velocity) {
      const Vec3 w = omega(p);
      u[0] += w[1] * offset[2] - w[2] * offset[1];
      u[1] += w[2] * offset[0] - w[0] * offset[2];
      u[2] += w[0] * offset[1] - w[1] * offset[0];
    }
    return u;
  }
};

// Two particles by their index in a view, i owned, j any (owned or ghost), as a host's
// neighbour list gives them: the pair kernels (lubrication, bonds) loop over such lists.
struct ParticlePair {
  int i = 0, j = 0;
};

// An owning particle list (tests, small drivers, a host's lattice-unit copies of its atoms);
// view() exposes it. Owned particles are added before ghosts.
struct ParticleSet {
  std::size_t num_owned = 0;  // the rest are ghosts
  std::vector<int> id;
  std::vector<double> position, velocity, angular_velocity, radius;

  std::size_t size() const { return radius.size(); }
  void clear() {
    num_owned = 0;
    id.clear();
    position.clear();
    velocity.clear();
    angular_velocity.clear();
    radius.clear();
  }
  void add(int identifier, const Vec3& x, const Vec3& v, const Vec3& omega, double r,
           bool owned = true) {
    id.push_back(identifier);
    position.insert(position.end(), x.begin(), x.end());
    velocity.insert(velocity.end(), v.begin(), v.end());
    angular_velocity.insert(angular_velocity.end(), omega.begin(), omega.end());
    radius.push_back(r);
    if (owned) num_owned = size();
  }
  void add(int identifier, const Vec3& x, const Vec3& v, double r, bool owned = true) {
    add(identifier, x, v, {0.0, 0.0, 0.0}, r, owned);
  }
  void set_position(std::size_t p, const Vec3& x) {
    for (int a = 0; a < 3; ++a) position[3 * p + a] = x[a];
  }
  void set_velocity(std::size_t p, const Vec3& v) {
    for (int a = 0; a < 3; ++a) velocity[3 * p + a] = v[a];
  }
  ParticleView view(bool rotating = false) const {
    ParticleView view;
    view.num_owned = num_owned;
    view.num_total = size();
    view.id = id.data();
    view.position = position.data();
    view.velocity = velocity.data();
    view.angular_velocity = rotating ? angular_velocity.data() : nullptr;
    view.radius = radius.data();
    return view;
  }
};

}  // namespace coupling
