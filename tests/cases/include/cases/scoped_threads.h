#pragma once
// The OpenMP thread count for one scope, restored at its end, for the tests that compare a
// stage on 1 and more threads bit for bit (without OpenMP only 1 thread exists).
#ifdef _OPENMP
#include <omp.h>
#endif

namespace cases {

class ScopedThreads {
 public:
  explicit ScopedThreads(int threads) { set(threads); }
  ~ScopedThreads() { set(before_); }
  ScopedThreads(const ScopedThreads&) = delete;
  ScopedThreads& operator=(const ScopedThreads&) = delete;
  void set(int threads) {
#ifdef _OPENMP
    omp_set_num_threads(threads);
#else
    (void)threads;
#endif
  }
  // `wanted`, or 1 without OpenMP: the most threads a comparison can run on.
  static int most(int wanted) {
#ifdef _OPENMP
    return wanted;
#else
    (void)wanted;
    return 1;
#endif
  }

 private:
#ifdef _OPENMP
  int before_ = omp_get_max_threads();
#else
  int before_ = 1;
#endif
};

}  // namespace cases
