#include "contact/voxel_sum_wall.h"

#include <algorithm>
#include <cmath>

namespace contact {

const Vec3* VoxelSpringStore::find(std::int64_t voxel) const {
  for (int s = 0; s < count; ++s)
    if (slots[s].voxel == voxel) return &slots[s].spring;
  return nullptr;
}

const Vec3* VoxelSpringStore::find(std::int64_t voxel, int& hint) const {
  for (int n = 0, s = hint < count ? hint : 0; n < count; ++n, s = s + 1 < count ? s + 1 : 0)
    if (slots[s].voxel == voxel) {
      hint = s + 1;
      return &slots[s].spring;
    }
  return nullptr;
}

bool VoxelSpringStore::add(std::int64_t voxel, Vec3 spring) {
  if (count >= kVoxelSpringCapacity) return false;
  slots[count].voxel = voxel;
  slots[count].spring = spring;
  ++count;
  return true;
}

void pack_spring_store(const VoxelSpringStore& store, double* out) {
  std::fill(out, out + kPackedSpringStoreSize, 0.0);
  out[0] = store.count;
  for (int s = 0; s < store.count; ++s) {
    double* slot = out + 1 + 4 * s;
    slot[0] = static_cast<double>(store.slots[s].voxel);
    slot[1] = store.slots[s].spring.x;
    slot[2] = store.slots[s].spring.y;
    slot[3] = store.slots[s].spring.z;
  }
}

bool unpack_spring_store(const double* in, VoxelSpringStore& store) {
  store = VoxelSpringStore{};
  const double count = in[0];
  if (!(count >= 0.0 && count <= kVoxelSpringCapacity) || count != std::floor(count)) return false;
  VoxelSpringStore read;
  for (int s = 0; s < static_cast<int>(count); ++s) {
    const double* slot = in + 1 + 4 * s;
    if (!(slot[0] >= 0.0) || slot[0] != std::floor(slot[0])) return false;
    read.add(static_cast<std::int64_t>(slot[0]), Vec3{slot[1], slot[2], slot[3]});
  }
  store = read;
  return true;
}

VoxelDistance distance_to_voxel(const lbm::VoxelGeometry& geometry, Vec3 centre, int i, int j,
                                int k) {
  const double spacing = geometry.spacing();
  const auto& origin = geometry.origin();
  double u[3];
  for (int a = 0; a < 3; ++a) u[a] = (centre[a] - origin[a]) / spacing;
  return distance_to_voxel(spacing, u, i, j, k);
}

VoxelDistance distance_to_voxel(double spacing, const double u[3], int i, int j, int k) {
  // Lattice coordinates: the cube of voxel (i,j,k) spans [i - 1/2, i + 1/2] (and so on).
  const int cell[3] = {i, j, k};
  Vec3 offset;  // from the cube's closest point to the centre, in cells
  Vec3 from_voxel_centre;
  for (int a = 0; a < 3; ++a) {
    const double closest = std::clamp(u[a], cell[a] - 0.5, cell[a] + 0.5);
    offset[a] = u[a] - closest;
    from_voxel_centre[a] = u[a] - cell[a];
  }
  VoxelDistance out;
  const double length = norm(offset);
  if (length > 0.0) {
    out.distance = length * spacing;
    out.normal = (1.0 / length) * offset;
    return out;
  }
  // Centre inside (or on) the cube: push it out the way it came, away from the voxel centre.
  const double from_centre = norm(from_voxel_centre);
  out.normal = from_centre > 0.0 ? (1.0 / from_centre) * from_voxel_centre : Vec3{0.0, 0.0, 1.0};
  return out;
}

namespace {

// Voxels whose cube can come within `reach` of the centre at lattice coordinates u (cubes
// centred on their voxel): |u - i| <= reach + 1/2 along every axis, clamped to the geometry.
struct VoxelBox {
  int lo[3], hi[3];
  bool empty = false;

  VoxelBox(const lbm::VoxelGeometry& geometry, const double u[3], double reach_cells) {
    for (int a = 0; a < 3; ++a) {
      lo[a] = std::max(0, static_cast<int>(std::ceil(u[a] - reach_cells - 0.5)));
      hi[a] = std::min(geometry.dims()[a] - 1, static_cast<int>(std::floor(u[a] + reach_cells + 0.5)));
      empty = empty || lo[a] > hi[a];
    }
  }
  bool contains(const std::array<int, 3>& cell) const {
    for (int a = 0; a < 3; ++a)
      if (cell[a] < lo[a] || cell[a] > hi[a]) return false;
    return true;
  }
};

// The cull of voxels beyond reach by their per-axis gaps (below): squared, in cells, with a
// margin far above the rounding of both it and the exact distance.
double culled_beyond(double reach_cells) { return reach_cells * reach_cells * (1.0 + 1e-9); }
// squared_gap_to_cell's voxel spans [cell, cell + 1): here the cube is centred on the cell.
double squared_gap(double coordinate, int cell) { return squared_gap_to_cell(coordinate + 0.5, cell); }

// Calls visit(i, j, k) for every solid voxel of the box that may lie within `reach` of the
// centre at lattice coordinates u, in increasing k, j, i.
template <class Visit>
void for_each_solid_voxel_near(const lbm::VoxelGeometry& geometry, const SolidBlockMap* blocks,
                               const double u[3], double reach, Visit&& visit) {
  const double reach_cells = reach / geometry.spacing();
  const VoxelBox box(geometry, u, reach_cells);
  if (box.empty) return;
  const int* lo = box.lo;
  const int* hi = box.hi;
  if (blocks != nullptr && !blocks->any_solid(lo, hi)) return;
  // The box holds (2 reach + 1)^3 voxels, the ball within reach about half of them, and near a
  // flat wall only a few of its solid ones: skip the voxels whose cube is beyond reach by its
  // per-axis gaps alone (squared, in cells), before the caller's exact distance. The margin is
  // far above the rounding of both, so every voxel the exact test keeps is still visited, in
  // the same order: the sum is bit-identical to scanning the whole box.
  const double beyond = culled_beyond(reach_cells);
  for (int k = lo[2]; k <= hi[2]; ++k) {
    const double gap_z = squared_gap(u[2], k);
    if (gap_z > beyond) continue;
    for (int j = lo[1]; j <= hi[1]; ++j) {
      const double gap_yz = gap_z + squared_gap(u[1], j);
      if (gap_yz > beyond) continue;
      // The row's cells within the remaining reach, one more on each side against rounding.
      const double half_chord = std::sqrt(beyond - gap_yz) + 0.5;
      const int first = std::max(lo[0], static_cast<int>(std::ceil(u[0] - half_chord)) - 1);
      const int last = std::min(hi[0], static_cast<int>(std::floor(u[0] + half_chord)) + 1);
      const auto in_reach = [&](int i) {
        if (gap_yz + squared_gap(u[0], i) <= beyond) visit(i, j, k);
      };
      if (blocks == nullptr) {
        for (int i = first; i <= last; ++i)
          if (geometry.is_solid(i, j, k)) in_reach(i);
      } else {
        blocks->for_each_solid_in_row(j, k, first, last, in_reach);
      }
    }
  }
}

}  // namespace

VoxelSumResult voxel_sum_wall_force(const WallContactParams& params, const VoxelSumInput& in) {
  VoxelSumResult out;
  voxel_sum_wall_force(params, in, out);
  return out;
}

void voxel_sum_wall_force(const WallContactParams& params, const VoxelSumInput& in,
                          VoxelSumResult& out) {
  out.force = Vec3{};
  out.springs.count = 0;
  out.contacts = out.sliding = out.springs_dropped = 0;
  out.max_overlap_ratio = 0.0;
  const lbm::VoxelGeometry& geometry = in.geometry;
  const double spacing = geometry.spacing();
  const auto& origin = geometry.origin();
  const double reach = wall_contact_reach(params, in.radius);
  // The centre in lattice coordinates, as distance_to_voxel computes it: three divisions,
  // computed only for a particle that has a wall to search (or a list to rebuild).
  double u[3];
  const auto find_lattice_coordinates = [&] {
    for (int a = 0; a < 3; ++a) u[a] = (in.centre[a] - origin[a]) / spacing;
  };
  // A particle whose candidate list (built with a skin) is empty has no wall in reach: the
  // particles in open fluid, most of them, cost one distance test.
  WallCandidates* const candidates = in.candidates;
  if (candidates != nullptr) {
    if (!candidates->covers(in.centre, reach)) {
      find_lattice_coordinates();
      candidates->restart(in.centre, reach + kWallCandidateSkin * spacing);
      for_each_solid_voxel_near(geometry, in.blocks, u, candidates->reach,
                                [&](int i, int j, int k) { candidates->voxels.push_back({i, j, k}); });
    }
    if (candidates->voxels.empty()) return;
  }
  find_lattice_coordinates();
  const bool keep_springs = params.friction.mu > 0.0;
  // What the law needs of the particle alone, once for all its voxels.
  const WallParticleTerms terms = wall_particle_terms(params, in.radius, in.mass);
  int spring_hint = 0;  // where the next voxel's spring of last step probably is
  // Eq. 6's term of solid voxel (i, j, k), if it is within reach.
  const auto add_voxel = [&](int i, int j, int k) {
    const VoxelDistance voxel = distance_to_voxel(spacing, u, i, j, k);
    if (voxel.distance > reach) return;
    const auto key = static_cast<std::int64_t>(geometry.index(i, j, k));
    const Vec3* stored = in.springs != nullptr ? in.springs->find(key, spring_hint) : nullptr;

    WallContactInput contact;
    contact.normal = voxel.normal;
    contact.gap = voxel.distance - in.radius;
    contact.radius = in.radius;
    contact.mass = in.mass;
    contact.velocity = in.velocity;
    contact.spring = stored != nullptr ? *stored : Vec3{};
    contact.dt = in.dt;
    const WallContactResult result = wall_contact_force(params, terms, contact);
    if (!result.active) return;
    out.force += result.force;
    ++out.contacts;
    if (result.sliding) ++out.sliding;
    out.max_overlap_ratio = std::max(out.max_overlap_ratio, -contact.gap / in.radius);
    if (keep_springs && !out.springs.add(key, result.spring)) ++out.springs_dropped;
  };
  if (candidates == nullptr) {
    for_each_solid_voxel_near(geometry, in.blocks, u, reach, add_voxel);
    return;
  }
  // The voxels of this query's own box that pass the scan's cull, as the scan would see them
  // (the list holds those of reach + skin: most of its voxels are beyond reach now, and the
  // cull drops them before the exact distance's square root and division).
  const VoxelBox box(geometry, u, reach / spacing);
  if (box.empty) return;
  const double beyond = culled_beyond(reach / spacing);
  for (const auto& v : candidates->voxels)
    if (box.contains(v) &&
        squared_gap(u[2], v[2]) + squared_gap(u[1], v[1]) + squared_gap(u[0], v[0]) <= beyond)
      add_voxel(v[0], v[1], v[2]);
}

double voxel_sum_resting_stiffness(const WallContactParams& params, double radius) {
  constexpr int kAdheringNeighbours = 8;  // the ring around the voxel under the centre
  return params.normal.k_n + kAdheringNeighbours * params.adhesion.k_a * radius;
}

TimeStepLimit voxel_sum_time_step_limit(const WallContactParams& params, double radius,
                                        double mass) {
  DashDotParams stiffest = params.normal;
  stiffest.k_n = std::max(voxel_sum_resting_stiffness(params, radius), params.friction.k_t);
  return time_step_limit(stiffest, mass);
}

}  // namespace contact
