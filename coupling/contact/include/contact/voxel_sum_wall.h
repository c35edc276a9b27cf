#pragma once
// Particle-wall force of the paper as a sum over voxels (Jaeger et al., section II.B,
// "Particle-Wall Interaction", Eq. 6):
//   F_pw = sum_k (F_n,k + F_a,k) n_k + F_f,k t_k,
// k running over every solid voxel within reach of the particle, each voxel a static body
// with its own dash-dot repulsion (Eq. 1, stiffness k_w), adhesion F_a,k = h_k k_a R for
// 0 <= h_k <= 0.03 R (Eq. 4) and Coulomb friction (Eq. 5) with its own tangential spring.
// The per-voxel law is wall_contact_force (wall_contact.h), called once per voxel; this file
// adds the voxel geometry, the sum and the bookkeeping of one spring per voxel. So, as there,
// each voxel's friction is capped at mu N_k with N_k = k_w delta_k (the elastic part of
// F_n,k, coulomb_friction.h) while it overlaps and N_k = F_a,k while it adheres, and each
// overlapping voxel brings its own dashpot k_q.
//
// A voxel acts as a cube, not as a sphere (doc/wall_models.md has the measurements):
// - "Voxels behave like very large particles and are static": the paper's wall laws are the
//   particle-particle laws in the limit of an infinitely large, infinitely heavy partner.
//   The adhesion F_a = h k_a R_i is the cohesion h k_c R_i R_j / (R_i + R_j) with R_j -> inf,
//   and the damping k_q = 0.5 sqrt(k_w m_i) is k_d with m_j -> inf. A partner of infinite
//   radius is locally flat: the particle sees the voxel's faces, edges and corners, and the
//   gap h is measured to the voxel's cube ("h is the distance between the particle and the
//   wall"). A sphere of radius of the order of dx would contradict the R_i of Eq. 4.
// - The fluid sees the same wall: half-way bounce-back puts the LBM wall on the cube faces,
//   so with cubes the particle touches the wall where the fluid ends, as with the smooth
//   model (voxel_surface.h), which merges the same cubes.
// - It makes the flattest floor that holds: the rest height of a particle (R = 3.5 dx) varies
//   over a floor cell by 0.044 dx with cubes against 0.10 dx with spheres of radius dx/2,
//   0.62 dx or 0.87 dx (d-unit reading of the table; lattice reading 0.17 against 0.20-0.22),
//   and over a voxel's middle it touches 9 cubes, each with its own load, where on spheres
//   it rests on one sphere's top at gap 0 and is not held.
// Voxels buried under others take part whenever they are within reach (only under overlaps
// near one cell); the centre exactly inside a voxel (overlap >= R) is reported through
// max_overlap_ratio for the caller's overlap guard, with the normal pointing from the voxel's
// centre to the particle's.
//
// Voxel (i,j,k) is the cube of side `spacing` centred at origin + (i,j,k) * spacing
// (lbm::VoxelGeometry); voxels outside the geometry's box count as fluid.
#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include "contact/solid_block_map.h"
#include "contact/stability_limits.h"
#include "contact/vec3.h"
#include "contact/wall_candidates.h"
#include "contact/wall_contact.h"
#include "lbm/voxel_geometry.h"

namespace contact {

// Tangential springs remembered per particle. At rest on a flat floor a particle of radius
// 3.5 dx touches 9 voxels (both readings of the paper's table); at the overlap guard's
// warning level (5 % of R from every wall) up to 14 on a floor, 28 in an inner edge, 39 in an
// inner box corner, and for a radius 3 sigma above the mean (4.55 dx) 21, 42 and 63
// (tests/contact/test_voxel_sum_wall.cpp, ContactCountsFitTheSpringStore). 64 holds them all.
// Packed, a store is 1 + 4 * 64 = 257 doubles (2 KiB) per atom, which LIGGGHTS's per-atom
// arrays, atom migration and restart files carry easily for the few thousand particles of a
// pore scene. Contacts beyond the capacity still act this step but keep no spring (their
// friction restarts from zero); the result counts them in springs_dropped, and the caller
// must report it (the wall fix warns or stops), never ignore it.
constexpr int kVoxelSpringCapacity = 64;

struct VoxelSpring {
  std::int64_t voxel = -1;  // lbm::VoxelGeometry::index of the voxel
  Vec3 spring;              // tangential spring of coulomb_friction.h
};

// Only slots[0..count) mean anything, so a copy copies only those: the voxel sum replaces every
// touching particle's store every DEM step and uses 9-20 of its 64 slots (2 KiB).
struct VoxelSpringStore {
  std::array<VoxelSpring, kVoxelSpringCapacity> slots;
  int count = 0;  // slots[0..count) are in use

  VoxelSpringStore() = default;
  VoxelSpringStore(const VoxelSpringStore& other) { *this = other; }
  VoxelSpringStore& operator=(const VoxelSpringStore& other) {
    count = other.count;
    std::copy(other.slots.begin(), other.slots.begin() + count, slots.begin());
    return *this;
  }

  // The stored spring of `voxel`, or null for a new contact.
  const Vec3* find(std::int64_t voxel) const;
  // The same, searching from slot `hint` on (and round to it), and leaving `hint` at the slot
  // after the one found: a particle's contacts come in the same order every step, so the next
  // one is usually there. Voxels are unique in a store, so the answer is find's.
  const Vec3* find(std::int64_t voxel, int& hint) const;
  // False (nothing stored) when the store is full.
  bool add(std::int64_t voxel, Vec3 spring);
};

// Flat double buffer of a store for LIGGGHTS per-atom arrays and restart files:
// [count, then per slot: voxel index, spring x, y, z]; unused slots are written as zeros.
// Voxel indices are exact as doubles below 2^53 voxels.
constexpr std::size_t kPackedSpringStoreSize = 1 + 4 * kVoxelSpringCapacity;
void pack_spring_store(const VoxelSpringStore& store, double* out);
// False, leaving `store` empty, when the buffer is not a packed store (count out of range,
// a voxel index that is negative or not an integer): a corrupt restart, for the caller to
// report.
bool unpack_spring_store(const double* in, VoxelSpringStore& store);

struct VoxelSumInput {
  explicit VoxelSumInput(const lbm::VoxelGeometry& voxels) : geometry(voxels) {}

  const lbm::VoxelGeometry& geometry;
  Vec3 centre;
  double radius = 0.0;
  double mass = 0.0;
  Vec3 velocity;  // the wall is at rest
  double dt = 0.0;
  const VoxelSpringStore* springs = nullptr;  // last step's; null = no history
  // Optional block map of `geometry`: a particle whose voxel box touches no solid block (in
  // open fluid) returns at once instead of scanning its (2 reach + 1)^3 voxels, and the scan
  // visits only the solid runs of each row. The result is the same with or without it.
  const SolidBlockMap* blocks = nullptr;
  // Optional per-particle list of the voxels in reach (wall_candidates.h), rebuilt here when
  // the particle has left its skin. The result is the same with or without it.
  WallCandidates* candidates = nullptr;
};

struct VoxelSumResult {
  Vec3 force;                      // F_pw on the particle
  VoxelSpringStore springs;        // one per active contact, for the next step
  int contacts = 0;                // voxels overlapping or adhering this step
  int sliding = 0;                 // of those, how many slide (friction at the Coulomb limit)
  int springs_dropped = 0;         // active contacts that found no room in `springs`
  double max_overlap_ratio = 0.0;  // largest voxel overlap / R (0 when none overlaps)
};

// The sum of Eq. 6 over the solid voxels within wall_contact_reach of the particle.
VoxelSumResult voxel_sum_wall_force(const WallContactParams& params, const VoxelSumInput& in);
// The same into a result the caller keeps between calls (every member overwritten): a result
// holds a 64-slot spring store, and constructing one per particle per DEM step cost more than
// the few springs it receives. `out.springs` must not be `*in.springs`.
void voxel_sum_wall_force(const WallContactParams& params, const VoxelSumInput& in,
                          VoxelSumResult& out);

// Normal stiffness of a particle of this radius resting on a flat voxel floor: the voxel
// under it (k_w, Eq. 1) and the 8 around it within the adhesion range, each adding k_a R
// (the slope of F_a = h k_a R, Eq. 4). k_w alone underestimates it: 0.1 + 8 x 0.35 = 29 k_w
// in the lattice reading of the paper's table, 5 k_w in the d-unit reading (R = 3.5 cells).
double voxel_sum_resting_stiffness(const WallContactParams& params, double radius);

// The wall's time step limit for the voxel sum: t_c / 10 of the stiffer of that resting
// stiffness and k_t, on the particle's mass.
TimeStepLimit voxel_sum_time_step_limit(const WallContactParams& params, double radius,
                                        double mass);

// Distance from `centre` to the cube of voxel (i,j,k), and the unit normal from the cube's
// closest point to the centre (from the voxel's centre when the centre is inside the cube).
struct VoxelDistance {
  double distance = 0.0;
  Vec3 normal;
};
VoxelDistance distance_to_voxel(const lbm::VoxelGeometry& geometry, Vec3 centre, int i, int j,
                                int k);
// The same from the centre's lattice coordinates u = (centre - origin) / spacing, which a
// caller measuring one centre against many voxels computes once.
VoxelDistance distance_to_voxel(double spacing, const double u[3], int i, int j, int k);

}  // namespace contact
