#include "stream_bandwidth.h"

#include <omp.h>

#include <algorithm>
#include <chrono>
#include <vector>

#include "lbm/huge_page_allocator.h"
#include "lbm/streaming_store.h"

double measure_copy_bandwidth(int threads, CopyStores stores, std::size_t bytes_per_array) {
  const std::size_t n = bytes_per_array / sizeof(double);
  // On the pages the populations get (lbm::PopulationField), so that the yardstick has
  // the same TLB as the kernel it measures.
  std::vector<double, lbm::HugePageAllocator<double>> a(n), b(n);
  // First touch in parallel so pages sit near the threads that use them.
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n; ++i) {
    a[i] = 1.0;
    b[i] = 0.0;
  }
  double best = 0.0;
  for (int repeat = 0; repeat < 5; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    if (stores == CopyStores::kPlain) {
#pragma omp parallel for num_threads(threads) schedule(static)
      for (std::size_t i = 0; i < n; ++i) b[i] = a[i];
    } else {
      constexpr std::size_t kBlock = 1 << 16;  // values per streaming_store call
#pragma omp parallel num_threads(threads)
      {
#pragma omp for schedule(static)
        for (std::size_t i = 0; i < n; i += kBlock)
          lbm::detail::streaming_store(b.data() + i, a.data() + i, int(std::min(kBlock, n - i)));
        lbm::detail::streaming_store_fence();
      }
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, 2.0 * n * sizeof(double) / seconds);
    std::swap(a, b);
  }
  return best;
}

double measure_update_bandwidth(int threads, std::size_t bytes_per_array) {
  const std::size_t n = bytes_per_array / sizeof(double);
  std::vector<double, lbm::HugePageAllocator<double>> a(n);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n; ++i) a[i] = 1.0;
  double best = 0.0;
  for (int repeat = 0; repeat < 5; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
    // The values stay near 1 (the update's fixed point), whatever the number of repeats.
#pragma omp parallel for num_threads(threads) schedule(static)
    for (std::size_t i = 0; i < n; ++i) a[i] = 0.999 * a[i] + 0.001;
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, 2.0 * n * sizeof(double) / seconds);
  }
  // Read back one value, so that the loops cannot be dropped as dead stores.
  volatile double sink = a[n / 2];
  (void)sink;
  return best;
}

double measure_multi_array_copy_bandwidth(int threads, int arrays, std::size_t values_per_array,
                                          std::size_t burst) {
  const std::size_t n = values_per_array;
  std::vector<double, lbm::HugePageAllocator<double>> a(n * arrays), b(n * arrays);
#pragma omp parallel for num_threads(threads) schedule(static)
  for (std::size_t i = 0; i < n * arrays; ++i) {
    a[i] = 1.0;
    b[i] = 0.0;
  }
  double best = 0.0;
  for (int repeat = 0; repeat < 5; ++repeat) {
    const auto start = std::chrono::steady_clock::now();
#pragma omp parallel num_threads(threads)
    {
#pragma omp for schedule(static)
      for (std::size_t i = 0; i < n; i += burst)
        for (int k = 0; k < arrays; ++k)
          lbm::detail::streaming_store(b.data() + k * n + i, a.data() + k * n + i,
                                       int(std::min(burst, n - i)));
      lbm::detail::streaming_store_fence();
    }
    const double seconds =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    best = std::max(best, 2.0 * n * arrays * sizeof(double) / seconds);
    std::swap(a, b);
  }
  return best;
}
