// bench_lbm: speed of the pure fluid step (halo exchange + stream-collide) in million
// lattice updates per second (MLUPS) on a fully periodic box, at 64^3 and 128^3 with 1 and
// 2 threads, next to the memory-bandwidth roofline measured in the same run.
//
// Bytes per update (counted like STREAM copy): 19 populations read + 19 written, in the
// storage precision, + 1 byte of node type. Roofline MLUPS = bandwidth / that, with the
// bandwidth the largest of a plain copy, a copy with streaming stores and an in-place update
// (the in-place kernel writes back lines it has just read: no write-allocate either).
// The figures and what they mean: doc/performance.md.
// Also one rank's share of the paper's lattice (90 x 40 x 40 split in two along x: rows of
// 45 nodes) on one thread, and the memory the solver holds per lattice node.
// When CMake found Palabos (Debian's libplb-dev), the same 128^3 TRT case in Palabos on one
// thread, interleaved with ours (ours, Palabos, ours, ...): BENCH lbm_vs_palabos, the median
// of the pairs' speed ratios, with their spread (palabos_trt_case.h).
#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <memory>
#include <vector>

#include "lbm/decomposition.h"
#include "lbm/fluid_solver.h"
#include "palabos_trt_case.h"
#include "stream_bandwidth.h"

namespace {

constexpr double kTau = 0.8;

struct Speed {
  double mlups = 0.0;
  double bytes_per_node = 0.0;
};

template <class Step>
double seconds_for(int steps, Step&& step) {
  const auto start = std::chrono::steady_clock::now();
  for (int s = 0; s < steps; ++s) step();
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

// Enough steps for ~0.5 s at the expected speed.
int timed_steps(double cells) { return std::max(5, int(3e7 / cells)); }

std::unique_ptr<lbm::FluidSolver> periodic_solver(std::array<int, 3> dims, double magic) {
  lbm::VoxelGeometry geometry(dims);
  lbm::FluidParameters p;
  p.tau = kTau;
  p.magic = magic;
  p.periodic = {true, true, true};
  lbm::Box box;
  box.hi = dims;
  return std::make_unique<lbm::FluidSolver>(geometry, p, lbm::FlowDrive{},
                                            lbm::Decomposition::serial(box, p.periodic));
}

Speed measure_mlups(std::array<int, 3> dims, int threads) {
  omp_set_num_threads(threads);
  const auto solver = periodic_solver(dims, lbm::FluidParameters{}.magic);
  solver->initialise_equilibrium(1.0, {0.01, 0.0, 0.0});
  const double cells = double(dims[0]) * dims[1] * dims[2];
  for (int s = 0; s < 3; ++s) solver->step();  // warm up: page faults, caches
  const int steps = timed_steps(cells);
  double best = 0.0;  // best of three repeats
  for (int repeat = 0; repeat < 3; ++repeat)
    best = std::max(best, cells * steps / seconds_for(steps, [&] { solver->step(); }) / 1e6);
  return {best, solver->bytes_per_node()};
}

double median(std::vector<double> values) {
  std::sort(values.begin(), values.end());
  const std::size_t n = values.size();
  return n % 2 ? values[n / 2] : 0.5 * (values[n / 2 - 1] + values[n / 2]);
}

// Our side of the Palabos case: the magic parameter Lambda = (1/omega+ - 1/2)(1/omega- - 1/2)
// that gives Palabos's fixed odd-moment rate omega- at our tau.
double palabos_case_magic() { return (kTau - 0.5) * (1.0 / palabos_trt_omega_minus() - 0.5); }

// Both codes from the same shear wave: equal to round-off when lattice, equilibrium and the
// two TRT rates are the same. Largest velocity difference over the nodes, relative to the
// wave's amplitude, after a few steps (the pull step of ours and Palabos's collide-then-
// stream differ by a collision, which leaves the moments unchanged).
double palabos_velocity_difference() {
  const int n = 16, steps = 20;
  const double amplitude = 0.01;
  const NodeState wave = [&](int, int j, int) -> std::array<double, 4> {
    return {1.0, amplitude * std::sin(2.0 * M_PI * (j + 0.5) / n), 0.0, 0.0};
  };
  const auto ours = periodic_solver({n, n, n}, palabos_case_magic());
  ours->initialise_equilibrium(wave);
  const auto palabos = make_palabos_trt_case(n, kTau, wave);
  for (int s = 0; s < steps; ++s) {
    ours->step();
    palabos->step();
  }
  double largest = 0.0;
  for (int k = 0; k < n; ++k)
    for (int j = 0; j < n; ++j)
      for (int i = 0; i < n; ++i) {
        const auto a = ours->velocity(ours->layout().cell(i, j, k));
        const auto b = palabos->velocity(i, j, k);
        for (int d = 0; d < 3; ++d) largest = std::max(largest, std::abs(a[d] - b[d]));
      }
  return largest / amplitude;
}

// 128^3, one thread each (Palabos runs in one process), pairs interleaved so that both see
// the same load of a shared machine.
void compare_with_palabos() {
  if (!palabos_available()) {
    std::printf("bench_lbm: built without Palabos (Debian libplb-dev not found at configure): lbm_vs_palabos skipped\n");
    return;
  }
  std::printf("BENCH palabos_same_case_velocity_difference %.2e relative\n",
              palabos_velocity_difference());
  omp_set_num_threads(1);
  const int n = 128, repeats = 5;
  const double cells = double(n) * n * n;
  const auto uniform = [](int, int, int) { return std::array<double, 4>{1.0, 0.01, 0.0, 0.0}; };
  const auto ours = periodic_solver({n, n, n}, palabos_case_magic());
  ours->initialise_equilibrium(uniform);
  const auto palabos = make_palabos_trt_case(n, kTau, uniform);
  for (int s = 0; s < 3; ++s) {  // warm up: page faults, caches
    ours->step();
    palabos->step();
  }
  const int steps = timed_steps(cells);
  std::vector<double> ours_mlups, palabos_mlups, ratios;
  for (int repeat = 0; repeat < repeats; ++repeat) {
    ours_mlups.push_back(cells * steps / seconds_for(steps, [&] { ours->step(); }) / 1e6);
    palabos_mlups.push_back(cells * steps / seconds_for(steps, [&] { palabos->step(); }) / 1e6);
    ratios.push_back(ours_mlups.back() / palabos_mlups.back());
  }
  std::printf("BENCH lbm_128_1t_palabos_case %.1f MLUPS\n", median(ours_mlups));
  std::printf("BENCH palabos_128_1t %.1f MLUPS\n", median(palabos_mlups));
  std::printf("BENCH lbm_vs_palabos_min %.2f ratio\n",
              *std::min_element(ratios.begin(), ratios.end()));
  std::printf("BENCH lbm_vs_palabos_max %.2f ratio\n",
              *std::max_element(ratios.begin(), ratios.end()));
  std::printf("BENCH lbm_vs_palabos %.2f ratio\n", median(ratios));
}

}  // namespace

int main() {
  const double bytes_per_update = 2.0 * 19 * sizeof(lbm::Real) + 1.0;
  const int max_threads = std::min(2, omp_get_num_procs());
  std::printf("BENCH bytes_per_cell_update %.0f bytes\n", bytes_per_update);
  double best_ratio_128 = 0.0;
  for (int threads = 1; threads <= max_threads; ++threads) {
    const double plain = measure_copy_bandwidth(threads, CopyStores::kPlain);
    const double streaming = measure_copy_bandwidth(threads, CopyStores::kStreaming);
    // The kernel runs in place: reading a line and writing it back is its access, so the
    // in-place update counts among the yardsticks (the best of the three wins).
    const double update = measure_update_bandwidth(threads);
    const double roofline = std::max({plain, streaming, update}) / bytes_per_update / 1e6;
    std::printf("BENCH stream_copy_bandwidth_%dt %.2f GB/s\n", threads, plain / 1e9);
    std::printf("BENCH stream_copy_streaming_bandwidth_%dt %.2f GB/s\n", threads, streaming / 1e9);
    std::printf("BENCH stream_update_bandwidth_%dt %.2f GB/s\n", threads, update / 1e9);
    std::printf("BENCH lbm_roofline_%dt %.1f MLUPS\n", threads, roofline);
    // The yardstick of the kernel's own access pattern: 19 arrays read and 19 written, as
    // large as the 128^3 lattice's, the most favourable burst of those tried. On machines
    // whose memory serves many streams far below one (a 2-core AMD EPYC guest measured
    // 57 GB/s for one array, 25 for 19) this, not the one-array copy, is what the kernel
    // can reach; lbm_roofline_ratio stays the one-array figure.
    double many = 0.0;
    for (std::size_t burst : {std::size_t(320), std::size_t(4096)})
      many = std::max(many, measure_multi_array_copy_bandwidth(threads, 19, 130 * 130 * 130, burst));
    const double many_roofline = many / bytes_per_update / 1e6;
    std::printf("BENCH stream_copy_19_arrays_bandwidth_%dt %.2f GB/s\n", threads, many / 1e9);
    for (int n : {64, 128}) {
      const Speed speed = measure_mlups({n, n, n}, threads);
      if (n == 64 && threads == 1)
        std::printf("BENCH lattice_bytes_per_node %.1f bytes\n", speed.bytes_per_node);
      std::printf("BENCH lbm_%d_%dt %.1f MLUPS\n", n, threads, speed.mlups);
      std::printf("BENCH lbm_%d_%dt_roofline_ratio %.3f ratio\n", n, threads,
                  speed.mlups / roofline);
      if (n == 128) {
        best_ratio_128 = std::max(best_ratio_128, speed.mlups / roofline);
        std::printf("BENCH lbm_128_%dt_19_array_copy_ratio %.3f ratio\n", threads,
                    speed.mlups / many_roofline);
      }
    }
    if (threads == 1) {
      const double mlups = measure_mlups({45, 40, 40}, 1).mlups;
      std::printf("BENCH lbm_paper_rank_block_1t %.1f MLUPS\n", mlups);
      std::printf("BENCH lbm_paper_rank_block_1t_roofline_ratio %.3f ratio\n", mlups / roofline);
    }
  }
  std::printf("BENCH lbm_roofline_ratio %.3f ratio\n", best_ratio_128);
  compare_with_palabos();
  return 0;
}
