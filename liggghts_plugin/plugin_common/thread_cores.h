#pragma once
// How many OpenMP threads each rank's fluid and coupling stages use, against the cores the
// rank may run on. mpirun binds every rank to one core by default when it starts two or
// fewer ranks (Open MPI's "bind to core"), so `OMP_NUM_THREADS=2 mpirun -np 1 liggghts-lbm`
// runs both threads on one core: every stage split over the threads then takes longer than
// on one thread (the paper scene 3.7 against 2.6 ms per fluid step; doc/performance.md,
// "Running on several cores"). The fix says so at setup instead of leaving the user to find it.
#include <mpi.h>

#include <string>

namespace lbm_pore {

struct ThreadCores {
  int threads = 1;  // OpenMP threads of this rank (omp_get_max_threads; 1 without OpenMP)
  int cores = 1;    // CPUs in this process's affinity mask (sched_getaffinity)
};

ThreadCores thread_cores();

// Collective. The setup summary's line on the threads ("fix lbm/pore: N OpenMP threads per
// rank ...") and, when some rank has more threads than cores, the warning that names the
// rank, its cores and the mpirun options that lift the binding; `warning` empty otherwise.
struct ThreadReport {
  std::string summary;
  std::string warning;
};
ThreadReport thread_report(MPI_Comm world);

}  // namespace lbm_pore
