// GoogleTest main that initialises MPI when lbm/ is built with it (the solver's
// communicator may call MPI even on one rank); the host owns MPI, as in the real runs.
#include <gtest/gtest.h>
#ifdef LBM_PORE_HAVE_MPI
#include <mpi.h>
#endif

int main(int argc, char** argv) {
#ifdef LBM_PORE_HAVE_MPI
  MPI_Init(&argc, &argv);
#endif
  ::testing::InitGoogleTest(&argc, argv);
  const int result = RUN_ALL_TESTS();
#ifdef LBM_PORE_HAVE_MPI
  MPI_Finalize();
#endif
  return result;
}
