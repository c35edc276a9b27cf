// bench_lbm: speed of the pure fluid step (halo exchange + stream-collide) in million
// lattice updates per second (MLUPS) on a fully periodic box, at 64^3 and 128^3 with 1 and
// 2 threads, next to the memory-bandwidth roofline measured in the same run.
//
// Bytes per update (counted like STREAM copy): 19 populations read + 19 written, in the
// storage precision, + 1 byte of node type. Roofline MLUPS = copy bandwidth / that, with the
// copy bandwidth the larger of a plain copy and a copy with streaming stores: the kernel
// writes with streaming stores (no write-allocate), so it is held to the same yardstick.
// Also one rank's share of the paper's lattice (90 x 40 x 40 split in two along x: rows of
// 45 nodes) on one thread, and the memory the solver holds per lattice node.
#include <omp.h>

#include <algorithm>
#include <array>
#include <chrono>
#include <cstdio>

#include "lbm/decomposition.h"
#include "lbm/fluid_solver.h"
#include "stream_bandwidth.h"

namespace {

struct Speed {
  double mlups = 0.0;
  double bytes_per_node = 0.0;
};

Speed measure_mlups(std::array<int, 3> dims, int threads) {
  omp_set_num_threads(threads);
  lbm::VoxelGeometry geometry(dims);
  lbm::FluidParameters p;
  p.tau = 0.8;
  p.periodic = {true, true, true};
  lbm::Box box;
  box.hi = dims;
  lbm::FluidSolver solver(geometry, p, lbm::FlowDrive{},
                          lbm::Decomposition::serial(box, p.periodic));
  solver.initialise_equilibrium(1.0, {0.01, 0.0, 0.0});
  const double cells = double(dims[0]) * dims[1] * dims[2];
  for (int s = 0; s < 3; ++s) solver.step();  // warm up: page faults, caches
  // Enough steps for ~0.5 s at the expected speed; best of three repeats.
  const int steps = std::max(5, int(3e7 / cells));
  double best = 0.0;
  for (int repeat = 0; repeat < 3; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    for (int s = 0; s < steps; ++s) solver.step();
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, cells * steps / seconds / 1e6);
  }
  return {best, solver.bytes_per_node()};
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
    const double roofline = std::max(plain, streaming) / bytes_per_update / 1e6;
    std::printf("BENCH stream_copy_bandwidth_%dt %.2f GB/s\n", threads, plain / 1e9);
    std::printf("BENCH stream_copy_streaming_bandwidth_%dt %.2f GB/s\n", threads, streaming / 1e9);
    std::printf("BENCH lbm_roofline_%dt %.1f MLUPS\n", threads, roofline);
    for (int n : {64, 128}) {
      const Speed speed = measure_mlups({n, n, n}, threads);
      if (n == 64 && threads == 1)
        std::printf("BENCH lattice_bytes_per_node %.1f bytes\n", speed.bytes_per_node);
      std::printf("BENCH lbm_%d_%dt %.1f MLUPS\n", n, threads, speed.mlups);
      std::printf("BENCH lbm_%d_%dt_roofline_ratio %.3f ratio\n", n, threads,
                  speed.mlups / roofline);
      if (n == 128) best_ratio_128 = std::max(best_ratio_128, speed.mlups / roofline);
    }
    if (threads == 1) {
      const double mlups = measure_mlups({45, 40, 40}, 1).mlups;
      std::printf("BENCH lbm_paper_rank_block_1t %.1f MLUPS\n", mlups);
      std::printf("BENCH lbm_paper_rank_block_1t_roofline_ratio %.3f ratio\n", mlups / roofline);
    }
  }
  std::printf("BENCH lbm_roofline_ratio %.3f ratio\n", best_ratio_128);
  return 0;
}
