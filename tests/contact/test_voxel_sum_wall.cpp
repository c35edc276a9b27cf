// The paper's voxel-sum wall (contact/voxel_sum_wall.h) against sums this file computes on its
// own: its own distance to a voxel, its own force law, root solves for rest positions. Run
// for both readings of the paper's parameter table (doc/paper_units.md): the coefficients in
// lattice units (k_w = k_a = 0.1) and in d-units with d = 7 cells (k_w = 0.1 * 7^3 = 34.3,
// k_a = 0.1 * 7^2 = 4.9), with R = 3.5 cells, rho_p = 2.3, mu = 0.1. The thresholds each test
// prints ("[voxel_sum]" lines) are the figures quoted in doc/wall_models.md.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "contact/voxel_sum_wall.h"

using namespace contact;

namespace {

constexpr double kPi = 3.14159265358979323846;
constexpr double kRadius = 3.5;   // d = 7 cells
constexpr double kDensity = 2.3;  // rho_p, fluid density 1
constexpr double kMu = 0.1;
constexpr double kRange = 0.03;  // adhesion range / R (Eq. 4)

struct Reading {
  const char* name;
  double k_w, k_a;
};
const Reading kLatticeReading{"lattice", 0.1, 0.1};
const Reading kDUnitReading{"d-unit", 0.1 * 7 * 7 * 7, 0.1 * 7 * 7};

double particle_mass(double radius) { return kDensity * 4.0 / 3.0 * kPi * std::pow(radius, 3); }

WallContactParams paper_params(const Reading& reading) {
  WallContactParams p;
  p.normal.k_n = reading.k_w;
  p.normal.damping_ratio = 0.25;  // k_q = 0.5 sqrt(k_w m_i)
  p.adhesion.k_a = reading.k_a;
  p.friction.mu = kMu;
  p.friction.k_t = 2.0 / 7.0 * reading.k_w;
  p.friction.damping_ratio = 0.25;
  return p;
}

// A floor of two voxel layers (k = 0, 1) in a 24 x 24 x 8 box of unit cells: the floor's top
// face is the plane z = 1.5.
constexpr double kFloorTop = 1.5;
lbm::VoxelGeometry floor_geometry() {
  lbm::VoxelGeometry g({24, 24, 8});
  for (int k = 0; k <= 1; ++k)
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i < 24; ++i) g.set_solid(i, j, k, true);
  return g;
}

// ---- Reference sums, written independently of the library -------------------------------

enum class VoxelShape { cube, sphere };

struct ReferenceContact {
  Vec3 normal;  // from the voxel to the centre
  double gap;   // distance minus R
};

// Distance from `c` (unit cells, origin 0) to voxel (i,j,k): to its cube [i +- 1/2]^3, or to
// a sphere of radius `sphere_radius` around its node.
ReferenceContact reference_contact(Vec3 c, int i, int j, int k, VoxelShape shape,
                                   double sphere_radius) {
  const double node[3] = {double(i), double(j), double(k)};
  Vec3 d;
  for (int a = 0; a < 3; ++a) {
    const double from_node = c[a] - node[a];
    d[a] = shape == VoxelShape::sphere
               ? from_node
               : std::copysign(std::max(std::fabs(from_node) - 0.5, 0.0), from_node);
  }
  const double length = std::sqrt(d.x * d.x + d.y * d.y + d.z * d.z);
  const double surface = shape == VoxelShape::sphere ? length - sphere_radius : length;
  return {(1.0 / length) * d, surface - kRadius};
}

// Conservative normal force of one voxel, repulsive positive: k_w delta when overlapping,
// -h k_a R within the adhesion range (Eqs. 1 and 4).
double reference_normal_force(const Reading& r, double gap) {
  if (gap < 0.0) return -r.k_w * gap;
  if (gap <= kRange * kRadius) return -gap * r.k_a * kRadius;
  return 0.0;
}

struct ReferenceSum {
  Vec3 normal_force;    // sum of the voxels' normal forces
  Vec3 friction_force;  // every contact at its Coulomb limit against `slide` (zero if none)
  double friction_capacity = 0.0;  // sum of mu (|F_n,k| + F_a,k)
  int contacts = 0;
};

ReferenceSum reference_sum(const lbm::VoxelGeometry& g, const Reading& r, Vec3 c, Vec3 slide,
                           VoxelShape shape = VoxelShape::cube, double sphere_radius = 0.0) {
  ReferenceSum sum;
  for (int k = int(c.z) - 6; k <= int(c.z) + 6; ++k)  // is_solid is false outside the box
    for (int j = int(c.y) - 6; j <= int(c.y) + 6; ++j)
      for (int i = int(c.x) - 6; i <= int(c.x) + 6; ++i) {
        if (!g.is_solid(i, j, k)) continue;
        const ReferenceContact contact = reference_contact(c, i, j, k, shape, sphere_radius);
        if (contact.gap > kRange * kRadius) continue;
        const double f = reference_normal_force(r, contact.gap);
        sum.normal_force += f * contact.normal;
        sum.friction_capacity += kMu * std::fabs(f);
        ++sum.contacts;
        const Vec3 t = slide - dot(slide, contact.normal) * contact.normal;
        if (norm(t) > 0.0) sum.friction_force -= (kMu * std::fabs(f) / norm(t)) * t;
      }
  return sum;
}

// Height z of the centre above (x, y) where the voxels carry the load W (pushing down) with
// every contact sliding against `slide`, reached from z_from the way a slowly moved particle
// gets there: up while the net force pushes up, down while it pulls down, to the first stable
// balance (between the heights where a voxel enters or leaves the adhesion range the net
// upward force falls as z rises). Returns NaN if there is none within 2 cells.
double balanced_height(const lbm::VoxelGeometry& g, const Reading& r, double x, double y,
                       double load, Vec3 slide, double z_from, VoxelShape shape = VoxelShape::cube,
                       double sphere_radius = 0.0) {
  const auto pushed_up = [&](double z) {
    const ReferenceSum s = reference_sum(g, r, {x, y, z}, slide, shape, sphere_radius);
    return s.normal_force.z + s.friction_force.z - load > 0.0;
  };
  const bool up = pushed_up(z_from);
  const double step = up ? 2e-4 : -2e-4;
  for (double z = z_from; std::fabs(z - z_from) < 2.0; z += step) {
    if (pushed_up(z + step) == up) continue;
    double pushed = z, pulled = z + step;  // pushed_up(pushed) == up != pushed_up(pulled)
    for (int it = 0; it < 60; ++it) {
      const double mid = 0.5 * (pushed + pulled);
      (pushed_up(mid) == up ? pushed : pulled) = mid;
    }
    return up ? pulled : pushed;  // the side with a net upward force
  }
  return std::nan("");
}

// Resistance to sliding along +x at x (y fixed): every contact at its Coulomb limit, the
// height balanced, minus the tangential part of the normal forces (the "bump" term).
struct SlideResistance {
  double total = 0.0;
  double bump = 0.0;  // from the normal forces alone
  double z = 0.0;
};
SlideResistance slide_resistance(const lbm::VoxelGeometry& g, const Reading& r, double x, double y,
                                 double load, double z_from, VoxelShape shape = VoxelShape::cube,
                                 double sphere_radius = 0.0) {
  const Vec3 slide{1, 0, 0};
  SlideResistance out;
  out.z = balanced_height(g, r, x, y, load, slide, z_from, shape, sphere_radius);
  const ReferenceSum s = reference_sum(g, r, {x, y, out.z}, slide, shape, sphere_radius);
  out.bump = -s.normal_force.x;
  out.total = -(s.normal_force.x + s.friction_force.x);
  return out;
}

// Largest net normal pull the floor resists above (x, y) from the rest height up: the net
// attraction grows with z between the heights where a voxel leaves the adhesion range, so
// its maximum is just below one of those.
double pull_off_force(const lbm::VoxelGeometry& g, const Reading& r, double x, double y,
                      double z_rest) {
  double best = -reference_sum(g, r, {x, y, z_rest}, {}).normal_force.z;
  const double reach = (1.0 + kRange) * kRadius;
  for (int j = int(y) - 6; j <= int(y) + 6; ++j)
    for (int i = int(x) - 6; i <= int(x) + 6; ++i) {
      const double sx = std::max(std::fabs(i - x) - 0.5, 0.0);
      const double sy = std::max(std::fabs(j - y) - 0.5, 0.0);
      const double s2 = sx * sx + sy * sy;
      if (s2 >= reach * reach) continue;
      const double z_drop = kFloorTop + std::sqrt(reach * reach - s2);
      if (z_drop < z_rest) continue;
      best = std::max(best, -reference_sum(g, r, {x, y, z_drop - 1e-9}, {}).normal_force.z);
    }
  return best;
}

// ---- A particle integrated by velocity Verlet (as LIGGGHTS's fix nve does) ----------------

struct Particle {
  const lbm::VoxelGeometry& geometry;
  WallContactParams params;
  double mass;
  double dt;
  Vec3 x, v, force;
  VoxelSpringStore springs;
  VoxelSumResult last;

  Particle(const lbm::VoxelGeometry& g, const WallContactParams& p, Vec3 start, double step)
      : geometry(g), params(p), mass(particle_mass(kRadius)), dt(step), x(start) {
    last = wall(x, v);
    force = last.force;
  }
  VoxelSumResult wall(Vec3 at, Vec3 velocity) {
    VoxelSumInput in(geometry);
    in.centre = at;
    in.radius = kRadius;
    in.mass = mass;
    in.velocity = velocity;
    in.dt = dt;
    in.springs = &springs;
    return voxel_sum_wall_force(params, in);
  }
  void step(Vec3 external) {
    v += (0.5 * dt / mass) * (force + external);
    x += dt * v;
    last = wall(x, v);
    springs = last.springs;
    force = last.force;
    v += (0.5 * dt / mass) * (force + external);
  }
};

// A step of 1/100 of the period of the stiffest normal oscillation: the wall spring plus the
// adhesion "spring" k_a R of the 8 voxels around the one under the centre.
double time_step(const Reading& r) {
  const double stiffness = r.k_w + 8.0 * r.k_a * kRadius;
  return 2.0 * kPi * std::sqrt(particle_mass(kRadius) / stiffness) / 100.0;
}

// Settles a particle above the centre of voxel (12, 12) under `load` from just above the
// reference rest height, and returns it.
Particle settled_on_floor(const lbm::VoxelGeometry& g, const Reading& r, double load,
                          double* z_reference) {
  const double z_rest =
      balanced_height(g, r, 12.0, 12.0, load, {}, kFloorTop + (1.0 + kRange) * kRadius - 1e-9);
  *z_reference = z_rest;
  Particle p(g, paper_params(r), {12.0, 12.0, z_rest + 0.01}, time_step(r));
  for (int s = 0; s < 6000; ++s) p.step({0.0, 0.0, -load});
  return p;
}

// The quasi-static sliding threshold along +x over two cells from the rest above (12, 12):
// the resistance at the start (friction alone: the normal forces cancel by symmetry there)
// and the largest met on the way, with the part of it that the normal forces give.
struct SlideThreshold {
  double at_rest = 0.0, largest = 0.0, largest_bump = 0.0;
  double lowest_z = 1e9, highest_z = -1e9;  // corrugation of the rest height on the way
};
SlideThreshold slide_threshold(const lbm::VoxelGeometry& g, const Reading& r, double load,
                               double z_rest, VoxelShape shape = VoxelShape::cube,
                               double sphere_radius = 0.0) {
  SlideThreshold t;
  double z = z_rest;
  constexpr int kPerCell = 500;
  for (int s = 0; s <= 2 * kPerCell; ++s) {
    const SlideResistance here =
        slide_resistance(g, r, 12.0 + double(s) / kPerCell, 12.0, load, z, shape, sphere_radius);
    if (s == 0) t.at_rest = here.total;
    t.largest = std::max(t.largest, here.total);
    t.largest_bump = std::max(t.largest_bump, here.bump);
    t.lowest_z = std::min(t.lowest_z, here.z);
    t.highest_z = std::max(t.highest_z, here.z);
    z = here.z;
  }
  return t;
}

// 50 periods of the particle's tangential oscillation on its springs, in steps.
int tangential_steps(const Reading& r, const Particle& p) {
  const double stiffness = 2.0 / 7.0 * r.k_w * p.last.contacts;
  return int(50.0 * 2.0 * kPi * std::sqrt(p.mass / stiffness) / p.dt);
}

// Drives `p` with an external force growing linearly from `from` to `to` over `ramp` steps
// and then held at `to` for `hold` steps; returns the largest |displacement . axis|, and
// stops once that is beyond 3 cells (gone, for every test here; the floor ends 11 cells on).
double ramp_and_hold(Particle& p, Vec3 axis, double from, double to, int ramp, int hold, Vec3 base,
                     Vec3 start) {
  double farthest = 0.0;
  for (int s = 1; s <= ramp + hold && farthest <= 3.0; ++s) {
    const double push = s < ramp ? from + (to - from) * s / ramp : to;
    p.step(base + push * axis);
    farthest = std::max(farthest, std::fabs(dot(p.x - start, axis)));
  }
  return farthest;
}

// No load (a deposit held by adhesion alone) and a load pressing the particle into the floor
// of 0.05 k_a R^2, about a quarter of its pull-off force.
double load_for(const Reading& r, int which) {
  return which == 0 ? 0.0 : 0.05 * r.k_a * kRadius * kRadius;
}

// Runs check(load, reference rest height, settled particle) for each of the two loads.
template <class Check>
void for_each_load(const lbm::VoxelGeometry& g, const Reading& r, Check check) {
  for (int which = 0; which < 2; ++which) {
    const double load = load_for(r, which);
    double z_ref = 0.0;
    Particle p = settled_on_floor(g, r, load, &z_ref);
    check(load, z_ref, p);
  }
}

// Conservative energy of the contacts, each voxel's potential continuous through its range:
// k_w delta^2 / 2 overlapping, k_a R h^2 / 2 adhering, constant (taken as zero) beyond.
double contact_energy(const lbm::VoxelGeometry& g, const Reading& r, Vec3 c) {
  const double range = kRange * kRadius;
  const double beyond = 0.5 * r.k_a * kRadius * range * range;
  double energy = 0.0;
  for (int k = int(c.z) - 6; k <= int(c.z) + 6; ++k)  // all others are out of range
    for (int j = int(c.y) - 6; j <= int(c.y) + 6; ++j)
      for (int i = int(c.x) - 6; i <= int(c.x) + 6; ++i) {
        if (!g.is_solid(i, j, k)) continue;
        const double gap = reference_contact(c, i, j, k, VoxelShape::cube, 0.0).gap;
        if (gap < 0.0)
          energy += 0.5 * r.k_w * gap * gap - beyond;
        else if (gap <= range)
          energy += 0.5 * r.k_a * kRadius * gap * gap - beyond;
      }
  return energy;
}

double spring_energy(const Reading& r, const VoxelSpringStore& store) {
  double energy = 0.0;
  for (int s = 0; s < store.count; ++s)
    energy += 0.5 * (2.0 / 7.0 * r.k_w) * dot(store.slots[s].spring, store.slots[s].spring);
  return energy;
}

// Force of one fresh contact sum (no history, at rest) from the library.
VoxelSumResult static_sum(const lbm::VoxelGeometry& g, const Reading& r, Vec3 c,
                          double radius = kRadius) {
  VoxelSumInput in(g);
  in.centre = c;
  in.radius = radius;
  in.mass = particle_mass(radius);
  in.dt = 0.01;
  return voxel_sum_wall_force(paper_params(r), in);
}

void expect_same_vector(Vec3 got, Vec3 want, double tolerance) {
  for (int a = 0; a < 3; ++a) EXPECT_NEAR(got[a], want[a], tolerance) << "component " << a;
}

class VoxelSumWall : public ::testing::TestWithParam<Reading> {};

}  // namespace

INSTANTIATE_TEST_SUITE_P(PaperTable, VoxelSumWall,
                         ::testing::Values(kLatticeReading, kDUnitReading), [](const auto& info) {
                           return std::string(info.param.name) == "lattice" ? "Lattice" : "DUnit";
                         });

// The library's sum of fresh contacts (no history, at rest) is the reference sum, anywhere
// over a floor cell: over its centre, its edges (two voxels at the same distance) and its
// corners (four), in the overlap and in the adhesion range.
TEST_P(VoxelSumWall, FloorForceIsTheReferenceSumEverywhere) {
  const Reading r = GetParam();
  const auto g = floor_geometry();
  for (int ix = 0; ix <= 4; ++ix)
    for (int iy = 0; iy <= 4; ++iy)
      for (const double gap : {-0.3, -0.05, 0.0, 0.02, 0.08, 0.2}) {
        const Vec3 c{12.0 + 0.125 * ix, 12.0 + 0.125 * iy, kFloorTop + kRadius + gap};
        const VoxelSumResult got = static_sum(g, r, c);
        const ReferenceSum want = reference_sum(g, r, c, {});
        EXPECT_EQ(got.contacts, want.contacts) << c.x << " " << c.y << " " << c.z;
        expect_same_vector(got.force, want.normal_force, 1e-12 * (1.0 + norm(want.normal_force)));
        EXPECT_NEAR(got.max_overlap_ratio, std::max(0.0, -gap / kRadius), 1e-12);
      }
}

// At rest on the floor: the dynamic equilibrium of the sum is the root of the reference force
// balance, to within the band that static friction can hold (the tangential springs of the
// tilted neighbour contacts are stretched while the particle settles: bound 1e-3 cells).
TEST_P(VoxelSumWall, RestsWhereTheReferenceSumBalancesTheLoad) {
  const Reading r = GetParam();
  const auto g = floor_geometry();
  for_each_load(g, r, [&](double load, double z_ref, Particle& p) {
    const ReferenceSum at_rest = reference_sum(g, r, p.x, {});
    std::printf(
        "[voxel_sum] %s: load %.4g: rest overlap/R %.4f (largest voxel), %d contacts, "
        "z - z_ref = %.2e\n",
        r.name, load, p.last.max_overlap_ratio, p.last.contacts, p.x.z - z_ref);
    EXPECT_NEAR(p.x.z, z_ref, 1e-3);
    EXPECT_NEAR(p.x.x, 12.0, 1e-9);
    EXPECT_NEAR(p.x.y, 12.0, 1e-9);
    EXPECT_LT(norm(p.v), 1e-9);
    EXPECT_NEAR(p.force.z, load, 1e-9 * (1.0 + load));  // at rest the wall carries the load
    EXPECT_EQ(p.last.contacts, at_rest.contacts);
  });
}

// Paper: friction holds a deposit "as long as the particle adheres". On the voxel floor two
// thresholds, both computed here by slide_threshold (every voxel within reach at its Coulomb
// limit mu (|F_n,k| + F_a,k), plus the tangential part of the normal forces, the height
// balanced at each position by a root solve):
// - below 95 % of the friction limit at the rest position the springs hold the particle
//   (it moves less than 0.2 cell while the force rises slowly, over 50 periods of its
//   tangential oscillation);
// - held at 95 % of the largest resistance on the way over the next two cells it stays within
//   the first cell; held at 105 % of it, it slides on (more than two cells).
// Between the two it creeps to where the resistance matches: the normal forces of the voxels
// it leaves behind (adhesion rising with the gap, Eq. 4) tether it to its cell.
TEST_P(VoxelSumWall, HoldsBelowAndSlidesAboveTheThresholdOfTheVoxels) {
  const Reading r = GetParam();
  const auto g = floor_geometry();
  for_each_load(g, r, [&](double load, double z_ref, Particle& p) {
    const SlideThreshold threshold = slide_threshold(g, r, load, z_ref);
    const int steps = tangential_steps(r, p);
    const Vec3 start = p.x, along{1, 0, 0}, base{0, 0, -load};
    const double friction = 0.95 * threshold.at_rest;
    const double below = 0.95 * threshold.largest, above = 1.05 * threshold.largest;
    const double stuck = ramp_and_hold(p, along, 0.0, friction, steps, 0, base, start);
    const double crept = ramp_and_hold(p, along, friction, below, steps, steps, base, start);
    const double slid = ramp_and_hold(p, along, below, above, steps / 5, steps, base, start);
    std::printf(
        "[voxel_sum] %s: load %.4g: friction limit at rest %.4g, largest resistance "
        "%.4g (normal forces' part up to %.3g); moved %.3f cell at 95 %% of the first, "
        "%.3f at 95 %% of the second, %.1f at 105 %%; rest height varies by %.3f cell\n",
        r.name, load, threshold.at_rest, threshold.largest, threshold.largest_bump, stuck, crept,
        slid, threshold.highest_z - threshold.lowest_z);
    EXPECT_LT(stuck, 0.2);
    EXPECT_LT(crept, 1.0);
    EXPECT_GT(slid, 2.0);
  });
}

// The normal pull-off force: held at 97 % of the reference the particle stays on the floor
// (still touching voxels, risen less than 0.2 cell), held at 103 % it is torn off (more than
// one cell). The reference is the largest net attraction of the voxels from the rest height up;
// it is several times the single smooth-wall contact's 0.03 k_a R^2.
TEST_P(VoxelSumWall, PullOffForceIsTheSummedAdhesion) {
  const Reading r = GetParam();
  const auto g = floor_geometry();
  double z_ref = 0.0;
  Particle p = settled_on_floor(g, r, 0.0, &z_ref);
  const double reference = pull_off_force(g, r, 12.0, 12.0, z_ref);
  const int steps = 50 * 100;  // time_step is 1/100 of the normal period
  const Vec3 start = p.x, up{0, 0, 1};
  const double held = ramp_and_hold(p, up, 0.0, 0.97 * reference, steps, steps, {}, start);
  const int still_touching = p.last.contacts;
  const double torn =
      ramp_and_hold(p, up, 0.97 * reference, 1.03 * reference, steps / 5, steps, {}, start);
  const double smooth = max_adhesion_force(paper_params(r).adhesion, kRadius);
  std::printf(
      "[voxel_sum] %s: pull-off %.4g (smooth wall 0.03 k_a R^2 = %.4g, ratio %.2f); "
      "rose %.3f cell at 97 %%, %.1f at 103 %%\n",
      r.name, reference, smooth, reference / smooth, held, torn);
  EXPECT_GT(still_touching, 0);
  EXPECT_LT(held, 0.2);
  EXPECT_GT(torn, 1.0);
  EXPECT_GT(reference, 2.0 * smooth);
}

// Energy does not grow for a particle resting on the floor (damped, 10^4 steps): moved off
// its rest by 0.05 cell along the floor and half the adhesion range up, and released at rest
// with fresh springs, its energy (kinetic + contact potentials + tangential springs) never
// exceeds the start by more than 1.5 % of the energy it was given, does not grow from one
// block of 1000 steps to the next, and ends below half of what it was given. The 1.5 %: when
// a contact starts sliding, coulomb_friction.h stores the whole capped force in the spring,
// its dashpot share included, and a fast first approach to the floor puts up to about 1 % of
// the energy into springs that way (measured: 0.8 % in the d-unit reading, 0 in the lattice
// reading), which they give back as they relax.
TEST_P(VoxelSumWall, EnergyDoesNotGrowAtRestOnTheWall) {
  const Reading r = GetParam();
  const auto g = floor_geometry();
  double z_ref = 0.0;
  const Particle rest = settled_on_floor(g, r, 0.0, &z_ref);
  Particle p(g, paper_params(r), rest.x + Vec3{0.05, 0.02, 0.5 * kRange * kRadius}, rest.dt);
  const auto energy = [&] {
    return 0.5 * p.mass * dot(p.v, p.v) + contact_energy(g, r, p.x) + spring_energy(r, p.springs);
  };
  const double start = energy();
  const double given = start - contact_energy(g, r, rest.x);
  double highest = start, block_end = start;
  for (int s = 1; s <= 10000; ++s) {
    p.step({});
    highest = std::max(highest, energy());
    if (s % 1000 == 0) {
      EXPECT_LE(energy(), block_end + 1e-12 * given) << "step " << s;
      block_end = energy();
    }
  }
  const double end = energy();
  std::printf(
      "[voxel_sum] %s: released with %.3g above rest: energy rose at most %.2e of it, "
      "lost %.3f of it\n",
      r.name, given, (highest - start) / given, (start - end) / given);
  EXPECT_GT(given, 0.0);
  EXPECT_LE(highest, start + 0.015 * given);
  EXPECT_LT(end, start - 0.5 * given);
}

// Over the outer edge of a step (solid for i <= 11, k <= 5, every j), the voxels in reach are
// the edge row's: voxel j at distance sqrt(d0^2 + s_j^2) from a centre at distance d0 from the
// edge line, s_j the distance along the edge to its extent. Hand sum of their normal forces
// vs the library; the direction is the edge's bisector when the centre is over a voxel's
// middle or over the boundary of two.
TEST_P(VoxelSumWall, OverAnEdgeTheEdgeRowSums) {
  const Reading r = GetParam();
  lbm::VoxelGeometry g({24, 24, 12});
  for (int k = 0; k <= 5; ++k)
    for (int j = 0; j < 24; ++j)
      for (int i = 0; i <= 11; ++i) g.set_solid(i, j, k, true);
  const Vec3 bisector = (1.0 / std::sqrt(2.0)) * Vec3{1, 0, 1};
  for (const double y : {12.0, 12.5, 12.2})
    for (const double d0 : {kRadius - 0.05, kRadius - 0.01, kRadius + 0.02, kRadius + 0.09}) {
      const Vec3 c = Vec3{11.5, y, 5.5} + d0 * bisector;
      Vec3 want;
      int in_reach = 0;
      for (int j = 0; j < 24; ++j) {
        const double along = y - std::clamp(y, j - 0.5, j + 0.5);
        const double d = std::sqrt(d0 * d0 + along * along);
        const double f = reference_normal_force(r, d - kRadius);
        if (d - kRadius > kRange * kRadius) continue;
        ++in_reach;
        want += (f / d) * (d0 * bisector + Vec3{0, along, 0});
      }
      const VoxelSumResult got = static_sum(g, r, c);
      EXPECT_EQ(got.contacts, in_reach) << "y " << y << " d0 " << d0;
      expect_same_vector(got.force, want, 1e-12 * (1.0 + norm(want)));
      if (y != 12.2) {
        EXPECT_NEAR(dot(got.force, bisector), std::copysign(norm(got.force), want.z),
                    1e-12 * (1.0 + norm(want)));
      }
      if (y == 12.0 && d0 == kRadius - 0.05)
        std::printf(
            "[voxel_sum] %s: over an edge at overlap 0.05: %d voxels, force %.4g "
            "(one merged contact: %.4g)\n",
            r.name, got.contacts, norm(got.force), r.k_w * 0.05);
    }
}

// Over the outer corner of a block (solid for i, j <= 11, k <= 5): on the diagonal only the
// corner voxel is in reach (its neighbours along the edges are sqrt(d0^2 + 2 d0/sqrt3 + 1)
// away), so the force is one contact's, along (1,1,1)/sqrt3; off the diagonal above the top
// face the library matches the reference sum.
TEST_P(VoxelSumWall, OverACornerTheCornerVoxelActsAlone) {
  const Reading r = GetParam();
  lbm::VoxelGeometry g({24, 24, 12});
  for (int k = 0; k <= 5; ++k)
    for (int j = 0; j <= 11; ++j)
      for (int i = 0; i <= 11; ++i) g.set_solid(i, j, k, true);
  const Vec3 corner{11.5, 11.5, 5.5};
  const Vec3 diagonal = (1.0 / std::sqrt(3.0)) * Vec3{1, 1, 1};
  for (const double d0 : {kRadius - 0.05, kRadius - 0.01, kRadius + 0.02, kRadius + 0.09}) {
    const VoxelSumResult got = static_sum(g, r, corner + d0 * diagonal);
    EXPECT_EQ(got.contacts, 1);
    expect_same_vector(got.force, reference_normal_force(r, d0 - kRadius) * diagonal, 1e-12);
  }
  for (const Vec3 offset : {Vec3{-0.3, -0.2, kRadius - 0.04}, Vec3{0.4, -1.2, kRadius + 0.03},
                            Vec3{1.0, 1.0, kRadius - 0.2}}) {
    const Vec3 c = corner + offset;
    const ReferenceSum want = reference_sum(g, r, c, {});
    const VoxelSumResult got = static_sum(g, r, c);
    EXPECT_EQ(got.contacts, want.contacts);
    expect_same_vector(got.force, want.normal_force, 1e-12 * (1.0 + norm(want.normal_force)));
  }
}

// The springs survive a restart: packed into the flat buffer and unpacked, a store is the
// same bit for bit, and a particle continued from the unpacked store follows the very same
// trajectory as one continued from the original.
TEST_P(VoxelSumWall, SpringStoreRoundTripsThroughAFlatBuffer) {
  const Reading r = GetParam();
  const auto g = floor_geometry();
  double z_ref = 0.0;
  Particle p = settled_on_floor(g, r, 0.0, &z_ref);
  const double friction = reference_sum(g, r, p.x, {}).friction_capacity;
  ramp_and_hold(p, {1, 0, 0}, 0.0, 0.5 * friction, 2000, 0, {}, p.x);
  ASSERT_GT(p.springs.count, 0);
  std::vector<double> buffer(kPackedSpringStoreSize, -7.0);
  pack_spring_store(p.springs, buffer.data());
  Particle restarted = p;
  restarted.springs = VoxelSpringStore{};
  ASSERT_TRUE(unpack_spring_store(buffer.data(), restarted.springs));
  ASSERT_EQ(restarted.springs.count, p.springs.count);
  for (int s = 0; s < p.springs.count; ++s) {
    EXPECT_EQ(restarted.springs.slots[s].voxel, p.springs.slots[s].voxel);
    for (int a = 0; a < 3; ++a)
      EXPECT_EQ(restarted.springs.slots[s].spring[a], p.springs.slots[s].spring[a]);
  }
  for (int s = 0; s < 2000; ++s) {
    p.step({0.6 * friction, 0, 0});
    restarted.step({0.6 * friction, 0, 0});
  }
  for (int a = 0; a < 3; ++a) {
    EXPECT_EQ(restarted.x[a], p.x[a]);
    EXPECT_EQ(restarted.v[a], p.v[a]);
  }
}

TEST(VoxelSpringStore, UnpackRejectsWhatIsNotAPackedStore) {
  VoxelSpringStore store;
  store.add(42, {1e-3, -2e-3, 0.5});
  store.add(7, {0, 0, 0});
  std::vector<double> good(kPackedSpringStoreSize);
  pack_spring_store(store, good.data());
  EXPECT_EQ(good[0], 2.0);
  EXPECT_EQ(good[1], 42.0);
  EXPECT_EQ(good[5], 7.0);
  EXPECT_EQ(good[kPackedSpringStoreSize - 1], 0.0);
  const auto corrupt = [&](std::size_t index, double value) {
    std::vector<double> bad = good;
    bad[index] = value;
    VoxelSpringStore out;
    out.add(1, {});
    const bool accepted = unpack_spring_store(bad.data(), out);
    EXPECT_EQ(out.count, 0) << index << " " << value;
    return accepted;
  };
  EXPECT_FALSE(corrupt(0, -1.0));
  EXPECT_FALSE(corrupt(0, kVoxelSpringCapacity + 1.0));
  EXPECT_FALSE(corrupt(0, 1.5));
  EXPECT_FALSE(corrupt(0, std::nan("")));
  EXPECT_FALSE(corrupt(1, -3.0));
  EXPECT_FALSE(corrupt(5, 2.5));
  EXPECT_FALSE(corrupt(5, std::nan("")));
}

// Cube distance with a spacing and an origin: the lattice picture scaled and shifted.
TEST(VoxelSumWallGeometry, DistanceToAVoxelUsesSpacingAndOrigin) {
  const lbm::VoxelGeometry unit({8, 8, 8});
  const lbm::VoxelGeometry scaled({8, 8, 8}, 0.5, {1.0, -2.0, 0.5});
  const Vec3 c_unit{5.3, 1.2, 3.9};
  const Vec3 c_scaled = Vec3{1.0, -2.0, 0.5} + 0.5 * c_unit;
  for (const auto& v : {std::array<int, 3>{3, 3, 3}, {5, 1, 6}, {5, 2, 3}, {0, 7, 3}}) {
    const VoxelDistance a = distance_to_voxel(unit, c_unit, v[0], v[1], v[2]);
    const VoxelDistance b = distance_to_voxel(scaled, c_scaled, v[0], v[1], v[2]);
    EXPECT_NEAR(b.distance, 0.5 * a.distance, 1e-14);
    expect_same_vector(b.normal, a.normal, 1e-13);
    const ReferenceContact ref = reference_contact(c_unit, v[0], v[1], v[2], VoxelShape::cube, 0);
    EXPECT_NEAR(a.distance, ref.gap + kRadius, 1e-14);
  }
  // Inside the cube: zero distance, pushed out away from the voxel's centre.
  const VoxelDistance inside = distance_to_voxel(unit, {5.2, 1.0, 3.0}, 5, 1, 3);
  EXPECT_EQ(inside.distance, 0.0);
  expect_same_vector(inside.normal, {1, 0, 0}, 1e-15);
}

// More contacts than the store holds: the force still sums them all, the extra springs are
// counted in springs_dropped (never silently lost). A floor of quarter-cell voxels under a
// particle of radius 3.5 at 5 % overlap puts about a hundred voxels in reach.
TEST(VoxelSumWallGeometry, OverflowOfTheSpringStoreIsReported) {
  lbm::VoxelGeometry g({64, 64, 8}, 0.25, {0.0, 0.0, 0.0});
  for (int k = 0; k <= 3; ++k)
    for (int j = 0; j < 64; ++j)
      for (int i = 0; i < 64; ++i) g.set_solid(i, j, k, true);
  const double top = 3.5 * 0.25;
  VoxelSumInput in(g);
  in.centre = {8.0, 8.0, top + 0.95 * kRadius};
  in.radius = kRadius;
  in.mass = particle_mass(kRadius);
  in.velocity = {1e-3, 0, 0};
  in.dt = 0.01;
  const VoxelSumResult got = voxel_sum_wall_force(paper_params(kDUnitReading), in);
  EXPECT_GT(got.contacts, kVoxelSpringCapacity);
  EXPECT_EQ(got.springs.count, kVoxelSpringCapacity);
  EXPECT_EQ(got.springs_dropped, got.contacts - kVoxelSpringCapacity);
  EXPECT_NEAR(got.max_overlap_ratio, 0.05, 1e-12);
}

// How many springs a particle needs: contacts at the overlap guard's warning level (5 % of
// R from every wall) on a floor, in an inner edge and in an inner box corner, for the mean
// radius and a radius 3 sigma above it (1.3 x 3.5 cells), over the worst of 16 positions
// relative to the voxel grid: the capacity holds both.
TEST(VoxelSumWallGeometry, ContactCountsFitTheSpringStore) {
  lbm::VoxelGeometry g({32, 32, 32});
  for (int k = 0; k < 32; ++k)
    for (int j = 0; j < 32; ++j)
      for (int i = 0; i < 32; ++i)
        if (k <= 1 || i <= 1 || j <= 1) g.set_solid(i, j, k, true);
  const double face = 1.5;
  for (const double radius : {kRadius, 1.3 * kRadius}) {
    int most[3] = {0, 0, 0};  // floor, edge, corner
    for (int shift = 0; shift < 16; ++shift) {
      const double fx = 0.25 * (shift % 4), fy = 0.25 * (shift / 4);
      const double d = 0.95 * radius;
      const Vec3 floor_only{16.0 + fx, 16.0 + fy, face + d};
      const Vec3 edge{face + d + fx, 16.0 + fy, face + d};
      const Vec3 corner{face + d + fx, face + d + fy, face + d};
      const Vec3 where[3] = {floor_only, edge, corner};
      for (int w = 0; w < 3; ++w)
        most[w] = std::max(most[w], static_sum(g, kDUnitReading, where[w], radius).contacts);
    }
    std::printf(
        "[voxel_sum] R = %.2f at 5 %% overlap: up to %d contacts on a floor, %d in an "
        "inner edge, %d in an inner corner (capacity %d)\n",
        radius, most[0], most[1], most[2], kVoxelSpringCapacity);
    EXPECT_LE(most[2], kVoxelSpringCapacity);
  }
}

// Why a voxel acts as a cube (doc/wall_models.md). Over a grid of positions covering a floor
// cell (a quarter of it, by symmetry) the rest height without load, from the reference sums,
// for cube voxels and for spheres around the nodes of radius dx/2 (inscribed), 0.62 dx (same
// volume) and sqrt(3)/2 dx (circumscribed): how much it varies over the cell (corrugation),
// and the friction limit where it is lowest and over the voxel's middle (its node). Where
// the particle is highest (over the point where four cubes meet, or over a sphere's top) it
// touches only the voxels at the same distance, rests at gap 0 like on a smooth wall and is
// not held, but it does not stay there: those are the hill tops of the rest height. The
// assertions are the decision's premises: the cube floor is the flattest, and it holds.
TEST_P(VoxelSumWall, CubeVoxelsMakeTheFlattestFloor) {
  const Reading r = GetParam();
  const auto g = floor_geometry();
  double cube_corrugation = 0.0;
  for (const double radius : {0.0, 0.5, 0.6204, 0.8660}) {
    const VoxelShape shape = radius == 0.0 ? VoxelShape::cube : VoxelShape::sphere;
    const double top = radius == 0.0 ? kFloorTop : 1.0 + radius;  // of the floor's voxels
    double lowest = 1e9, highest = -1e9, hold_lowest = 0.0, hold_middle = 0.0;
    for (int ix = 0; ix <= 10; ++ix)
      for (int iy = 0; iy <= ix; ++iy) {
        const double x = 12.0 + 0.05 * ix, y = 12.0 + 0.05 * iy;
        const double z = balanced_height(g, r, x, y, 0.0, {}, top + (1.0 + kRange) * kRadius - 1e-9,
                                         shape, radius);
        const double hold = reference_sum(g, r, {x, y, z}, {}, shape, radius).friction_capacity;
        if (ix == 0) hold_middle = hold;
        if (z < lowest) lowest = z, hold_lowest = hold;
        highest = std::max(highest, z);
      }
    const double corrugation = highest - lowest;
    std::printf(
        "[voxel_sum] %s: %-6s %.3f: rest height varies by %.4f cell over a cell; "
        "friction limit %.4g where lowest, %.4g over the voxel's middle\n",
        r.name, radius == 0.0 ? "cube" : "sphere", radius == 0.0 ? 1.0 : radius, corrugation,
        hold_lowest, hold_middle);
    if (radius == 0.0) {
      cube_corrugation = corrugation;
      EXPECT_GT(hold_lowest, 0.0);
      EXPECT_GT(hold_middle, 0.0);
    } else {
      EXPECT_LT(cube_corrugation, corrugation);
    }
  }
}

// The accelerated sum (solid runs, culled rows and voxels, per-particle candidate lists) is
// the plain scan of every voxel of the box, to the last bit: a particle with its springs
// walks through a pore (a block with a cylindrical hole), along its wall and across its
// edges, and every step both give the same force, contacts and springs.
TEST(VoxelSumWallGeometry, AcceleratedSumIsThePlainBoxScanBitForBit) {
  lbm::VoxelGeometry g({40, 24, 24}, 1.0, {0.5, 0.5, 0.5});
  for (int k = 0; k < 24; ++k)
    for (int j = 0; j < 24; ++j)
      for (int i = 20; i < 30; ++i) {
        const double dy = j - 11.5, dz = k - 11.5;
        if (dy * dy + dz * dz >= 49.0) g.set_solid(i, j, k, true);
      }
  const WallContactParams params = paper_params(kDUnitReading);
  const SolidBlockMap blocks(g);
  const double mass = particle_mass(kRadius);
  const double reach = wall_contact_reach(params, kRadius);
  // The plain scan: every voxel of the box around the centre, in increasing k, j, i.
  const auto plain = [&](Vec3 centre, Vec3 velocity, const VoxelSpringStore& springs) {
    VoxelSumResult out;
    for (int k = 0; k < 24; ++k)
      for (int j = 0; j < 24; ++j)
        for (int i = 0; i < 40; ++i) {
          if (!g.is_solid(i, j, k)) continue;
          const VoxelDistance voxel = distance_to_voxel(g, centre, i, j, k);
          if (voxel.distance > reach) continue;
          const auto key = static_cast<std::int64_t>(g.index(i, j, k));
          const Vec3* stored = springs.find(key);
          WallContactInput contact;
          contact.normal = voxel.normal;
          contact.gap = voxel.distance - kRadius;
          contact.radius = kRadius;
          contact.mass = mass;
          contact.velocity = velocity;
          contact.spring = stored != nullptr ? *stored : Vec3{};
          contact.dt = 0.01;
          const WallContactResult result = wall_contact_force(params, contact);
          if (!result.active) continue;
          out.force += result.force;
          ++out.contacts;
          out.springs.add(key, result.spring);
        }
    return out;
  };
  WallCandidates candidates;
  VoxelSpringStore springs_plain, springs_fast;
  int steps_in_contact = 0;
  const Vec3 velocity{0.02, 0.013, -0.007};
  for (int step = 0; step < 3000; ++step) {
    // From the open inlet into the hole, spiralling along its wall (0.01 cell per step).
    const double t = 0.01 * step;
    const Vec3 centre{12.0 + t * 0.5, 11.5 + 3.4 * std::cos(0.3 * t), 11.5 + 3.4 * std::sin(0.3 * t)};
    VoxelSumInput in(g);
    in.centre = centre;
    in.radius = kRadius;
    in.mass = mass;
    in.velocity = velocity;
    in.dt = 0.01;
    in.springs = &springs_fast;
    in.blocks = &blocks;
    in.candidates = &candidates;
    const VoxelSumResult fast = voxel_sum_wall_force(params, in);
    const VoxelSumResult want = plain(centre, velocity, springs_plain);
    ASSERT_EQ(fast.contacts, want.contacts) << "step " << step;
    for (int a = 0; a < 3; ++a) ASSERT_EQ(fast.force[a], want.force[a]) << "step " << step;
    ASSERT_EQ(fast.springs.count, want.springs.count);
    for (int s = 0; s < want.springs.count; ++s) {
      ASSERT_EQ(fast.springs.slots[s].voxel, want.springs.slots[s].voxel);
      for (int a = 0; a < 3; ++a)
        ASSERT_EQ(fast.springs.slots[s].spring[a], want.springs.slots[s].spring[a]);
    }
    springs_fast = fast.springs;
    springs_plain = want.springs;
    if (want.contacts > 0) ++steps_in_contact;
  }
  EXPECT_GT(steps_in_contact, 1000);
}
