// GoogleTest main for the lbm_parallel suites. The test owns MPI (as LIGGGHTS would) and
// hands MPI_COMM_WORLD to lbm/; only this file and the tests themselves name it.
#include <gtest/gtest.h>

#include <cstdio>

#ifdef LBM_PORE_HAVE_MPI
#include <mpi.h>
#endif

#ifdef LBM_PORE_HAVE_MPI
namespace {
// On ranks other than 0: print failures only, tagged with the rank.
class FailurePrinter : public ::testing::EmptyTestEventListener {
 public:
  explicit FailurePrinter(int rank) : rank_(rank) {}
  void OnTestPartResult(const ::testing::TestPartResult& result) override {
    if (result.failed())
      std::printf("[rank %d] %s:%d: failure\n%s\n", rank_,
                  result.file_name() ? result.file_name() : "?", result.line_number(),
                  result.summary());
  }

 private:
  int rank_;
};
}  // namespace
#endif

int main(int argc, char** argv) {
#ifdef LBM_PORE_HAVE_MPI
  MPI_Init(&argc, &argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // Only rank 0 prints the progress; failures on any rank still print and set the status.
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
    listeners.Append(new FailurePrinter(rank));
  }
#endif
  ::testing::InitGoogleTest(&argc, argv);
  int status = RUN_ALL_TESTS();
#ifdef LBM_PORE_HAVE_MPI
  // A test failing on one rank only must fail the whole run.
  MPI_Allreduce(MPI_IN_PLACE, &status, 1, MPI_INT, MPI_MAX, MPI_COMM_WORLD);
  MPI_Finalize();
#endif
  return status;
}
