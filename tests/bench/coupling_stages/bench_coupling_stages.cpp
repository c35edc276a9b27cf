// bench_coupling_stages: SphereCoupling::step on one rank's block of the paper's lattice
// (45 x 40 x 40: the 90 x 40 x 40 lattice split in two along x, periodic across the flow
// here, driven by a body force) with 40 spheres of the paper's size (d = 7.1 cells) moving
// slowly through it: about the links per step of one rank at the paper-run benchmark's
// steady state, without the DEM, LIGGGHTS or MPI around it, so that a change to a stage is
// measured alone and quickly, and profiled (perf record) without the rest.
//
// Prints, per fluid step, each stage's time, the links, the coupling stages (mapping,
// refill, moving walls, force) per link in ns and in collide-stream cell updates of the
// same run (`coupling_stages_fluid_cell_updates_per_link`), the median of --repeat rounds
// of --steps steps each with their spread, and a checksum of the populations at the end:
// the same checksum from two builds means the same bits.
//
//   bench_coupling_stages [--steps N] [--repeat N] [--spheres N] [--evict-mb N] [--gather-moments]
//                         [--correct-in-sweep] [--links-in-sweep]
// (--gather-moments: the moving walls gather the moments from the populations instead of
// reading the field the kernel keeps, SphereCouplingOptions::kernel_moments;
// --correct-in-sweep: the link mass correction in the moving walls' sweep rather than the
// kernel's pass, SphereCouplingOptions::correct_mass_in_kernel = false; --links-in-sweep: the
// moving walls' links in their sweep before the kernel, moving_walls_in_kernel = false (in the
// kernel's pass, the default, the time the kernel spends applying them is booked to the moving
// walls, KernelLinks::prepared_seconds); --evict-mb N:
// N MiB of other data are written between two fluid steps, outside the timed stages, as the
// DEM substeps of a full run do, so that each step starts with the lattice out of the
// caches: 0, the default, keeps the caches of the last step)
#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <vector>

#include "cases/serial_flow.h"
#include "coupling/sphere_coupling.h"
#include "coupling/stage_clock.h"
#include "lbm/d3q19.h"

namespace {

struct Round {
  double step_ms = 0, mapping = 0, refill = 0, halo = 0, moving_walls = 0, force = 0, collide_stream = 0;
  double links = 0;
};

// Deterministic positions on a jittered grid (no two spheres overlap), velocities of a few
// 1e-3 lattice units in varied directions: the particles of the paper's regime move about
// that fast against the lattice.
coupling::ParticleSet make_spheres(int count, const std::array<int, 3>& dims, double radius) {
  coupling::ParticleSet set;
  std::uint64_t state = 12345;
  const auto uniform = [&] {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    return double(state >> 11) / double(1ULL << 53);
  };
  const double pitch = 2.0 * radius + 1.5;
  const int per[3] = {int((dims[0] - 10) / pitch), int(dims[1] / pitch), int(dims[2] / pitch)};
  std::vector<std::array<double, 3>> sites;
  for (int k = 0; k < per[2]; ++k)
    for (int j = 0; j < per[1]; ++j)
      for (int i = 0; i < per[0]; ++i)
        sites.push_back({5.0 + (i + 0.5) * pitch, (j + 0.5) * pitch, (k + 0.5) * pitch});
  for (int p = 0; p < count && p < int(sites.size()); ++p) {
    coupling::Vec3 x, v;
    for (int a = 0; a < 3; ++a) {
      x[a] = sites[std::size_t(p)][a] + 0.4 * (uniform() - 0.5);
      v[a] = 4e-3 * (uniform() - 0.5);
    }
    set.add(p + 1, x, v, radius * (0.9 + 0.2 * uniform()));
  }
  return set;
}

std::uint64_t checksum(const lbm::FluidSolver& solver) {
  std::uint64_t h = 1469598103934665603ULL;
  const lbm::BlockLayout& g = solver.layout();
  for (int k = 0; k < g.size(2); ++k)
    for (int j = 0; j < g.size(1); ++j)
      for (int i = 0; i < g.size(0); ++i)
        for (int q = 0; q < lbm::D3Q19::Q; ++q) {
          const double v = solver.populations().at(q, g.cell(i, j, k));
          std::uint64_t bits;
          std::memcpy(&bits, &v, sizeof bits);
          h = (h ^ bits) * 1099511628211ULL;
        }
  return h;
}

double median(std::vector<double> v) {
  std::sort(v.begin(), v.end());
  return v.empty() ? 0.0 : v[v.size() / 2];
}

}  // namespace

int main(int argc, char** argv) {
  int steps = 500, repeat = 5, spheres = 40, evict_mb = 0;
  bool kernel_moments = true, correct_in_kernel = true, links_in_kernel = true;
  for (int i = 1; i < argc; i += 2) {
    const std::string key = argv[i];
    if (key == "--gather-moments" || key == "--correct-in-sweep" || key == "--links-in-sweep") {
      (key == "--gather-moments" ? kernel_moments : key == "--correct-in-sweep" ? correct_in_kernel
                                                                                : links_in_kernel) = false;
      --i;
      continue;
    }
    if (i + 1 >= argc) {
      std::fprintf(stderr, "bench_coupling_stages: %s needs a value\n", argv[i]);
      return 2;
    }
    const int value = std::atoi(argv[i + 1]);
    if (key == "--steps") steps = value;
    else if (key == "--repeat") repeat = value;
    else if (key == "--spheres") spheres = value;
    else if (key == "--evict-mb") evict_mb = value;
    else {
      std::fprintf(stderr, "bench_coupling_stages: unknown option %s (--steps, --repeat, --spheres, --evict-mb)\n", argv[i]);
      return 2;
    }
  }
  if (steps < 1 || repeat < 1 || spheres < 1 || evict_mb < 0) {
    std::fprintf(stderr, "bench_coupling_stages: --steps, --repeat and --spheres must be >= 1, --evict-mb >= 0\n");
    return 2;
  }
  const std::array<int, 3> dims{45, 40, 40};
  const double radius = 0.5 * 7.1;
  auto solver = cases::make_solver(dims, {true, true, true}, 1.0, {1e-6, 0.0, 0.0});
  coupling::ParticleSet particles = make_spheres(spheres, dims, radius);
  coupling::SphereCouplingOptions options;
  options.kernel_moments = kernel_moments;
  options.correct_mass_in_kernel = correct_in_kernel;
  options.moving_walls_in_kernel = links_in_kernel;
  coupling::SphereCoupling coupling(*solver, options);
  std::vector<char> other_data(std::size_t(evict_mb) << 20);
  double evicting = 0.0;  // seconds spent writing other_data, taken off the step's time
  const auto advance = [&] {
    if (!other_data.empty()) {
      const double start = coupling::clock_seconds();
      // A read and a write of every line (memset may bypass the caches on large sizes).
      for (std::size_t i = 0; i < other_data.size(); i += 64) ++other_data[i];
      evicting += coupling::clock_seconds() - start;
    }
    for (std::size_t p = 0; p < particles.size(); ++p) {
      coupling::Vec3 x = particles.view().x(p);
      const coupling::Vec3 v = particles.view().v(p);
      for (int a = 0; a < 3; ++a) x[a] += v[a];
      particles.set_position(p, x);
    }
    coupling.step(particles.view());
  };
  for (int s = 0; s < 50; ++s) advance();  // the links and caches settled
  std::vector<Round> rounds;
  for (int r = 0; r < repeat; ++r) {
    const coupling::StageTimes before = coupling.times();
    const coupling::LinkCounts links_before = coupling.link_counts();
    const double evicted_before = evicting;
    const double start = coupling::clock_seconds();
    for (int s = 0; s < steps; ++s) advance();
    const double elapsed = coupling::clock_seconds() - start - (evicting - evicted_before);
    const coupling::StageTimes& t = coupling.times();
    const double per = 1e3 / steps;
    Round round;
    round.step_ms = elapsed * per;
    round.mapping = (t.mapping - before.mapping) * per;
    round.refill = (t.refill - before.refill) * per;
    round.halo = (t.halo - before.halo) * per;
    round.moving_walls = (t.moving_walls - before.moving_walls) * per;
    round.force = (t.force - before.force) * per;
    round.collide_stream = (t.collide_stream - before.collide_stream) * per;
    round.links = double(coupling.link_counts().links - links_before.links) / steps;
    rounds.push_back(round);
  }
  const auto figure = [&](const char* name, double Round::*member, const char* unit) {
    std::vector<double> v;
    for (const Round& r : rounds) v.push_back(r.*member);
    std::printf("BENCH coupling_stages_%s %.4g %s\n", name, median(v), unit);
    return median(v);
  };
  std::printf("bench_coupling_stages: %d x %d x %d lattice, %zu spheres, %d rounds of %d steps, %d MiB written between steps\n",
              dims[0], dims[1], dims[2], particles.size(), repeat, steps, evict_mb);
  figure("fluid_step_ms", &Round::step_ms, "ms");
  figure("mapping_ms", &Round::mapping, "ms");
  figure("refill_ms", &Round::refill, "ms");
  figure("halo_ms", &Round::halo, "ms");
  figure("moving_walls_ms", &Round::moving_walls, "ms");
  figure("force_ms", &Round::force, "ms");
  const double kernel = figure("collide_stream_ms", &Round::collide_stream, "ms");
  const double links = figure("links_per_step", &Round::links, "count");
  std::vector<double> ns, fcu;
  for (const Round& r : rounds) {
    const double coupling_ms = r.mapping + r.refill + r.moving_walls + r.force;
    ns.push_back(1e6 * coupling_ms / r.links);
    fcu.push_back(coupling_ms / r.links / (r.collide_stream / double(solver->updated_cells())));
  }
  std::sort(ns.begin(), ns.end());
  std::sort(fcu.begin(), fcu.end());
  std::printf("BENCH coupling_stages_ns_per_link %.1f ns\n", median(ns));
  std::printf("BENCH coupling_stages_ns_per_link_min %.1f ns\n", ns.front());
  std::printf("BENCH coupling_stages_ns_per_link_max %.1f ns\n", ns.back());
  std::printf("BENCH coupling_stages_fluid_cell_updates_per_link %.2f ratio\n", median(fcu));
  std::printf("BENCH coupling_stages_fluid_cell_updates_per_link_min %.2f ratio\n", fcu.front());
  std::printf("BENCH coupling_stages_fluid_cell_updates_per_link_max %.2f ratio\n", fcu.back());
  std::printf("bench_coupling_stages: collide-stream %.1f ns per cell, %.0f links per step\n",
              1e6 * kernel / double(solver->updated_cells()), links);
  std::printf("bench_coupling_stages: checksum of the populations %016llx\n",
              static_cast<unsigned long long>(checksum(*solver)));
  return 0;
}
