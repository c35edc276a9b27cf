#pragma once
// Inside an OpenMP parallel region: this thread's index and the number of threads, so that
// a stage can take the t-th of nt contiguous shares of its work (0 and 1 without OpenMP).
#ifdef _OPENMP
#include <omp.h>
#endif

namespace lbm {

struct TeamMember {
  int index = 0;
  int size = 1;
};

inline TeamMember team_member() {
#ifdef _OPENMP
  return {omp_get_thread_num(), omp_get_num_threads()};
#else
  return {};
#endif
}

// The threads a parallel region started here would have (1 without OpenMP).
inline int max_threads() {
#ifdef _OPENMP
  return omp_get_max_threads();
#else
  return 1;
#endif
}

}  // namespace lbm
