// GoogleTest main for tests that drive LAMMPS: MPI must be initialized around the tests.
#include <gtest/gtest.h>
#include <mpi.h>

// Open MPI keeps allocations from MPI_Init until exit by design; LeakSanitizer would fail every
// run of this executable on them (gtest discovery runs it at build time, without the CI's
// ASAN_OPTIONS). Only read by sanitizer builds.
extern "C" const char* __asan_default_options() { return "detect_leaks=0"; }

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  ::testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  // Only rank 0 reports; every rank runs every test (the engine calls are collective).
  if (rank != 0) {
    auto& listeners = ::testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int rc = RUN_ALL_TESTS();
  MPI_Finalize();
  return rc;
}
