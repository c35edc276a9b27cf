#include "plugin_common/thread_cores.h"

#include <sched.h>

#include <cstdio>

#ifdef _OPENMP
#include <omp.h>
#endif

namespace lbm_pore {

ThreadCores thread_cores() {
  ThreadCores out;
#ifdef _OPENMP
  out.threads = omp_get_max_threads();
#endif
  cpu_set_t mask;
  CPU_ZERO(&mask);
  if (sched_getaffinity(0, sizeof mask, &mask) == 0) out.cores = CPU_COUNT(&mask);
  return out;
}

ThreadReport thread_report(MPI_Comm world) {
  const ThreadCores mine = thread_cores();
  int rank = 0, ranks = 1;
  MPI_Comm_rank(world, &rank);
  MPI_Comm_size(world, &ranks);
  // The rank with the fewest cores per thread: (cores - threads, rank) by MINLOC.
  struct {
    int shortfall;
    int rank;
  } local{mine.cores - mine.threads, rank}, worst{0, 0};
  MPI_Allreduce(&local, &worst, 1, MPI_2INT, MPI_MINLOC, world);
  int counts[2] = {mine.threads, mine.cores};  // that rank's threads and cores, to every rank
  MPI_Bcast(counts, 2, MPI_INT, worst.rank, world);
  ThreadReport out;
  char text[600];
  std::snprintf(text, sizeof text, "fix lbm/pore: %d OpenMP thread%s per rank, %d rank%s\n", mine.threads,
                mine.threads == 1 ? "" : "s", ranks, ranks == 1 ? "" : "s");
  out.summary = text;
  if (worst.shortfall < 0) {
    std::snprintf(text, sizeof text,
                  "fix lbm/pore: rank %d runs %d OpenMP threads on %d core%s (its CPU affinity): the "
                  "threads share the core%s and every split stage runs slower than on one thread. "
                  "mpirun binds each rank to one core by default; run with 'mpirun --bind-to none' "
                  "or '--map-by slot:PE=%d', or set OMP_NUM_THREADS=%d",
                  worst.rank, counts[0], counts[1], counts[1] == 1 ? "" : "s",
                  counts[1] == 1 ? "" : "s", counts[0], counts[1]);
    out.warning = text;
  }
  return out;
}

}  // namespace lbm_pore
