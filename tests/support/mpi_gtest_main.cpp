// The GoogleTest main of every test executable that needs MPI: the fluid solver is built on a
// communicator even on one rank, and the LAMMPS engine calls are collective. Every rank runs
// every test; only rank 0 prints. Linked instead of gtest_main.
#include <gtest/gtest.h>
#include <mpi.h>

// Under AddressSanitizer: Open MPI keeps allocations from MPI_Init (partly in components it
// has unloaded by exit) that LeakSanitizer reports as leaks and turns into a failing exit
// code, which breaks GoogleTest's test discovery at build time. CI runs with
// detect_leaks=0 for the same reason; the other ASan/UBSan checks stay on.
extern "C" const char* __asan_default_options() {
  return "detect_leaks=0";
}

int main(int argc, char** argv) {
  MPI_Init(&argc, &argv);
  testing::InitGoogleTest(&argc, argv);
  int rank = 0;
  MPI_Comm_rank(MPI_COMM_WORLD, &rank);
  if (rank != 0) {
    auto& listeners = testing::UnitTest::GetInstance()->listeners();
    delete listeners.Release(listeners.default_result_printer());
  }
  const int rc = RUN_ALL_TESTS();
  MPI_Finalize();
  return rc;
}
