#pragma once
// Allocator of the population arrays: large arrays start on a 2 MiB boundary and ask Linux
// for transparent huge pages (madvise), which most kernels give only to memory that asks
// ("madvise" mode). The collide-stream kernel reads 19 streams and writes 19, each in a
// 4 KiB page of its own that it leaves every 512 doubles; on 2 MiB pages the 38 streams
// miss the TLB 512 times less often: 10 % faster at 128^3 (bench_lbm, doc/performance.md).
// Only where memory lives changes, never a value. Elsewhere (or when the system says no)
// it is an ordinary aligned allocation.
#include <cstddef>
#include <cstdlib>
#include <new>

#if defined(__linux__)
#include <sys/mman.h>
#endif

namespace lbm {

template <typename T>
struct HugePageAllocator {
  using value_type = T;
  static constexpr std::size_t kHugePage = std::size_t(2) << 20;
  static constexpr std::size_t kCacheLine = 64;

  HugePageAllocator() = default;
  template <typename U>
  HugePageAllocator(const HugePageAllocator<U>&) {}

  T* allocate(std::size_t count) {
    const std::size_t bytes = count * sizeof(T);
    // Below one huge page there is nothing to gain: cache-line alignment only.
    const std::size_t alignment = bytes >= kHugePage ? kHugePage : kCacheLine;
    const std::size_t rounded = (bytes + alignment - 1) / alignment * alignment;
    void* memory = std::aligned_alloc(alignment, rounded == 0 ? alignment : rounded);
    if (memory == nullptr) throw std::bad_alloc();
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    if (alignment == kHugePage) madvise(memory, rounded, MADV_HUGEPAGE);  // a hint: may say no
#endif
    return static_cast<T*>(memory);
  }
  void deallocate(T* memory, std::size_t) { std::free(memory); }
};

template <typename T, typename U>
bool operator==(const HugePageAllocator<T>&, const HugePageAllocator<U>&) { return true; }
template <typename T, typename U>
bool operator!=(const HugePageAllocator<T>&, const HugePageAllocator<U>&) { return false; }

}  // namespace lbm
